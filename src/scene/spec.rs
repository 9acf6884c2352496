//! What a parameter is, apart from the field that holds it: its [`Spec`]
//! (key, label, units, valid values, default, meaning), its value as a
//! [`DefaultValue`], the options of a [`Choice`], and why a value is refused
//! ([`ParamError`]). The controls ([`super::controls`]) bind a spec to a
//! field; the schema ([`super::schema`]) derives both from a struct.

use crate::physics::material::Material;

/// A parameter's value (a number, count, switch, or a material's or option's key).
pub type Value = DefaultValue;

/// Why a parameter value was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParamError {
    /// The key is not a parameter of the scene.
    #[error("unknown parameter '{key}'{suggestion} (known: {known})")]
    UnknownKey {
        /// The offending key.
        key: String,
        /// The close matches, as ", did you mean 'a' or 'b'?" (empty if none).
        suggestion: String,
        /// The scene's keys.
        known: String,
    },
    /// The value is non-finite or outside the documented range.
    #[error("{key} = {value} is outside its valid range {min} … {max} {unit}")]
    OutOfRange {
        /// Parameter key.
        key: String,
        /// Offending value as text.
        value: String,
        /// Lower bound.
        min: String,
        /// Upper bound.
        max: String,
        /// SI unit.
        unit: &'static str,
    },
    /// The text could not be parsed for this parameter.
    #[error("{key}: cannot read '{value}' as {expected}")]
    Parse {
        /// Parameter key.
        key: String,
        /// The text given.
        value: String,
        /// What was expected.
        expected: &'static str,
    },
    /// Two parameters contradict each other.
    #[error("{0}")]
    Inconsistent(String),
}

impl ParamError {
    /// The error for `key`, which is none of `known`: it names the close
    /// matches, if any.
    pub fn unknown(key: &str, known: &[&str]) -> ParamError {
        ParamError::UnknownKey { key: key.into(), suggestion: did_you_mean(key, known), known: known.join(", ") }
    }
}

/// The names of `known` close to `word`, best first (at most three): names
/// at most a third of their letters away (Damerau–Levenshtein), and names
/// that contain it.
pub fn close_matches<'a>(word: &str, known: &[&'a str]) -> Vec<&'a str> {
    let mut scored: Vec<(f64, &'a str)> = known
        .iter()
        .map(|k| (strsim::normalized_damerau_levenshtein(word, k), *k))
        .filter(|(score, k)| *score >= 0.66 || (word.len() >= 3 && k.contains(word)))
        .collect();
    crate::sorting::sort_by_key(&mut scored, |a| -a.0);
    scored.into_iter().take(3).map(|(_, k)| k).collect()
}

/// ", did you mean 'a' or 'b'?" for the close matches of `word` (empty if none).
pub fn did_you_mean(word: &str, known: &[&str]) -> String {
    let close: Vec<String> = close_matches(word, known).iter().map(|k| format!("'{k}'")).collect();
    match close.len() {
        0 => String::new(),
        _ => format!(", did you mean {}?", close.join(" or ")),
    }
}

/// The default value of a control, as written once in its declaration.
#[derive(Debug, Clone, PartialEq)]
pub enum DefaultValue {
    /// A real number, SI.
    Number(f64),
    /// A whole number.
    Count(usize),
    /// A switch.
    Toggle(bool),
    /// A material name or an option key.
    Text(String),
}

impl From<f64> for DefaultValue {
    fn from(v: f64) -> Self {
        DefaultValue::Number(v)
    }
}

impl From<usize> for DefaultValue {
    fn from(v: usize) -> Self {
        DefaultValue::Count(v)
    }
}

impl From<bool> for DefaultValue {
    fn from(v: bool) -> Self {
        DefaultValue::Toggle(v)
    }
}

impl From<&str> for DefaultValue {
    fn from(v: &str) -> Self {
        DefaultValue::Text(v.to_string())
    }
}

impl From<String> for DefaultValue {
    fn from(v: String) -> Self {
        DefaultValue::Text(v)
    }
}

/// A value as short, parseable text for messages: six significant digits
/// ("0.0001", "1.5e-7", "-1", "inf"), not the float's every digit.
pub fn short(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return format!("{v}");
    }
    let rounded: f64 = format!("{v:.5e}").parse().unwrap_or(v);
    if (1e-3..1e5).contains(&rounded.abs()) { format!("{rounded}") } else { format!("{rounded:e}") }
}

