//! The parameter schema: every parameter struct of a scene derives
//! [`ParamSet`] (`#[derive(ParamSet)]` of the `grainscope-derive` crate) from its
//! fields' doc comments and `#[param(...)]` attributes, so that a parameter
//! is one field with its attributes. From that one declaration come the
//! struct's `Default`, the controls the window and `--set` edit, a typed
//! [`ParamSet::get`] that reads one field without copying the rest, and the
//! static list of [`Spec`]s that the command line's `params`, the parameter
//! reference, links, sweeps and Python read.

pub use super::controls::{Control, ControlKind};
pub use super::spec::{Choice, ChoiceField, ParamError, Spec, SpecKind, Value, check_material, short, unknown_option};
pub use grainscope_derive::{Choice, ParamSet};

use crate::physics::material::Material;

/// A parameter struct: its parameters, documented, with typed access.
/// Derived (`#[derive(ParamSet)]`); see the `grainscope-derive` crate for the
/// attributes.
pub trait ParamSet: Default + Sized {
    /// The controls bound to the fields, in declaration order, with the
    /// defaults of `d` (the enclosing struct's default, so that a scene can
    /// give a shared struct its own defaults).
    fn controls_with<'a>(&'a mut self, d: &Self) -> Vec<Control<'a>>;

    /// The value of parameter `key`, read from its field; None if the struct
    /// has no such parameter.
    fn get(&self, key: &str) -> Option<Value>;

    /// Every parameter's spec, in the order of the controls.
    fn specs() -> &'static [Spec];

    /// The controls bound to the fields, with the struct's own defaults.
    fn controls(&mut self) -> Vec<Control<'_>> {
        self.controls_with(&Self::default())
    }

    /// The spec of parameter `key`.
    fn spec(key: &str) -> Option<&'static Spec> {
        Self::specs().iter().find(|s| s.key == key)
    }

    /// Sets parameter `key` to `value` (of the parameter's kind; a material
    /// by name) and checks its range; on error nothing changes.
    fn set(&mut self, key: &str, value: &Value) -> Result<(), ParamError> {
        let mut controls = self.controls();
        let known: Vec<&'static str> = controls.iter().map(|c| c.key).collect();
        let c = controls.iter_mut().find(|c| c.key == key).ok_or_else(|| ParamError::unknown(key, &known))?;
        let old = c.value();
        if !c.assign(value) {
            return Err(ParamError::Parse {
                key: key.into(),
                value: format!("{value:?}"),
                expected: "a value of the parameter's kind",
            });
        }
        if let Err(e) = c.check() {
            c.assign(&old);
            return Err(e);
        }
        Ok(())
    }

    /// Checks every parameter against its spec, reading each field in place.
    fn check_all(&self) -> Result<(), ParamError>;
}

/// The specs of `P`'s parameters, from its controls at the default.
pub fn specs_of<P: ParamSet>() -> Vec<Spec> {
    let d = P::default();
    let mut p = P::default();
    p.controls_with(&d).iter().map(Control::spec).collect()
}

/// A field type that a parameter can hold: its value as a [`Value`].
pub trait FieldValue {
    /// The value.
    fn value(&self) -> Value;

    /// Checks the value against its parameter's spec.
    fn check(&self, spec: &Spec) -> Result<(), ParamError> {
        spec.check(&self.value())
    }
}

/// A field type with a control of its own kind (a `String` is a choice and
/// names its options).
pub trait FieldControl: FieldValue {
    /// The control of a field of this type.
    fn control<'a>(key: &'static str, label: &'static str, value: &'a mut Self) -> Control<'a>;
}

impl FieldValue for f64 {
    fn value(&self) -> Value {
        Value::Number(*self)
    }
}

impl FieldControl for f64 {
    fn control<'a>(key: &'static str, label: &'static str, value: &'a mut Self) -> Control<'a> {
        Control::number(key, label, value)
    }
}

impl FieldValue for usize {
    fn value(&self) -> Value {
        Value::Count(*self)
    }
}

impl FieldControl for usize {
    fn control<'a>(key: &'static str, label: &'static str, value: &'a mut Self) -> Control<'a> {
        Control::count(key, label, value)
    }
}

impl FieldValue for bool {
    fn value(&self) -> Value {
        Value::Toggle(*self)
    }
}

impl FieldControl for bool {
    fn control<'a>(key: &'static str, label: &'static str, value: &'a mut Self) -> Control<'a> {
        Control::toggle(key, label, value)
    }
}

impl FieldValue for Material {
    fn value(&self) -> Value {
        Value::Text(self.name.clone())
    }

    fn check(&self, spec: &Spec) -> Result<(), ParamError> {
        check_material(spec.key, self)
    }
}

impl FieldControl for Material {
    fn control<'a>(key: &'static str, label: &'static str, value: &'a mut Self) -> Control<'a> {
        Control::material(key, label, value)
    }
}

impl FieldValue for String {
    fn value(&self) -> Value {
        Value::Text(self.clone())
    }
}
