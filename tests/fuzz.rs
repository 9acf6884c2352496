//! Property tests on everything a user can hand the explorer: mutated preset
//! files, `--set` values, measurement CSVs and session files. None may panic;
//! whatever is accepted is valid and round-trips; whatever is rejected
//! changes nothing (no parameter, no existing file, no temporary left).
//!
//! Each property runs `GRAINSCOPE_FUZZ_CASES` cases (256 by default), and
//! the one that computes and writes a scene a sixteenth of them; `.ci/run`
//! raises it so that CI runs over 10 000 cases. proptest's own
//! `PROPTEST_CASES`, if set, overrides both counts: the test macro applies it
//! over a property's configuration.

use grainscope::cli::{Command, run};
use grainscope::preset::{Preset, SHIPPED};
use grainscope::scene::{ControlKind, SCENES, SceneParams};
use proptest::prelude::*;
use proptest::sample::Index;
use std::path::Path;

/// Cases per property: `GRAINSCOPE_FUZZ_CASES`, divided by `cost` for the
/// properties that compute and write a scene.
fn config(cost: u32) -> ProptestConfig {
    let cases = std::env::var("GRAINSCOPE_FUZZ_CASES").ok().and_then(|v| v.parse::<u32>().ok()).unwrap_or(256);
    ProptestConfig { cases: (cases / cost).max(8), failure_persistence: None, ..ProptestConfig::default() }
}

/// Text a user (or a broken disk) might put into a file.
fn fragment() -> impl Strategy<Value = String> {
    let pieces = prop_oneof![
        Just("nan".to_string()),
        Just("inf".to_string()),
        Just("-inf".to_string()),
        Just("1e300".to_string()),
        Just("-1".to_string()),
        Just("0".to_string()),
        Just("1e-320".to_string()),
        Just("18446744073709551616".to_string()),
        Just("\"".to_string()),
        Just("(".to_string()),
        Just(")".to_string()),
        Just(",".to_string()),
        Just(":".to_string()),
        Just("//".to_string()),
        Just("\n".to_string()),
        Just("Some(".to_string()),
        Just("true".to_string()),
        Just("\u{0}".to_string()),
        Just("é→γ".to_string()),
        any::<f64>().prop_map(|v| format!("{v:e}")),
        any::<i64>().prop_map(|v| v.to_string()),
        proptest::collection::vec(any::<char>(), 0..6).prop_map(|c| c.into_iter().collect()),
    ];
    proptest::collection::vec(pieces, 1..4).prop_map(|v| v.concat())
}

/// One edit of a text.
#[derive(Debug, Clone)]
enum Edit {
    /// Cut the text here (a truncated file).
    Truncate(Index),
    /// Remove a stretch.
    Delete(Index, usize),
    /// Insert a fragment.
    Insert(Index, String),
    /// Replace the n-th number in the text.
    Number(Index, String),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        1 => any::<Index>().prop_map(Edit::Truncate),
        1 => (any::<Index>(), 1usize..40).prop_map(|(i, n)| Edit::Delete(i, n)),
        1 => (any::<Index>(), fragment()).prop_map(|(i, s)| Edit::Insert(i, s)),
        3 => (any::<Index>(), fragment()).prop_map(|(i, s)| Edit::Number(i, s)),
    ]
}

/// Byte offsets of char boundaries, so edits keep valid UTF-8 where the
/// inserted text is valid.
fn boundary(text: &str, i: &Index) -> usize {
    let bounds: Vec<usize> = text.char_indices().map(|(b, _)| b).chain([text.len()]).collect();
    bounds[i.index(bounds.len())]
}

fn apply(text: &str, edits: &[Edit]) -> String {
    let mut t = text.to_string();
    for e in edits {
        match e {
            Edit::Truncate(i) => {
                let at = boundary(&t, i);
                t.truncate(at);
            }
            Edit::Delete(i, n) => {
                let at = boundary(&t, i);
                let end = t[at..].char_indices().nth(*n).map_or(t.len(), |(b, _)| at + b);
                t.replace_range(at..end, "");
            }
            Edit::Insert(i, s) => {
                let at = boundary(&t, i);
                t.insert_str(at, s);
            }
            Edit::Number(i, s) => {
                let numbers = number_spans(&t);
                if !numbers.is_empty() {
                    let (a, b) = numbers[i.index(numbers.len())];
                    t.replace_range(a..b, s);
                }
            }
        }
    }
    t
}