/// What kind of value a parameter holds, and its valid values.
#[derive(Debug, Clone, PartialEq)]
pub enum SpecKind {
    /// A real number, SI.
    Number {
        /// Smallest valid value, SI.
        min: f64,
        /// Largest valid value, SI.
        max: f64,
        /// A logarithmic slider.
        log: bool,
        /// Factor from SI to the displayed unit.
        display_scale: f64,
    },
    /// A whole number.
    Count {
        /// Smallest valid value.
        min: usize,
        /// Largest valid value.
        max: usize,
    },
    /// A switch.
    Toggle,
    /// A material of Table 2.2.
    Material,
    /// One of fixed options, stored by key.
    Choice {
        /// (key, label) of each option.
        options: Vec<(&'static str, &'static str)>,
    },
}

/// One parameter as declared: key, label, units, range, default and meaning.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// Key in presets, links and on the command line.
    pub key: &'static str,
    /// Label in the window.
    pub label: &'static str,
    /// Unit shown in the window.
    pub unit: &'static str,
    /// SI unit of the stored value (empty if dimensionless).
    pub si_unit: &'static str,
    /// Meaning and trade-offs.
    pub doc: &'static str,
    /// The default.
    pub default: Option<Value>,
    /// Changing it only restyles the output.
    pub style_only: bool,
    /// It sets only what a figure shows (an axis range, a curve's
    /// resolution, an overlay): no scalar depends on it.
    pub figure_only: bool,
    /// It sets a numerical resolution or sample of the method (a count, a
    /// step, a tolerance, a seed), not the physics: a converged answer does
    /// not depend on it, and the sensitivity tools report it apart.
    pub numerical: bool,
    /// Kind and valid values.
    pub kind: SpecKind,
}

impl Spec {
    /// Whether the parameter is a number (real or whole) that a sweep can vary.
    pub fn is_numeric(&self) -> bool {
        matches!(self.kind, SpecKind::Number { .. } | SpecKind::Count { .. })
    }

    /// `value` as short text in display units, for labels ("2 µm", "on",
    /// an option's label).
    pub fn display(&self, value: &Value) -> String {
        match (&self.kind, value) {
            (SpecKind::Number { display_scale, .. }, Value::Number(v)) => {
                let s = crate::figure::tick_label(v * display_scale);
                if self.unit.is_empty() { s } else { format!("{s} {}", self.unit) }
            }
            (_, Value::Number(v)) => v.to_string(),
            (_, Value::Count(v)) => v.to_string(),
            (_, Value::Toggle(v)) => if *v { "on" } else { "off" }.to_string(),
            (SpecKind::Choice { options }, Value::Text(v)) => {
                options.iter().find(|(k, _)| k == v).map_or_else(|| v.to_string(), |(_, l)| l.to_string())
            }
            (_, Value::Text(v)) => v.to_string(),
        }
    }

    /// The default as short text in display units.
    pub fn default_text(&self) -> Option<String> {
        Some(match (self.default.as_ref()?, &self.kind) {
            (Value::Toggle(v), _) => v.to_string(),
            (Value::Text(v), _) => v.to_string(),
            (d, _) => self.display(d),
        })
    }

    /// One line of documentation: key, SI unit, range, default and meaning.
    pub fn doc_line(&self) -> String {
        let range = match &self.kind {
            SpecKind::Number { min, max, .. } => format!("{min:e} … {max:e} {}", self.si_unit),
            SpecKind::Count { min, max } => format!("{min} … {max}"),
            SpecKind::Toggle => "true | false".into(),
            SpecKind::Material => "material of Table 2.2".into(),
            SpecKind::Choice { options } => options.iter().map(|(k, _)| *k).collect::<Vec<_>>().join(" | "),
        };
        let default = self.default_text().map(|d| format!("; default {d}")).unwrap_or_default();
        format!("{}: {} [{}{default}] — {}", self.key, self.label, range.trim(), self.doc)
    }

    /// The value written as `text` (SI units for numbers, `true`/`false`,
    /// `on`/`off`, `yes`/`no` or `1`/`0` for a switch, a material name of
    /// Table 2.2, an option key), unchecked against the range.
    pub fn parse(&self, text: &str) -> Result<Value, ParamError> {
        let t = text.trim();
        let parse_err = |expected| ParamError::Parse { key: self.key.into(), value: text.into(), expected };
        match &self.kind {
            SpecKind::Number { .. } => t.parse().map(Value::Number).map_err(|_| parse_err("a number in SI units")),
            SpecKind::Count { .. } => t.parse().map(Value::Count).map_err(|_| parse_err("a whole number")),
            SpecKind::Toggle => match t {
                "true" | "on" | "yes" | "1" => Ok(Value::Toggle(true)),
                "false" | "off" | "no" | "0" => Ok(Value::Toggle(false)),
                _ => Err(parse_err("true or false")),
            },
            SpecKind::Material => match Material::named(t) {
                Some(m) => Ok(Value::Text(m.name.clone())),
                None => Err(parse_err("a material name of Table 2.2")),
            },
            SpecKind::Choice { options } => match options.iter().find(|(k, _)| *k == t) {
                Some((k, _)) => Ok(Value::Text(k.to_string())),
                None => Err(parse_err("one of the option keys (see `grainscope params`)")),
            },
        }
    }

