//! Decks: a lecture as a file. A deck is an ordered list of slides, each a
//! scene in a given state (a preset, named or inline, with optional
//! overrides) with a title, speaker notes, the figure to enlarge and the
//! controls to keep at hand. The window presents a deck; `grainscope deck`
//! writes its handout (every slide's figures and an index with the notes).
//!
//! ```ron
//! (
//!     title: "Why grains stick",
//!     slides: [
//!         (
//!             title: "Two ice spheres bounce at 8 m/s",
//!             notes: "Thesis Sect. 2.3, Fig. 2.2: ...",
//!             preset: Some("ice-bounce-8ms"),
//!             set: ["velocity=4"],
//!             enlarge: Some("energy-budget"),
//!             highlight: ["velocity"],
//!         ),
//!     ],
//! )
//! ```
//!
//! A slide names a shipped preset or a preset file (relative to the deck's
//! folder) in `preset`, or holds its parameters inline in `scene` (the
//! `scene` of a preset file); `set` applies `KEY=VALUE` overrides as
//! `grainscope run --set` does.

use crate::files::{WriteError, write_atomically};
use crate::preset::Preset;
use crate::scene::{ParamError, SceneParams};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// A lecture: slides in order.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Deck {
    /// Title of the lecture.
    #[serde(default)]
    pub title: String,
    /// What the lecture covers.
    #[serde(default)]
    pub description: String,
    /// The slides, in order.
    pub slides: Vec<Slide>,
}

/// One slide: a scene in a given state, with its title and notes.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Slide {
    /// Title shown above the plots.
    pub title: String,
    /// Speaker notes, plain text.
    #[serde(default)]
    pub notes: String,
    /// A shipped preset's name, or a preset file relative to the deck.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preset: Option<String>,
    /// The parameters inline (instead of `preset`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scene: Option<SceneParams>,
    /// `KEY=VALUE` overrides applied to the preset (SI units).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub set: Vec<String>,
    /// The figure (by id) drawn large, the others smaller below it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub enlarge: Option<String>,
    /// Parameters (by key) kept at hand beside the plots while presenting.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub highlight: Vec<String>,
}

/// Why a deck could not be read, resolved or written.
#[derive(Debug, thiserror::Error)]
pub enum DeckError {
    /// The file could not be read.
    #[error("cannot read {}: {cause}", path.display())]
    Read {
        /// File.
        path: PathBuf,
        /// What the operating system said.
        cause: std::io::Error,
    },
    /// The RON text is malformed.
    #[error("{origin}:{line}:{column}: {message}")]
    Syntax {
        /// File name.
        origin: String,
        /// Line (1-based).
        line: usize,
        /// Column (1-based).
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// A slide does not resolve to valid parameters.
    #[error("{origin}, slide {number} ('{title}'): {message}")]
    Slide {
        /// File name.
        origin: String,
        /// Slide number, 1-based.
        number: usize,
        /// Slide title.
        title: String,
        /// What is wrong.
        message: String,
    },
    /// The deck has no slides.
    #[error("{0}: a deck needs at least one slide")]
    Empty(String),
    /// The file could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
    /// Serialisation failed.
    #[error("cannot serialise deck: {0}")]
    Serialise(String),
}

/// A deck with every slide resolved to its parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadedDeck {
    /// The deck as written.
    pub deck: Deck,
    /// Each slide's parameters, as the deck defines them.
    pub params: Vec<SceneParams>,
    /// Where it came from (file or shipped name).
    pub origin: String,
}

