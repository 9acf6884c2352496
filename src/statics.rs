//! Texts that live as long as the program. Scalars name their key, label
//! and unit with `&'static str`; read back from bytes (a browser's Web
//! Worker sends results to its page) each distinct text is kept once, so
//! that the memory kept is bounded by the texts the program itself has.

use std::collections::HashSet;
use std::sync::{Mutex, OnceLock};

/// A text that lives as long as the program. A field of this type, with
/// `#[serde(deserialize_with = "crate::statics::deserialize")]`, reads back
/// from bytes of any lifetime (serde would otherwise borrow a `&str` field
/// from the bytes).
pub type Text = &'static str;

/// The one `'static` copy of `text`.
pub fn intern(text: &str) -> &'static str {
    static KEPT: OnceLock<Mutex<HashSet<&'static str>>> = OnceLock::new();
    let mut kept = KEPT.get_or_init(Mutex::default).lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    match kept.get(text) {
        Some(&s) => s,
        None => {
            let s: &'static str = Box::leak(text.to_owned().into_boxed_str());
            kept.insert(s);
            s
        }
    }
}

/// Reads a `&'static str` field through [`intern`] (for
/// `#[serde(deserialize_with = "crate::statics::deserialize")]`).
pub fn deserialize<'de, D: serde::Deserializer<'de>>(d: D) -> Result<&'static str, D::Error> {
    let text = <std::borrow::Cow<'de, str> as serde::Deserialize>::deserialize(d)?;
    Ok(intern(&text))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_texts_share_one_copy() {
        let a = intern(&String::from("restitution e"));
        let b = intern(&String::from("restitution e"));
        assert_eq!(a, "restitution e");
        assert!(std::ptr::eq(a, b));
        assert!(!std::ptr::eq(a, intern("restitution")));
    }
}