/// Byte ranges of the numeric literals in `text`.
fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts =
            bytes[i].is_ascii_digit() && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
        if starts {
            let a = if i > 0 && bytes[i - 1] == b'-' { i - 1 } else { i };
            let mut b = i;
            while b < bytes.len() && (bytes[b].is_ascii_digit() || matches!(bytes[b], b'.' | b'e' | b'E' | b'-' | b'+'))
            {
                b += 1;
            }
            spans.push((a, b));
            i = b;
        } else {
            i += 1;
        }
    }
    spans
}

proptest! {
    #![proptest_config(config(1))]

    /// A mutated shipped preset is either refused with a message or accepted
    /// as valid parameters that survive a save and reload unchanged.
    #[test]
    fn mutated_presets_are_refused_or_valid(which in any::<Index>(), edits in proptest::collection::vec(edit(), 1..4)) {
        let (file, text) = SHIPPED[which.index(SHIPPED.len())];
        let mutated = apply(text, &edits);
        match Preset::from_ron(&mutated, file) {
            Ok(preset) => {
                prop_assert!(preset.scene.validate().is_ok());
                let saved = preset.to_ron().expect("an accepted preset serialises");
                let again = Preset::from_ron(&saved, "saved").expect("a saved preset loads");
                prop_assert_eq!(again, preset);
            }
            Err(e) => {
                let message = e.to_string();
                prop_assert!(message.starts_with(file), "the message names the file: {}", message);
                prop_assert!(!message.contains("panicked"));
            }
        }
    }

    /// Any `--set` value for any key of any scene: either taken (and the
    /// parameters stay valid) or refused with nothing changed.
    #[test]
    fn set_values_are_taken_or_change_nothing(scene in any::<Index>(), key in any::<Index>(), value in fragment()) {
        let info = &SCENES[scene.index(SCENES.len())];
        let mut params = SceneParams::default_for(info.id).expect("scene");
        let keys: Vec<&str> = params.controls().iter().map(|c| c.key).collect();
        let key = keys[key.index(keys.len())];
        let before = params.clone();
        match params.set(key, &value) {
            Ok(()) => prop_assert!(params.validate().is_ok()),
            Err(e) => {
                prop_assert_eq!(&params, &before);
                let message = e.to_string();
                prop_assert!(message.contains(key) || message.contains("known:"), "{}", message);
            }
        }
    }

    /// Values inside and around every numeric range: accepted exactly when
    /// inside, the error naming the value as typed.
    #[test]
    fn numbers_are_taken_exactly_inside_their_range(scene in any::<Index>(), key in any::<Index>(), t in -0.5f64..1.5) {
        let info = &SCENES[scene.index(SCENES.len())];
        let mut params = SceneParams::default_for(info.id).expect("scene");
        let ranges: Vec<(&str, f64, f64, bool)> = params
            .controls()
            .iter()
            .filter_map(|c| match &c.kind {
                ControlKind::Number { min, max, log, .. } => Some((c.key, *min, *max, *log)),
                _ => None,
            })
            .collect();
        prop_assume!(!ranges.is_empty());
        let (key, min, max, log) = ranges[key.index(ranges.len())];
        let value = if log && min > 0.0 { min * (max / min).powf(t) } else { min + (max - min) * t };
        let typed = format!("{value:e}");
        let inside = value >= min && value <= max;
        match params.set(key, &typed) {
            Ok(()) => prop_assert!(inside, "{} = {} accepted outside {} … {}", key, typed, min, max),
            Err(e) => {
                let message = e.to_string();
                // Inside the range a value can still contradict another
                // parameter (e.g. a lower end above the upper end).
                prop_assert!(!inside || message.contains("must") || message.contains("below") || message.contains("than"), "{}", message);
                if !inside {
                    prop_assert!(message.contains(&typed), "{}", message);
                }
            }
        }
    }

    /// Mutated measurement files: refused with a line-numbered reason, or
    /// read as finite, positive velocities and finite coefficients.
    #[test]
    fn mutated_measurements_are_refused_or_finite(edits in proptest::collection::vec(edit(), 1..4)) {
        let text = include_str!("../assets/examples/wall-mica-synthetic.csv");
        let mutated = apply(text, &edits);
        if let Ok(data) = grainscope::measurements::parse(&mutated) {
            prop_assert!(!data.is_empty());
            for m in data {
                prop_assert!(m.velocity.is_finite() && m.velocity > 0.0, "{:?}", m);
                prop_assert!(m.restitution.is_finite(), "{:?}", m);
                prop_assert!(m.uncertainty.is_none_or(|s| s.is_finite() && s >= 0.0), "{:?}", m);
            }
        }
    }

    /// Mutated session files never stop the explorer: it starts with a
    /// valid session, and an unreadable file is kept, byte for byte.
    #[test]
    fn mutated_sessions_start_valid_and_keep_the_bad_file(edits in proptest::collection::vec(edit(), 1..4)) {
        let session = grainscope::session::Session { scene: "rocking".into(), ..Default::default() };
        let text = ron::to_string(&session).expect("serialises");
        let mutated = apply(&text, &edits);
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("session.ron");
        std::fs::write(&path, &mutated).expect("write");
        let restored = grainscope::session::load(&path);
        for p in restored.session.params.values() {
            prop_assert!(p.validate().is_ok());
        }
        prop_assert_eq!(restored.session.params.len(), SCENES.len());
        if restored.found {
            prop_assert!(restored.notice.is_none());
            prop_assert_eq!(std::fs::read_to_string(&path).expect("kept"), mutated);
        } else {
            prop_assert!(restored.notice.is_some());
            let files: Vec<_> = std::fs::read_dir(dir.path()).expect("dir").filter_map(|e| e.ok()).collect();
            prop_assert_eq!(files.len(), 1);
            prop_assert_eq!(std::fs::read_to_string(files[0].path()).expect("kept"), mutated);
        }
    }
}