impl Slide {
    /// The slide's parameters: its preset (shipped name, or a file relative
    /// to `base`) or inline scene, with the overrides applied and checked.
    pub fn resolve(&self, base: Option<&Path>) -> Result<SceneParams, String> {
        let mut params = match (&self.preset, &self.scene) {
            (Some(_), Some(_)) => return Err("give either 'preset' or 'scene', not both".into()),
            (None, None) => return Err("give a 'preset' (shipped name or file) or an inline 'scene'".into()),
            (None, Some(scene)) => scene.clone(),
            (Some(name), None) => {
                let relative = base.map(|b| b.join(name)).filter(|p| p.exists());
                let found = match relative {
                    Some(path) => Preset::load(&path),
                    None => crate::preset::resolve(name),
                };
                found.map_err(|e| format!("preset '{name}': {e}"))?.scene
            }
        };
        for s in &self.set {
            let (k, v) = s.split_once('=').ok_or_else(|| format!("set expects KEY=VALUE, got '{s}'"))?;
            params.set(k.trim(), v.trim()).map_err(|e: ParamError| format!("set {s}: {e}"))?;
        }
        params.validate().map_err(|e| e.to_string())?;
        let keys = params.keys();
        if let Some(k) = self.highlight.iter().find(|k| !keys.contains(&k.as_str())) {
            return Err(format!("highlight: '{k}' is not a parameter of scene '{}'", params.info().id));
        }
        Ok(params)
    }
}

