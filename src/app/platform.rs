//! What differs per platform, behind one small trait that deals in bytes:
//! asking the user for a file to open, saving bytes under a suggested name,
//! writing files into a folder the user named, the session's storage and a
//! clock. The window asks for these and never touches a file system, a
//! dialog or a system clock itself; [`native::NativePlatform`] implements
//! them with rfd and `std::fs`, and the browser build (`web/`) with a
//! file picker, downloads and local storage.

#[cfg(not(target_arch = "wasm32"))]
pub mod native;

use crate::session::Restored;

/// The kinds of file the window asks for; each names its filter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// A preset or deck (`.ron`).
    Preset,
    /// Measurements (`.csv`).
    Measurements,
    /// An exported figure (`.png`, `.svg` or `.csv`).
    Figure,
}

impl FileKind {
    /// The filter's name and its extensions.
    pub fn filter(self) -> (&'static str, &'static [&'static str]) {
        match self {
            FileKind::Preset => ("preset", &["ron"]),
            FileKind::Measurements => ("measurements", &["csv"]),
            FileKind::Figure => ("PNG, SVG or CSV", &["png", "svg", "csv"]),
        }
    }
}

/// A file the user gave the window: its name (a full path where the
/// platform has paths) and its bytes.
#[derive(Debug, Clone, PartialEq)]
pub struct Picked {
    /// The name as the platform gives it.
    pub name: String,
    /// The file's content.
    pub bytes: Vec<u8>,
}

/// What a platform reports back from a dialog it was asked to show.
#[derive(Debug, Clone, PartialEq)]
pub enum Answer {
    /// A file was picked to open.
    Opened(FileKind, Picked),
    /// Bytes of this kind were saved where the user chose (the name or path shown).
    Saved(FileKind, String),
    /// Reading or saving a file of this kind failed (why).
    Failed(FileKind, String),
    /// The dialog was cancelled, or the platform has none.
    Cancelled,
}

/// The platform services the window uses.
pub trait Platform {
    /// Asks the user for a file to open; the answer arrives by [`Platform::poll`].
    fn pick_file(&mut self, kind: FileKind);
    /// Asks the user where to save `bytes` (suggested file name); the answer
    /// arrives by [`Platform::poll`].
    fn save_file(&mut self, kind: FileKind, suggested: &str, bytes: Vec<u8>);
    /// Answers of dialogs that finished since the last call.
    fn poll(&mut self) -> Vec<Answer>;
    /// Reads the file the user named (a typed path); an error says why.
    fn read(&mut self, name: &str) -> Result<Vec<u8>, String>;
    /// Writes `bytes` under the name the user gave, replacing an earlier
    /// file only when the whole of it is written. Returns the name written.
    fn write(&mut self, name: &str, bytes: &[u8]) -> Result<String, String>;
    /// Writes `files` (name, bytes) into the folder the user named, all or
    /// nothing. Returns the names written.
    fn write_all(&mut self, folder: &str, files: &[(String, Vec<u8>)]) -> Result<Vec<String>, String>;
    /// The session kept from the last start (default settings with a notice
    /// when it could not be read).
    fn load_session(&mut self) -> Restored;
    /// Keeps the session (RON bytes) for the next start.
    fn save_session(&mut self, bytes: &[u8]) -> Result<(), String>;
    /// Seconds since an arbitrary start, never going back.
    fn now(&self) -> f64;
    /// Whether the user can name files and folders by path (a typed preset
    /// or data path, an export folder). A browser cannot: it saves by
    /// downloads and opens by its file picker or a drop, and the window
    /// shows no path fields there.
    fn paths(&self) -> bool {
        true
    }
    /// Offers a link to the present state, `query` being its query part
    /// (see [`crate::links`]): the whole address and where it went, or why
    /// there is none.
    fn share_link(&mut self, query: &str) -> Result<SharedLink, String> {
        Err(format!("a link opens the browser version: add {query} to the address of its page"))
    }
}

/// A link the platform gave to the present state.
#[derive(Debug, Clone, PartialEq)]
pub struct SharedLink {
    /// The whole address.
    pub address: String,
    /// What the status line says, e.g. where the link went.
    pub said: String,
}

/// A platform with nothing behind it: no dialogs, no files, no session;
/// a clock that stands still. For tests of the window's state.
#[derive(Debug, Default)]
pub struct NullPlatform {
    answers: Vec<Answer>,
}

impl Platform for NullPlatform {
    fn paths(&self) -> bool {
        false
    }
    fn pick_file(&mut self, _kind: FileKind) {
        self.answers.push(Answer::Cancelled);
    }
    fn save_file(&mut self, _kind: FileKind, _suggested: &str, _bytes: Vec<u8>) {
        self.answers.push(Answer::Cancelled);
    }
    fn poll(&mut self) -> Vec<Answer> {
        std::mem::take(&mut self.answers)
    }
    fn read(&mut self, name: &str) -> Result<Vec<u8>, String> {
        Err(format!("{name}: no files on this platform"))
    }
    fn write(&mut self, name: &str, _bytes: &[u8]) -> Result<String, String> {
        Err(format!("{name}: no files on this platform"))
    }
    fn write_all(&mut self, folder: &str, _files: &[(String, Vec<u8>)]) -> Result<Vec<String>, String> {
        Err(format!("{folder}: no files on this platform"))
    }
    fn load_session(&mut self) -> Restored {
        Restored { session: Default::default(), found: false, notice: None, may_save: false }
    }
    fn save_session(&mut self, _bytes: &[u8]) -> Result<(), String> {
        Ok(())
    }
    fn now(&self) -> f64 {
        0.0
    }
}
