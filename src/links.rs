//! Links that open the explorer in a given state: the query part of a web
//! address, so that a lecturer can put one on a slide (or in a QR code) and
//! every student lands on the same scene.
//!
//! - `?preset=NAME` opens a shipped preset;
//! - `?deck=NAME&slide=N` presents a shipped deck from slide N (from 1);
//! - `?scene=ID&KEY=VALUE&…` opens a scene with the parameters that differ
//!   from its defaults, in SI units as `--set` takes them;
//! - `?state=RON` carries a whole preset, for a state its parameters alone
//!   cannot say (a measurement table, say).
//!
//! [`link_to`] writes the shortest of these that reopens the state exactly.

use crate::deck::LoadedDeck;
use crate::preset::Preset;
use crate::scene::SceneParams;
use crate::scene::controls::DefaultValue;
use percent_encoding::{AsciiSet, NON_ALPHANUMERIC, percent_decode_str, utf8_percent_encode};

/// Characters written as they are in a query value; everything else is
/// percent-encoded.
const KEPT: &AsciiSet = &NON_ALPHANUMERIC.remove(b'-').remove(b'.').remove(b'_').remove(b'~');

/// The longest `?state=` link written, characters (browsers and QR codes
/// take far more, but a link this long is no longer one to copy by hand).
pub const LONGEST: usize = 8000;

/// What a link opens.
#[derive(Debug)]
pub enum Opened {
    /// A scene's state, and the name it is shown under.
    Preset(Box<Preset>, String),
    /// A deck, presented from this slide (from 0).
    Deck(Box<LoadedDeck>, usize),
    /// Nothing (no known key in the query).
    Nothing,
}

/// The (key, value) pairs of a query ("?a=1&b=2" or "a=1&b=2"), decoded.
pub fn pairs(query: &str) -> Result<Vec<(String, String)>, String> {
    let decode = |s: &str| {
        percent_decode_str(&s.replace('+', " "))
            .decode_utf8()
            .map(|c| c.into_owned())
            .map_err(|_| format!("the link's {s:?} is not UTF-8 text"))
    };
    query
        .trim_start_matches('?')
        .split('&')
        .filter(|p| !p.is_empty())
        .map(|p| {
            let (k, v) = p.split_once('=').unwrap_or((p, ""));
            Ok((decode(k)?, decode(v)?))
        })
        .collect()
}

/// What the query of a link opens; an error names what is wrong with it.
pub fn open(query: &str) -> Result<Opened, String> {
    let pairs = pairs(query)?;
    let get = |key: &str| pairs.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str());
    if let Some(name) = get("preset") {
        let preset = crate::preset::resolve(name).map_err(|e| format!("the link's preset {name}: {e}"))?;
        return Ok(Opened::Preset(Box::new(preset), name.to_string()));
    }
    if let Some(name) = get("deck") {
        let deck = crate::deck::resolve(name).map_err(|e| format!("the link's deck {name}: {e}"))?;
        let slides = deck.deck.slides.len();
        let slide = match get("slide") {
            None => 1,
            Some(s) => match s.trim().parse::<usize>() {
                Ok(n) if (1..=slides).contains(&n) => n,
                _ => return Err(format!("the link's slide {s} is not a slide of deck {name} (1 to {slides})")),
            },
        };
        return Ok(Opened::Deck(Box::new(deck), slide - 1));
    }
    if let Some(text) = get("state") {
        let preset = Preset::from_ron(text, "the link").map_err(|e| e.to_string())?;
        let name = format!("a link to {}", preset.scene.info().title);
        return Ok(Opened::Preset(Box::new(preset), name));
    }
    if let Some(id) = get("scene") {
        let mut params = SceneParams::default_for(id).ok_or_else(|| format!("the link's scene {id} is not a scene"))?;
        for (key, value) in pairs.iter().filter(|(k, _)| k != "scene") {
            params.set(key, value).map_err(|e| format!("the link's {key}={value}: {e}"))?;
        }
        let title = params.info().title.to_string();
        let preset = Preset { title: title.clone(), description: String::new(), scene: params, sensitivity: None };
        return Ok(Opened::Preset(Box::new(preset), format!("a link to {title}")));
    }
    Ok(Opened::Nothing)
}