impl Deck {
    /// Parses a deck and resolves every slide; `base` is the folder preset
    /// files are looked up in first.
    pub fn from_ron(text: &str, origin: &str, base: Option<&Path>) -> Result<LoadedDeck, DeckError> {
        let deck: Deck = ron::from_str(text).map_err(|e| DeckError::Syntax {
            origin: origin.into(),
            line: e.span.start.line,
            column: e.span.start.col,
            message: e.code.to_string(),
        })?;
        if deck.slides.is_empty() {
            return Err(DeckError::Empty(origin.into()));
        }
        let params = deck
            .slides
            .iter()
            .enumerate()
            .map(|(i, s)| {
                s.resolve(base).map_err(|message| DeckError::Slide {
                    origin: origin.into(),
                    number: i + 1,
                    title: s.title.clone(),
                    message,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(LoadedDeck { deck, params, origin: origin.into() })
    }

    /// Reads a deck file.
    pub fn load(path: &Path) -> Result<LoadedDeck, DeckError> {
        let text = std::fs::read_to_string(path).map_err(|cause| DeckError::Read { path: path.into(), cause })?;
        Deck::from_ron(&text, &path.display().to_string(), path.parent())
    }

    /// The deck as RON text.
    pub fn to_ron(&self) -> Result<String, DeckError> {
        let body = ron::ser::to_string_pretty(self, ron::ser::PrettyConfig::default().struct_names(false))
            .map_err(|e| DeckError::Serialise(e.to_string()))?;
        Ok(format!("// grainscope deck: slides in order, each a scene with title and speaker notes.\n{body}\n"))
    }

    /// Writes the deck atomically (an existing file stays intact on error).
    pub fn save(&self, path: &Path) -> Result<(), DeckError> {
        write_atomically(path, self.to_ron()?.as_bytes())?;
        Ok(())
    }
}

/// The decks shipped in `presets/decks/`, compiled into the binary: (file name, text).
pub const SHIPPED: [(&str, &str); 3] = [
    ("grains-to-planetesimals.ron", include_str!("../presets/decks/grains-to-planetesimals.ron")),
    ("sticking-and-rolling.ron", include_str!("../presets/decks/sticking-and-rolling.ron")),
    ("porous-growth.ron", include_str!("../presets/decks/porous-growth.ron")),
];

/// Finds a deck by path, or by the name of a shipped deck (with or without `.ron`).
pub fn resolve(name: &str) -> Result<LoadedDeck, DeckError> {
    let path = Path::new(name);
    if path.exists() {
        return Deck::load(path);
    }
    let stem = name.trim_end_matches(".ron");
    let stem = stem.rsplit('/').next().unwrap_or(stem);
    match SHIPPED.iter().find(|(file, _)| file.trim_end_matches(".ron") == stem) {
        Some((file, text)) => Deck::from_ron(text, file, None),
        None => Err(DeckError::Read {
            path: path.into(),
            cause: std::io::Error::new(std::io::ErrorKind::NotFound, "no such file and no shipped deck of that name"),
        }),
    }
}

/// A file-name-safe form of a title: lower case, words joined by '-'.
pub fn slug(title: &str) -> String {
    let mut out = String::new();
    for c in title.chars().flat_map(char::to_lowercase) {
        if c.is_ascii_alphanumeric() {
            out.push(c);
        } else if !out.ends_with('-') && !out.is_empty() {
            out.push('-');
        }
    }
    let out = out.trim_end_matches('-');
    out.chars().take(40).collect::<String>().trim_end_matches('-').to_string()
}

/// The folder of slide `i` (0-based) in a handout: "03-title-words".
pub fn slide_folder(i: usize, slide: &Slide) -> String {
    let s = slug(&slide.title);
    if s.is_empty() { format!("{:02}", i + 1) } else { format!("{:02}-{s}", i + 1) }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every shipped deck loads, every slide resolves and has notes a
    /// lecturer can read from.
    #[test]
    fn shipped_decks_load_with_notes() {
        for (file, text) in SHIPPED {
            let loaded = Deck::from_ron(text, file, None).unwrap_or_else(|e| panic!("{e}"));
            assert!(loaded.deck.slides.len() >= 5, "{file}");
            for s in &loaded.deck.slides {
                assert!(s.notes.split_whitespace().count() >= 25, "{file}: '{}' has short notes", s.title);
            }
        }
        let overview = Deck::from_ron(SHIPPED[0].1, SHIPPED[0].0, None).expect("overview");
        assert!((10..=15).contains(&overview.deck.slides.len()));
        let chapters: std::collections::BTreeSet<&str> = overview.params.iter().map(|p| p.info().id).collect();
        assert!(chapters.len() >= 8, "the overview walks many scenes: {chapters:?}");
    }

    /// Speaker notes write a unit as the slide's controls show it ("J/m²",
    /// not "J m⁻²"): one form of a unit within a slide.
    #[test]
    fn notes_write_units_as_the_controls_do() {
        for (file, text) in SHIPPED {
            let mut loaded = Deck::from_ron(text, file, None).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(loaded.deck.slides.len(), loaded.params.len());
            for (slide, params) in loaded.deck.slides.iter().zip(loaded.params.iter_mut()) {
                for c in params.controls() {
                    // The stored unit written out, where the screen writes the same unit otherwise.
                    let (screen, written) = (crate::units::pretty(c.unit), crate::units::superscripts(c.si_unit));
                    if !c.unit.is_empty() && crate::units::pretty(c.si_unit) == screen && written != screen {
                        assert!(
                            !slide.notes.contains(&format!(" {written}")),
                            "{file}: '{}' writes {written} where its control {} shows {screen}",
                            slide.title,
                            c.key
                        );
                    }
                }
            }
        }
    }

    /// Slides that do not resolve are refused with their number and title.
    #[test]
    fn bad_slides_are_named() {
        let cases = [
            (r#"(slides: [(title: "A", preset: Some("no-such-preset"))])"#, "slide 1 ('A')"),
            (r#"(slides: [(title: "A")])"#, "give a 'preset'"),
            (r#"(slides: [(title: "A", preset: Some("ice-bounce-8ms"), set: ["velocity=-1"])])"#, "velocity"),
            (r#"(slides: [(title: "A", preset: Some("ice-bounce-8ms"), highlight: ["nope"])])"#, "'nope'"),
            (r#"(slides: [])"#, "at least one slide"),
            (r#"(slides: [(title: "A", unknown: 1)])"#, "t:1:"),
        ];
        for (text, wanted) in cases {
            let err = Deck::from_ron(text, "t", None).expect_err(text).to_string();
            assert!(err.contains(wanted), "{text}: {err}");
        }
    }

    /// A deck saved and read back is the same deck with the same parameters.
    #[test]
    fn decks_round_trip() {
        let loaded = Deck::from_ron(SHIPPED[1].1, SHIPPED[1].0, None).expect("loads");
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("deck.ron");
        loaded.deck.save(&path).expect("saves");
        let back = Deck::load(&path).expect("reads");
        assert_eq!(back.deck, loaded.deck);
        assert_eq!(back.params, loaded.params);
    }

    #[test]
    fn slugs_are_file_names() {
        assert_eq!(slug("Why do grains stick? (Sect. 1.3)"), "why-do-grains-stick-sect-1-3");
        assert_eq!(slide_folder(2, &Slide { title: "Ωt_s = 1".into(), ..Slide::default() }), "03-t-s-1");
    }
}
