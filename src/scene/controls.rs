//! Self-documenting parameters: every public parameter of a scene is listed
//! as a [`Control`] with its key, unit, valid range and meaning. The window
//! builds its sliders from them, `--set` parses through them, and validation
//! checks them.

use super::spec::{ChoiceField, Spec, SpecKind, check_material};
pub use super::spec::{DefaultValue, ParamError, close_matches, did_you_mean, short};
use crate::physics::material::Material;

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
        /// The chosen option.
        value: &'a mut dyn ChoiceField,
        /// (key, label) of each option.
        options: Vec<(&'static str, &'static str)>,
    },
}

/// One documented parameter, declared with a builder:
///
/// ```
/// # use grainscope::scene::Control;
/// let mut velocity = 8.0;
/// let c = Control::number("velocity", "impact velocity v", &mut velocity)
///     .unit("m s^-1")
///     .shown("m/s", 1.0)
///     .range(1e-3, 1e3)
///     .log()
///     .default(8.0)
///     .doc("relative velocity at first contact");
/// assert!(c.check().is_ok());
/// ```
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
    /// Meaning and trade-offs.
    pub doc: &'static str,
    /// The value of the scene's `Default` parameters.
    pub default: Option<DefaultValue>,
    /// Changing it only restyles the output; nothing is recomputed.
    pub style_only: bool,
    /// It sets only what a figure shows (an axis range, a curve's
    /// resolution, an overlay): no scalar depends on it.
    pub figure_only: bool,
    /// It sets a numerical resolution or sample of the method (a count, a
    /// step, a tolerance, a seed), not the physics.
    pub numerical: bool,
    /// The value.
    pub kind: ControlKind<'a>,
}

impl<'a> Control<'a> {
    /// A control of `kind` with no unit, documentation or default yet.
    fn new(key: &'static str, label: &'static str, kind: ControlKind<'a>) -> Self {
        Control {
            key,
            label,
            unit: "",
            si_unit: "",
            doc: "",
            default: None,
            style_only: false,
            figure_only: false,
            numerical: false,
            kind,
        }
    }

    /// A real-valued control (SI); set its unit, range and default with the
    /// builder methods.
    pub fn number(key: &'static str, label: &'static str, value: &'a mut f64) -> Self {
        let kind =
            ControlKind::Number { value, min: f64::NEG_INFINITY, max: f64::INFINITY, log: false, display_scale: 1.0 };
        Control::new(key, label, kind)
    }

    /// A whole-number control.
    pub fn count(key: &'static str, label: &'static str, value: &'a mut usize) -> Self {
        Control::new(key, label, ControlKind::Count { value, min: 0, max: usize::MAX })
    }

    /// A switch.
    pub fn toggle(key: &'static str, label: &'static str, value: &'a mut bool) -> Self {
        Control::new(key, label, ControlKind::Toggle(value))
    }

    /// A material picker.
    pub fn material(key: &'static str, label: &'static str, value: &'a mut Material) -> Self {
        Control::new(key, label, ControlKind::Material(value))
    }

    /// A choice among fixed options (stored by key).
    pub fn choice(
        key: &'static str,
        label: &'static str,
        value: &'a mut dyn ChoiceField,
        options: Vec<(&'static str, &'static str)>,
    ) -> Self {
        Control::new(key, label, ControlKind::Choice { value, options })
    }

    /// The SI unit of the value, also shown in the window unless [`Control::shown`] says otherwise.
    pub fn unit(mut self, si_unit: &'static str) -> Self {
        self.si_unit = si_unit;
        self.unit = si_unit;
        self
    }

    /// Shows the value in `unit`, as `value × display_scale`.
    pub fn shown(mut self, unit: &'static str, scale: f64) -> Self {
        self.unit = unit;
        if let ControlKind::Number { display_scale, .. } = &mut self.kind {
            *display_scale = scale;
        }
        self
    }

    /// The valid range, SI (whole numbers for counts).
    pub fn range(mut self, lo: f64, hi: f64) -> Self {
        match &mut self.kind {
            ControlKind::Number { min, max, .. } => (*min, *max) = (lo, hi),
            ControlKind::Count { min, max, .. } => (*min, *max) = (lo as usize, hi as usize),
            _ => {}
        }
        self
    }

    /// A logarithmic slider (the parameter spans decades).
    pub fn log(mut self) -> Self {
        if let ControlKind::Number { log, .. } = &mut self.kind {
            *log = true;
        }
        self
    }

    /// The default value (that of the scene's `Default` parameters; a test checks they agree).
    pub fn default(mut self, value: impl Into<DefaultValue>) -> Self {
        self.default = Some(value.into());
        self
    }

    /// Meaning and trade-offs.
    pub fn doc(mut self, doc: &'static str) -> Self {
        self.doc = doc;
        self
    }

    /// Another label for the same quantity in this context.
    pub fn labelled(mut self, label: &'static str) -> Self {
        self.label = label;
        self
    }

    /// Marks the control as styling only.
    pub fn style_only(mut self) -> Self {
        self.style_only = true;
        self
    }

    /// Marks the control as setting only what a figure shows.
    pub fn figure_only(mut self) -> Self {
        self.figure_only = true;
        self
    }

    /// Marks the control as a numerical resolution or sample of the method
    /// (a converged answer does not depend on it).
    pub fn numerical(mut self) -> Self {
        self.numerical = true;
        self
    }