/// Snapshot of a folder: names and contents.
fn snapshot(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("dir")
        .filter_map(|e| e.ok())
        .map(|e| (e.file_name().to_string_lossy().into_owned(), std::fs::read(e.path()).unwrap_or_default()))
        .collect();
    files.sort();
    files
}

proptest! {
    #![proptest_config(config(16))]

    /// `grainscope run PRESET --out DIR` with a mutated preset: when it is
    /// refused, the files already in DIR are unchanged and nothing is added.
    #[test]
    fn a_refused_run_leaves_the_output_folder_alone(which in 0usize..2, edits in proptest::collection::vec(edit(), 1..3)) {
        let name = ["ice-bounce-8ms.ron", "adhesion-ice-monomers.ron"][which];
        let text = SHIPPED.iter().find(|(f, _)| *f == name).map(|(_, t)| *t).expect("shipped");
        let dir = tempfile::tempdir().expect("tempdir");
        let out = dir.path().join("out");
        std::fs::create_dir(&out).expect("out");
        std::fs::write(out.join("contact-radius.csv"), "earlier result").expect("write");
        std::fs::write(out.join("notes.txt"), "the user's own file").expect("write");
        let before = snapshot(&out);
        let preset = dir.path().join("mutated.ron");
        std::fs::write(&preset, apply(text, &edits)).expect("write");
        let result = run(Command::Run {
            preset: preset.display().to_string(),
            set: Vec::new(),
            out: Some(out.clone()),
            json: true,
            preset_only: false,
        });
        if result.is_err() {
            prop_assert_eq!(snapshot(&out), before);
        } else {
            prop_assert!(snapshot(&out).iter().all(|(n, _)| !n.ends_with(".tmp")));
        }
    }
}
