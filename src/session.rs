//! The explorer's session: what is restored on the next start (open scene,
//! every scene's parameters, pins, paths). It lives in its own RON file,
//! written atomically. A file that cannot be read never stops the explorer:
//! it starts with default settings, says so once, and keeps the unreadable
//! file beside the new one for inspection.

use crate::figure::Series;
use crate::files::{WriteError, write_atomically};
use crate::scene::{SCENES, SceneParams};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Curves kept for comparison.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pin {
    /// Parameters they were computed with.
    pub params: SceneParams,
    /// Fixed label (sweeps) or empty to label by the parameters that differ.
    pub label: String,
    /// (figure id, series) pairs.
    pub curves: Vec<(String, Series)>,
    /// Colour index.
    pub color: usize,
}

/// What is restored on the next start.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Session {
    /// Identifier of the open scene.
    pub scene: String,
    /// Parameters of every scene, by scene identifier (so adding or
    /// reordering scenes keeps every scene's settings).
    pub params: BTreeMap<String, SceneParams>,
    /// Pinned curves.
    pub pins: Vec<Pin>,
    /// Lecture mode: plots fill the screen in a light high-contrast theme
    /// with large text and thick lines; parameters in a panel over them.
    pub lecture: bool,
    /// Light theme outside lecture mode (lecture mode is always light).
    pub light: bool,
    /// Folder for quick exports.
    pub export_dir: String,
    /// Path typed for loading and saving presets.
    pub preset_path: String,
    /// Path typed for importing measurements.
    pub data_path: String,
    /// How each scene shows its panels, by scene identifier: the identifier
    /// of the one figure shown alone, or [`ALL_PANELS`] for every panel at
    /// once; a scene without an entry shows them all when they fit at a
    /// legible size, else one at a time.
    pub panels: BTreeMap<String, String>,
}

/// The entry of [`Session::panels`] that shows every panel of a scene at once.
pub const ALL_PANELS: &str = "all";

impl Default for Session {
    fn default() -> Self {
        Session {
            scene: SCENES[0].id.to_string(),
            params: SCENES
                .iter()
                .filter_map(|s| SceneParams::default_for(s.id).map(|p| (s.id.to_string(), p)))
                .collect(),
            pins: Vec::new(),
            lecture: false,
            light: false,
            export_dir: "exports".into(),
            preset_path: "presets/my-preset.ron".into(),
            data_path: "assets/examples/wall-mica-synthetic.csv".into(),
            panels: BTreeMap::new(),
        }
    }
}

impl Session {
    /// Repairs a restored session: scenes that are unknown, stored under
    /// another scene's id or invalid are dropped, missing ones get defaults.
    pub fn repaired(mut self) -> Session {
        self.params.retain(|id, p| p.info().id == id && p.validate().is_ok());
        for (id, p) in Session::default().params {
            self.params.entry(id).or_insert(p);
        }
        self.pins.retain(|pin| pin.params.validate().is_ok());
        if !self.params.contains_key(&self.scene) {
            self.scene = SCENES[0].id.to_string();
        }
        self
    }

    /// Position of the open scene in [`SCENES`].
    pub fn index(&self) -> usize {
        SCENES.iter().position(|s| s.id == self.scene).unwrap_or(0)
    }
}

/// A session read from its file, with what the user should be told about it.
#[derive(Debug)]
pub struct Restored {
    /// The session (default settings when there was none or it was unreadable).
    pub session: Session,
    /// Whether a session file was found and read.
    pub found: bool,
    /// A message for the user when the file could not be read.
    pub notice: Option<String>,
    /// Whether saving to the path is safe: false when an unreadable file
    /// could not be set aside (saving would destroy it).
    pub may_save: bool,
}

/// Parses a session from RON text and repairs it (see [`Session::repaired`]).
pub fn parse(text: &str) -> Result<Session, String> {
    ron::from_str::<Session>(text).map(Session::repaired).map_err(|e| e.to_string())
}