/// A control's value as `--set` takes it.
fn text(value: &DefaultValue) -> String {
    match value {
        // Rust writes the shortest text that reads back to the same number.
        DefaultValue::Number(v) => format!("{v}"),
        DefaultValue::Count(n) => n.to_string(),
        DefaultValue::Toggle(b) => b.to_string(),
        DefaultValue::Text(s) => s.clone(),
    }
}

/// The query of a link that reopens `params` exactly: the scene and the
/// parameters that differ from its defaults where those say it all, else
/// the whole state. None when even that would be longer than [`LONGEST`].
pub fn link_to(params: &SceneParams) -> Option<String> {
    let id = params.info().id;
    let defaults = SceneParams::default_for(id)?;
    let mut query = format!("?scene={}", utf8_percent_encode(id, KEPT));
    for key in params.keys() {
        let Some(value) = params.get(key) else { continue };
        if defaults.get(key).as_ref() == Some(&value) {
            continue;
        }
        query.push_str(&format!("&{key}={}", utf8_percent_encode(&text(&value), KEPT)));
    }
    // The parameters say it all when they rebuild this very state.
    let rebuilt = match open(&query) {
        Ok(Opened::Preset(p, _)) => p.scene == *params,
        _ => false,
    };
    if rebuilt {
        return Some(query);
    }
    let preset = Preset { title: String::new(), description: String::new(), scene: params.clone(), sensitivity: None };
    let ron = preset.to_ron().ok()?;
    let query = format!("?state={}", utf8_percent_encode(&ron, KEPT));
    (query.len() <= LONGEST).then_some(query)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reopened(query: &str) -> SceneParams {
        match open(query) {
            Ok(Opened::Preset(p, _)) => p.scene,
            other => panic!("{query}: {other:?}"),
        }
    }

    /// Every shipped preset's state comes back from its link, and a preset
    /// that only moves parameters gets a short, readable one.
    #[test]
    fn every_shipped_preset_survives_its_link() {
        for (file, _) in crate::preset::SHIPPED {
            let preset = crate::preset::resolve(file).expect("shipped");
            match link_to(&preset.scene) {
                Some(query) => assert_eq!(reopened(&query), preset.scene, "{file}: {query}"),
                // Only a state too large to say in a link has none (a table of measurements).
                None => {
                    let whole = Preset { title: String::new(), description: String::new(), ..preset };
                    let ron = whole.to_ron().expect("writes");
                    assert!(utf8_percent_encode(&ron, KEPT).to_string().len() > LONGEST, "{file}: no link");
                }
            }
        }
        let mut p = crate::preset::resolve("ice-bounce-8ms").expect("shipped").scene;
        p.set("velocity", "3").expect("in range");
        let query = link_to(&p).expect("a link");
        assert!(query.starts_with("?scene=hysteresis&") && query.contains("velocity=3"), "{query}");
        assert_eq!(reopened(&query), p);
    }

    /// A default scene's link names only the scene.
    #[test]
    fn a_default_scene_links_by_name_alone() {
        let p = SceneParams::default_for("restitution").expect("a scene");
        assert_eq!(link_to(&p).as_deref(), Some("?scene=restitution"));
    }

    #[test]
    fn presets_and_deck_slides_open_by_name() {
        assert!(matches!(open("?preset=ice-bounce-8ms"), Ok(Opened::Preset(_, n)) if n == "ice-bounce-8ms"));
        assert!(matches!(open("?deck=porous-growth&slide=3"), Ok(Opened::Deck(_, 2))));
        assert!(matches!(open(""), Ok(Opened::Nothing)));
        assert!(matches!(open("?utm_source=slides"), Ok(Opened::Nothing)));
    }

    /// A bad link says what is wrong with it.
    #[test]
    fn bad_links_are_named() {
        let e = |q: &str| open(q).err().unwrap_or_else(|| panic!("{q} opened"));
        assert!(e("?preset=no-such").contains("no-such"));
        assert!(e("?deck=porous-growth&slide=99").contains("1 to 10"));
        assert!(e("?deck=porous-growth&slide=x").contains("slide x"));
        assert!(e("?scene=nothing").contains("nothing"));
        assert!(e("?scene=hysteresis&velocity=-1").contains("velocity"));
        assert!(e("?scene=hysteresis&nonsense=1").contains("nonsense"));
        assert!(e("?state=(scene:").contains("the link"));
        assert!(e("?preset=%FF").contains("UTF-8"));
    }
}