    /// The spec of the control (its value aside).
    pub fn spec(&self) -> Spec {
        let c = self;
        let kind = match &c.kind {
            ControlKind::Number { min, max, log, display_scale, .. } => {
                SpecKind::Number { min: *min, max: *max, log: *log, display_scale: *display_scale }
            }
            ControlKind::Count { min, max, .. } => SpecKind::Count { min: *min, max: *max },
            ControlKind::Toggle(_) => SpecKind::Toggle,
            ControlKind::Material(_) => SpecKind::Material,
            ControlKind::Choice { options, .. } => SpecKind::Choice { options: options.clone() },
        };
        Spec {
            key: c.key,
            label: c.label,
            unit: c.unit,
            si_unit: c.si_unit,
            doc: c.doc,
            default: c.default.clone(),
            style_only: c.style_only,
            figure_only: c.figure_only,
            numerical: c.numerical,
            kind,
        }
    }

    /// Whether the current value equals the declared default (false when none is declared).
    pub fn is_default(&self) -> bool {
        match (&self.kind, &self.default) {
            (ControlKind::Number { value, .. }, Some(DefaultValue::Number(d))) => **value == *d,
            (ControlKind::Count { value, .. }, Some(DefaultValue::Count(d))) => **value == *d,
            (ControlKind::Toggle(v), Some(DefaultValue::Toggle(d))) => **v == *d,
            (ControlKind::Material(m), Some(DefaultValue::Text(d))) => m.name == *d,
            (ControlKind::Choice { value, .. }, Some(DefaultValue::Text(d))) => value.key() == d,
            _ => false,
        }
    }

    /// The declared default as short text in display units.
    pub fn default_text(&self) -> Option<String> {
        self.spec().default_text()
    }

    /// Checks the value against the documented range.
    pub fn check(&self) -> Result<(), ParamError> {
        match &self.kind {
            ControlKind::Material(m) => check_material(self.key, m),
            _ => self.spec().check(&self.value()),
        }
    }

    /// Sets the value from text (SI units for numbers, `true`/`false`,
    /// a material name), then checks the range. On error the value is unchanged.
    pub fn set_text(&mut self, text: &str) -> Result<(), ParamError> {
        let value = self.spec().parse_checked(text)?;
        let old = self.value();
        if !self.assign(&value) {
            return Err(ParamError::Parse {
                key: self.key.into(),
                value: text.into(),
                expected: "one of the option keys (see `grainscope params`)",
            });
        }
        if let Err(e) = self.check() {
            self.assign(&old);
            return Err(e);
        }
        Ok(())
    }

    /// The current value.
    pub fn value(&self) -> DefaultValue {
        match &self.kind {
            ControlKind::Number { value, .. } => DefaultValue::Number(**value),
            ControlKind::Count { value, .. } => DefaultValue::Count(**value),
            ControlKind::Toggle(v) => DefaultValue::Toggle(**v),
            ControlKind::Material(m) => DefaultValue::Text(m.name.clone()),
            ControlKind::Choice { value, .. } => DefaultValue::Text(value.key().to_string()),
        }
    }

    /// Sets the value from `v` when it is of the control's kind (a material
    /// is looked up by name); returns whether it was taken. Unchecked: the
    /// caller validates.
    pub fn assign(&mut self, v: &DefaultValue) -> bool {
        match (&mut self.kind, v) {
            (ControlKind::Number { value, .. }, DefaultValue::Number(x)) => **value = *x,
            (ControlKind::Count { value, .. }, DefaultValue::Count(x)) => **value = *x,
            (ControlKind::Toggle(b), DefaultValue::Toggle(x)) => **b = *x,
            (ControlKind::Choice { value, .. }, DefaultValue::Text(x)) => {
                if !value.set_key(x) {
                    return false;
                }
            }
            (ControlKind::Material(m), DefaultValue::Text(x)) => match Material::named(x) {
                Some(found) => **m = found.clone(),
                None => return false,
            },
            _ => return false,
        }
        true
    }

    /// The value as short text in display units, for labels.
    pub fn display_value(&self) -> String {
        self.spec().display(&self.value())
    }

    /// One line of documentation: key, SI unit, range and meaning.
    pub fn doc_line(&self) -> String {
        self.spec().doc_line()
    }
}

/// A parameter range sampled on a grid, such as `r_min … r_max` with `n`
/// points: the one place that checks the lower end is below the upper end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogRange {
    /// Lower end.
    pub min: f64,
    /// Upper end.
    pub max: f64,
    /// Number of points (at least 2).
    pub n: usize,
}

impl LogRange {
    /// The range `min … max` of the parameters named `keys` (e.g. "r_min/r_max"),
    /// refused unless `min < max`.
    pub fn new(keys: &str, min: f64, max: f64, n: usize) -> Result<LogRange, ParamError> {
        if min < max {
            Ok(LogRange { min, max, n })
        } else {
            Err(ParamError::Inconsistent(format!("{keys}: the lower end must be below the upper end")))
        }
    }

    /// The `n` values, evenly spaced in log space.
    pub fn values(&self) -> Vec<f64> {
        super::grid::logspace(self.min, self.max, self.n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mistyped_name_is_answered_with_its_close_matches() {
        let known = ["velocity", "surface_energy", "t_vis", "radius_1", "radius_2", "yield_strength"];
        assert_eq!(close_matches("velocty", &known), vec!["velocity"]);
        assert_eq!(close_matches("energy", &known), vec!["surface_energy"]);
        assert_eq!(close_matches("radius", &known), vec!["radius_1", "radius_2"]);
        assert!(close_matches("zz", &known).is_empty());
        assert_eq!(did_you_mean("tvis", &known), ", did you mean 't_vis'?");
        assert_eq!(did_you_mean("zz", &known), "");
        let e = ParamError::unknown("velocty", &known);
        assert!(e.to_string().starts_with("unknown parameter 'velocty', did you mean 'velocity'? (known: velocity, "));
    }
}
