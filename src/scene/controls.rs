//! Self-documenting parameters: every public parameter of a scene is listed
//! as a [`Control`] with its key, unit, valid range and meaning. The window
//! builds its sliders from them, `--set` parses through them, and validation
//! checks them.

use crate::physics::material::Material;

/// Why a parameter value was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParamError {
    /// The key is not a parameter of the scene.
    #[error("unknown parameter '{key}' (known: {known})")]
    UnknownKey {
        /// The offending key.
        key: String,
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

/// The kind of value a control edits.
#[derive(Debug)]
pub enum ControlKind<'a> {
    /// A real number in SI units, shown as `value × display_scale` in `unit`.
    Number {
        /// The value, SI.
        value: &'a mut f64,
        /// Smallest valid value, SI.
        min: f64,
        /// Largest valid value, SI.
        max: f64,
        /// Use a logarithmic slider (the parameter spans decades).
        log: bool,
        /// Factor from SI to the displayed unit (e.g. 1e6 for µm).
        display_scale: f64,
    },
    /// A whole number.
    Count {
        /// The value.
        value: &'a mut usize,
        /// Smallest valid value.
        min: usize,
        /// Largest valid value.
        max: usize,
    },
    /// A switch.
    Toggle(&'a mut bool),
    /// A material from Table 2.2 (or a custom one).
    Material(&'a mut Material),
    /// One of a fixed list of options, stored by key.
    Choice {
        /// The chosen key.
        value: &'a mut String,
        /// (key, label) of each option.
        options: Vec<(&'static str, &'static str)>,
    },
}

/// One documented parameter.
#[derive(Debug)]
pub struct Control<'a> {
    /// Key in presets and on the command line.
    pub key: &'static str,
    /// Label in the window.
    pub label: &'static str,
    /// Unit shown in the window (after `display_scale`).
    pub unit: &'static str,
    /// SI unit of the stored value (empty if dimensionless).
    pub si_unit: &'static str,
    /// Meaning, default and trade-offs.
    pub doc: &'static str,
    /// Changing it only restyles the output; nothing is recomputed.
    pub style_only: bool,
    /// The value.
    pub kind: ControlKind<'a>,
}

impl<'a> Control<'a> {
    /// A real-valued control.
    #[allow(clippy::too_many_arguments)]
    pub fn number(
        key: &'static str,
        label: &'static str,
        value: &'a mut f64,
        si_unit: &'static str,
        (min, max): (f64, f64),
        log: bool,
        (unit, display_scale): (&'static str, f64),
        doc: &'static str,
    ) -> Self {
        Control {
            key,
            label,
            unit,
            si_unit,
            doc,
            style_only: false,
            kind: ControlKind::Number { value, min, max, log, display_scale },
        }
    }

    /// A whole-number control.
    pub fn count(
        key: &'static str,
        label: &'static str,
        value: &'a mut usize,
        (min, max): (usize, usize),
        doc: &'static str,
    ) -> Self {
        Control::unitless(key, label, doc, ControlKind::Count { value, min, max })
    }

    /// A control without a unit.
    fn unitless(key: &'static str, label: &'static str, doc: &'static str, kind: ControlKind<'a>) -> Self {
        Control { key, label, unit: "", si_unit: "", doc, style_only: false, kind }
    }

    /// A switch.
    pub fn toggle(key: &'static str, label: &'static str, value: &'a mut bool, doc: &'static str) -> Self {
        Control::unitless(key, label, doc, ControlKind::Toggle(value))
    }

    /// A material picker.
    pub fn material(key: &'static str, label: &'static str, value: &'a mut Material, doc: &'static str) -> Self {
        Control::unitless(key, label, doc, ControlKind::Material(value))
    }

    /// A choice among fixed options (stored by key).
    pub fn choice(
        key: &'static str,
        label: &'static str,
        value: &'a mut String,
        options: Vec<(&'static str, &'static str)>,
        doc: &'static str,
    ) -> Self {
        Control::unitless(key, label, doc, ControlKind::Choice { value, options })
    }

    /// Marks the control as styling only.
    pub fn style_only(mut self) -> Self {
        self.style_only = true;
        self
    }

    /// Checks the value against the documented range.
    pub fn check(&self) -> Result<(), ParamError> {
        let out = |value: String, min: String, max: String| ParamError::OutOfRange {
            key: self.key.into(),
            value,
            min,
            max,
            unit: self.si_unit,
        };
        match &self.kind {
            ControlKind::Number { value, min, max, .. } => {
                if !(value.is_finite() && **value >= *min && **value <= *max) {
                    return Err(out(format!("{value:e}"), format!("{min:e}"), format!("{max:e}")));
                }
            }
            ControlKind::Count { value, min, max } => {
                if !(**value >= *min && **value <= *max) {
                    return Err(out(value.to_string(), min.to_string(), max.to_string()));
                }
            }
            ControlKind::Toggle(_) => {}
            ControlKind::Choice { value, options } => {
                if !options.iter().any(|(k, _)| k == value) {
                    let keys: Vec<&str> = options.iter().map(|(k, _)| *k).collect();
                    return Err(ParamError::Parse {
                        key: self.key.into(),
                        value: value.to_string(),
                        expected: if keys.is_empty() { "a known option" } else { "one of the listed options" },
                    });
                }
            }
            ControlKind::Material(m) => {
                let bad = |what: &str, v: f64| {
                    ParamError::Inconsistent(format!("{}: material '{}' has invalid {what} {v:e}", self.key, m.name))
                };
                for (what, v) in [
                    ("Young's modulus", m.youngs_modulus),
                    ("density", m.density),
                    ("surface energy", m.surface_energy),
                ] {
                    if !(v.is_finite() && v > 0.0) {
                        return Err(bad(what, v));
                    }
                }
                if !(m.poisson_ratio > 0.0 && m.poisson_ratio < 0.5) {
                    return Err(bad("Poisson ratio", m.poisson_ratio));
                }
            }
        }
        Ok(())
    }

    /// Sets the value from text (SI units for numbers, `true`/`false`,
    /// a material name), then checks the range. On error the value is unchanged.
    pub fn set_text(&mut self, text: &str) -> Result<(), ParamError> {
        let parse_err = |expected| ParamError::Parse { key: self.key.into(), value: text.into(), expected };
        match &mut self.kind {
            ControlKind::Number { value, .. } => {
                let v: f64 = text.trim().parse().map_err(|_| parse_err("a number in SI units"))?;
                let old = **value;
                **value = v;
                if let Err(e) = self.check() {
                    if let ControlKind::Number { value, .. } = &mut self.kind {
                        **value = old;
                    }
                    return Err(e);
                }
            }
            ControlKind::Count { value, .. } => {
                let v: usize = text.trim().parse().map_err(|_| parse_err("a whole number"))?;
                let old = **value;
                **value = v;
                if let Err(e) = self.check() {
                    if let ControlKind::Count { value, .. } = &mut self.kind {
                        **value = old;
                    }
                    return Err(e);
                }
            }
            ControlKind::Toggle(value) => {
                **value = match text.trim() {
                    "true" | "on" | "yes" | "1" => true,
                    "false" | "off" | "no" | "0" => false,
                    _ => return Err(parse_err("true or false")),
                };
            }
            ControlKind::Material(value) => {
                let m = Material::named(text.trim()).ok_or_else(|| parse_err("a material name of Table 2.2"))?;
                **value = m.clone();
            }
            ControlKind::Choice { value, options } => {
                let key = options
                    .iter()
                    .find(|(k, _)| *k == text.trim())
                    .map(|(k, _)| *k)
                    .ok_or_else(|| parse_err("one of the option keys (see `grainscope params`)"))?;
                **value = key.to_string();
            }
        }
        Ok(())
    }

    /// The value as short text in display units, for labels.
    pub fn display_value(&self) -> String {
        match &self.kind {
            ControlKind::Number { value, display_scale, .. } => {
                let v = **value * display_scale;
                let s = crate::figure::tick_label(v);
                if self.unit.is_empty() { s } else { format!("{s} {}", self.unit) }
            }
            ControlKind::Count { value, .. } => value.to_string(),
            ControlKind::Toggle(v) => if **v { "on" } else { "off" }.to_string(),
            ControlKind::Material(m) => m.name.clone(),
            ControlKind::Choice { value, options } => {
                options.iter().find(|(k, _)| k == value).map_or_else(|| value.to_string(), |(_, l)| l.to_string())
            }
        }
    }

    /// One line of documentation: key, SI unit, range and meaning.
    pub fn doc_line(&self) -> String {
        let range = match &self.kind {
            ControlKind::Number { min, max, .. } => format!("{min:e} … {max:e} {}", self.si_unit),
            ControlKind::Count { min, max, .. } => format!("{min} … {max}"),
            ControlKind::Toggle(_) => "true | false".into(),
            ControlKind::Material(_) => "material of Table 2.2".into(),
            ControlKind::Choice { options, .. } => options.iter().map(|(k, _)| *k).collect::<Vec<_>>().join(" | "),
        };
        format!("{}: {} [{}] — {}", self.key, self.label, range.trim(), self.doc)
    }
}
