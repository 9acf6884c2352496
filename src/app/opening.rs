//! What a file given to the window means, from its name and bytes: a
//! preset or a deck (`.ron`), a figure exported by grainscope (its embedded
//! state), or measurements (a CSV file without embedded state).

use super::platform::Picked;
use crate::deck::{Deck, DeckError, LoadedDeck};
use crate::physics::fit::Measurement;
use crate::preset::{Preset, PresetError};
use crate::provenance::ProvenanceError;
use std::path::Path;

/// What a file stands for.
pub enum Opened {
    /// A scene's state.
    Preset(Box<Preset>),
    /// A lecture.
    Deck(LoadedDeck),
    /// Measurements for the fit.
    Measurements,
}

fn extension(name: &str) -> String {
    Path::new(name).extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase()
}

fn text(picked: &Picked) -> Result<&str, String> {
    std::str::from_utf8(&picked.bytes).map_err(|_| format!("{} is not UTF-8 text", picked.name))
}

/// Reads a file as the window opens it; an error says why, naming the file.
pub fn open(picked: &Picked) -> Result<Opened, String> {
    let ext = extension(&picked.name);
    if matches!(ext.as_str(), "png" | "svg" | "csv") {
        return match crate::preset::from_embedded_bytes(&picked.bytes, &picked.name) {
            Ok(p) => Ok(Opened::Preset(Box::new(p))),
            Err(PresetError::Embedded(e)) if ext == "csv" && matches!(*e, ProvenanceError::Missing(_)) => {
                Ok(Opened::Measurements)
            }
            Err(e) => Err(format!("preset not loaded: {e}")),
        };
    }
    let text = text(picked)?;
    match Preset::from_ron(text, &picked.name) {
        Ok(p) => Ok(Opened::Preset(Box::new(p))),
        Err(preset_error) => match Deck::from_ron(text, &picked.name, base(&picked.name)) {
            Ok(d) => Ok(Opened::Deck(d)),
            Err(DeckError::Read { .. }) | Err(DeckError::Syntax { .. }) => {
                Err(format!("preset not loaded: {preset_error}"))
            }
            Err(deck_error) => Err(format!("deck not loaded: {deck_error}")),
        },
    }
}

/// The folder a deck's relative preset files are looked up in: the deck's own.
fn base(name: &str) -> Option<&Path> {
    Path::new(name).parent().filter(|p| !p.as_os_str().is_empty())
}

/// Reads a deck for the deck editor.
pub fn deck(picked: &Picked) -> Result<LoadedDeck, String> {
    let text = text(picked)?;
    Deck::from_ron(text, &picked.name, base(&picked.name)).map_err(|e| e.to_string())
}

/// Reads measurements.
pub fn measurements(picked: &Picked) -> Result<Vec<Measurement>, String> {
    let text = std::str::from_utf8(&picked.bytes).map_err(|_| "not UTF-8 text".to_string())?;
    crate::measurements::parse(text).map_err(|e| e.to_string())
}

/// A shipped preset or deck by name (with or without `.ron`), as a file.
pub fn shipped(name: &str) -> Option<Picked> {
    let stem = name.trim_end_matches(".ron");
    let stem = stem.rsplit('/').next().unwrap_or(stem);
    crate::preset::SHIPPED
        .iter()
        .chain(crate::deck::SHIPPED.iter())
        .find(|(file, _)| file.trim_end_matches(".ron") == stem)
        .map(|(file, text)| Picked { name: file.to_string(), bytes: text.as_bytes().to_vec() })
}

/// Resolves every slide of a deck built in the window.
pub fn resolve_all(deck: &Deck, base: Option<&Path>) -> Result<LoadedDeck, String> {
    if deck.slides.is_empty() {
        return Err("the deck has no slides yet: add the current state as a slide".into());
    }
    let params = deck
        .slides
        .iter()
        .enumerate()
        .map(|(i, s)| s.resolve(base).map_err(|e| format!("slide {} ('{}'): {e}", i + 1, s.title)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(LoadedDeck { deck: deck.clone(), params, origin: "the deck editor".into() })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Shipped presets and decks open by name; their kinds are told apart.
    #[test]
    fn shipped_files_open_by_name() {
        let preset = shipped("ice-bounce-8ms").expect("shipped preset");
        assert!(matches!(open(&preset), Ok(Opened::Preset(_))));
        let deck = shipped("porous-growth.ron").expect("shipped deck");
        assert!(matches!(open(&deck), Ok(Opened::Deck(_))));
        assert!(shipped("no-such-thing").is_none());
    }

    /// A preset with a bad value names the file, line and value.
    #[test]
    fn a_bad_preset_names_its_place() {
        let bad = Picked {
            name: "bad.ron".into(),
            bytes: b"(title: \"bad\", scene: Hysteresis((collision: (velocity: -1e0))))".to_vec(),
        };
        let e = open(&bad).err().expect("refused");
        assert!(e.starts_with("preset not loaded: bad.ron:1:") && e.contains("velocity = -1e0 is outside"), "{e}");
    }
}