    /// [`Spec::parse`] and [`Spec::check`]: an out-of-range value is named
    /// as the user wrote it, not as it reads back.
    pub fn parse_checked(&self, text: &str) -> Result<Value, ParamError> {
        let value = self.parse(text)?;
        self.check(&value).map_err(|e| match e {
            ParamError::OutOfRange { key, min, max, unit, .. } => {
                ParamError::OutOfRange { key, value: text.trim().to_string(), min, max, unit }
            }
            other => other,
        })?;
        Ok(value)
    }

    /// Checks `value` against the spec.
    pub fn check(&self, value: &Value) -> Result<(), ParamError> {
        let out = |value: String, min: String, max: String| ParamError::OutOfRange {
            key: self.key.into(),
            value,
            min,
            max,
            unit: self.si_unit,
        };
        match (&self.kind, value) {
            (SpecKind::Number { min, max, .. }, Value::Number(v)) if !(v.is_finite() && v >= min && v <= max) => {
                Err(out(short(*v), format!("{min:e}"), format!("{max:e}")))
            }
            (SpecKind::Count { min, max }, Value::Count(v)) if !(v >= min && v <= max) => {
                Err(out(v.to_string(), min.to_string(), max.to_string()))
            }
            (SpecKind::Choice { options }, Value::Text(v)) if !options.iter().any(|(k, _)| k == v) => {
                Err(ParamError::Parse {
                    key: self.key.into(),
                    value: v.clone(),
                    expected: if options.is_empty() { "a known option" } else { "one of the listed options" },
                })
            }
            _ => Ok(()),
        }
    }
}

/// Checks that material parameter `key` holds a physical material.
pub fn check_material(key: &str, m: &Material) -> Result<(), ParamError> {
    let bad =
        |what: &str, v: f64| ParamError::Inconsistent(format!("{key}: material '{}' has invalid {what} {v:e}", m.name));
    for (what, v) in
        [("Young's modulus", m.youngs_modulus), ("density", m.density), ("surface energy", m.surface_energy)]
    {
        if !(v.is_finite() && v > 0.0) {
            return Err(bad(what, v));
        }
    }
    if !(m.poisson_ratio > 0.0 && m.poisson_ratio < 0.5) {
        return Err(bad("Poisson ratio", m.poisson_ratio));
    }
    Ok(())
}

/// A parameter that is one of fixed options: an enum deriving `Choice`,
/// stored in files by its key.
pub trait Choice: Sized + 'static {
    /// (key, label) of each option, in order.
    const OPTIONS: &'static [(&'static str, &'static str)];

    /// The option's key, as files and the command line write it.
    fn key(&self) -> &'static str;

    /// The option of `key`, if any.
    fn from_key(key: &str) -> Option<Self>;

    /// The option's label, as the window shows it.
    fn label(&self) -> &'static str {
        Self::OPTIONS.iter().find(|(k, _)| *k == self.key()).map_or("", |(_, l)| l)
    }
}

/// The message for `text`, which is none of `options`' keys.
pub fn unknown_option(text: &str, options: &[(&str, &str)]) -> String {
    let keys: Vec<&str> = options.iter().map(|(k, _)| *k).collect();
    format!("unknown option '{text}'{} (options: {})", did_you_mean(text, &keys), keys.join(", "))
}

/// What a choice control edits: an enum of options, or the key of an option
/// held as text (for options known only at run time, such as the
/// experiments of a table).
pub trait ChoiceField: std::fmt::Debug {
    /// The chosen option's key.
    fn key(&self) -> &str;

    /// Chooses the option `key`; false (and nothing changes) if there is none.
    fn set_key(&mut self, key: &str) -> bool;
}

impl<T: Choice + std::fmt::Debug> ChoiceField for T {
    fn key(&self) -> &str {
        Choice::key(self)
    }

    fn set_key(&mut self, key: &str) -> bool {
        match T::from_key(key) {
            Some(v) => {
                *self = v;
                true
            }
            None => false,
        }
    }
}

impl ChoiceField for String {
    fn key(&self) -> &str {
        self
    }

    fn set_key(&mut self, key: &str) -> bool {
        key.clone_into(self);
        true
    }
}