/// Reads the session at `path`. A missing file gives the default session
/// silently; an unreadable one (truncated, garbage, a format this version
/// does not know) gives the default session, is renamed to
/// `<name>.unreadable-<seconds since 1970>` and named in the notice.
pub fn load(path: &Path) -> Restored {
    let fresh = |notice| Restored { session: Session::default(), found: false, notice, may_save: true };
    let text = match std::fs::read(path) {
        Ok(bytes) => String::from_utf8(bytes).map_err(|_| "not UTF-8 text".to_string()),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return fresh(None),
        Err(e) => Err(e.to_string()),
    };
    match text.and_then(|t| parse(&t)) {
        Ok(session) => Restored { session, found: true, notice: None, may_save: true },
        Err(why) => {
            let why = why.lines().next().unwrap_or_default().to_string();
            let head = format!(
                "the saved session {} could not be read ({why}); started with default settings",
                path.display()
            );
            match set_aside(path) {
                Ok(aside) => fresh(Some(format!("{head}, the file was kept as {}", aside.display()))),
                Err(e) => Restored {
                    may_save: false,
                    ..fresh(Some(format!(
                        "{head}; it could not be set aside ({e}), so this session will not be saved over it"
                    )))
                },
            }
        }
    }
}

/// Renames an unreadable session file out of the way, never over another file.
fn set_aside(path: &Path) -> std::io::Result<PathBuf> {
    let seconds = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let name = path.file_name().map_or_else(|| "session".into(), |n| n.to_string_lossy().into_owned());
    for n in 0..100 {
        let suffix = if n == 0 { String::new() } else { format!("-{n}") };
        let aside = path.with_file_name(format!("{name}.unreadable-{seconds}{suffix}"));
        if !aside.exists() {
            std::fs::rename(path, &aside)?;
            return Ok(aside);
        }
    }
    Err(std::io::Error::other("too many unreadable session files"))
}

/// The session as the RON text of its file.
pub fn to_ron(session: &Session) -> Result<String, String> {
    ron::ser::to_string_pretty(session, ron::ser::PrettyConfig::default().struct_names(false))
        .map_err(|e| e.to_string())
}

/// Writes the session to `path` atomically.
pub fn save(session: &Session, path: &Path) -> Result<(), WriteError> {
    let text = to_ron(session).map_err(|e| WriteError {
        path: path.to_path_buf(),
        cause: std::io::Error::other(e),
        written: Vec::new(),
        not_written: vec![path.to_path_buf()],
    })?;
    write_atomically(path, text.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_saved_session_reads_back() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("session.ron");
        let session = Session { scene: "rocking".into(), lecture: true, ..Session::default() };
        save(&session, &path).unwrap();
        let restored = load(&path);
        assert!(restored.found && restored.notice.is_none());
        assert_eq!(restored.session, session);
    }

    #[test]
    fn a_missing_session_starts_clean_silently() {
        let dir = tempfile::tempdir().unwrap();
        let restored = load(&dir.path().join("session.ron"));
        assert!(!restored.found && restored.notice.is_none());
        assert_eq!(restored.session, Session::default());
    }

    /// Truncated, garbage and binary files: the explorer starts clean, says
    /// so, and the bad file is kept, byte for byte, beside the path.
    #[test]
    fn an_unreadable_session_is_kept_aside() {
        let good = ron::to_string(&Session::default()).unwrap();
        let cases: [&[u8]; 4] = [&good.as_bytes()[..good.len() / 2], b"garbage {{{", &[0xff, 0xfe, 0x00, 0x42], b""];
        for bytes in cases {
            let dir = tempfile::tempdir().unwrap();
            let path = dir.path().join("session.ron");
            std::fs::write(&path, bytes).unwrap();
            let restored = load(&path);
            assert!(!restored.found);
            assert_eq!(restored.session, Session::default());
            let notice = restored.notice.expect("a notice");
            assert!(notice.contains("started with default settings") && notice.contains("kept as"), "{notice}");
            assert!(!path.exists(), "the bad file is moved, not overwritten");
            let kept: Vec<_> = std::fs::read_dir(dir.path()).unwrap().filter_map(|e| e.ok()).collect();
            assert_eq!(kept.len(), 1);
            assert_eq!(std::fs::read(kept[0].path()).unwrap(), bytes);
        }
    }
}
