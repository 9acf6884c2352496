//! The desktop platform: rfd's file dialogs, files by path with `std::fs`,
//! the session in a RON file, and the monotonic system clock.

use super::{Answer, FileKind, Picked, Platform};
use crate::files::{FileSet, write_atomically};
use crate::session::Restored;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::time::Instant;

/// Files, dialogs, session and clock of a desktop.
pub struct NativePlatform {
    /// The session file (none: the session is neither read nor kept).
    session_path: Option<PathBuf>,
    /// Whether saving the session over its file is safe (an unreadable file
    /// that could not be set aside is never written over).
    may_save: bool,
    answers: (Sender<Answer>, Receiver<Answer>),
    start: Instant,
}

impl NativePlatform {
    /// A desktop platform keeping the session at `session_path`.
    pub fn new(session_path: Option<PathBuf>) -> Self {
        NativePlatform { session_path, may_save: true, answers: channel(), start: Instant::now() }
    }

    /// Shows a blocking dialog off the window's thread: the desktop's
    /// dialog blocks its caller until the user answers, and the window must
    /// keep drawing meanwhile. The answer arrives by [`Platform::poll`].
    fn in_background(&self, dialog: impl FnOnce() -> Answer + Send + 'static) {
        let tx = self.answers.0.clone();
        let shown = std::thread::Builder::new().name("grainscope-dialog".into()).spawn(move || {
            let _ = tx.send(dialog());
        });
        if shown.is_err() {
            let _ = self.answers.0.send(Answer::Cancelled);
        }
    }
}

fn dialog(kind: FileKind) -> rfd::FileDialog {
    let (name, extensions) = kind.filter();
    rfd::FileDialog::new().add_filter(name, extensions)
}

impl Platform for NativePlatform {
    fn pick_file(&mut self, kind: FileKind) {
        self.in_background(move || {
            let Some(path) = dialog(kind).pick_file() else { return Answer::Cancelled };
            match std::fs::read(&path) {
                Ok(bytes) => Answer::Opened(kind, Picked { name: path.display().to_string(), bytes }),
                Err(e) => Answer::Failed(kind, format!("cannot read {}: {e}", path.display())),
            }
        });
    }

    fn save_file(&mut self, kind: FileKind, suggested: &str, bytes: Vec<u8>) {
        let suggested = suggested.to_string();
        self.in_background(move || {
            let Some(path) = dialog(kind).set_file_name(suggested).save_file() else { return Answer::Cancelled };
            match write_atomically(&path, &bytes) {
                Ok(()) => Answer::Saved(kind, path.display().to_string()),
                Err(e) => Answer::Failed(kind, e.to_string()),
            }
        });
    }

    fn poll(&mut self) -> Vec<Answer> {
        self.answers.1.try_iter().collect()
    }

    fn read(&mut self, name: &str) -> Result<Vec<u8>, String> {
        std::fs::read(name).map_err(|e| format!("cannot read {name}: {e}"))
    }

    fn write(&mut self, name: &str, bytes: &[u8]) -> Result<String, String> {
        write_atomically(Path::new(name), bytes).map(|()| name.to_string()).map_err(|e| e.to_string())
    }

    fn write_all(&mut self, folder: &str, files: &[(String, Vec<u8>)]) -> Result<Vec<String>, String> {
        let dir = Path::new(folder);
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot create folder {}: {e}", dir.display()))?;
        let mut set = FileSet::new();
        for (name, bytes) in files {
            set.stage(&dir.join(name), bytes).map_err(|e| e.to_string())?;
        }
        let written = set.commit().map_err(|e| e.to_string())?;
        Ok(written.iter().map(|p| p.display().to_string()).collect())
    }

    fn load_session(&mut self) -> Restored {
        match &self.session_path {
            Some(path) => {
                let restored = crate::session::load(path);
                self.may_save = restored.may_save;
                restored
            }
            None => Restored { session: Default::default(), found: false, notice: None, may_save: false },
        }
    }

    fn save_session(&mut self, bytes: &[u8]) -> Result<(), String> {
        match &self.session_path {
            Some(path) if self.may_save => write_atomically(path, bytes).map_err(|e| e.to_string()),
            _ => Ok(()),
        }
    }

    fn now(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }
}
