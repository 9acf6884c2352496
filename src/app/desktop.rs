//! The desktop entry: opens the native window on the native platform, with
//! the files named on the command line (paths stay at this edge).

use super::GrainscopeApp;
use super::command::Command;
use super::platform::native::NativePlatform;
use crate::preset::{Preset, resolve};
use std::io::Write;
use std::path::PathBuf;

/// Key under which earlier versions kept the session in eframe's storage
/// (read once when no session file exists yet).
const SESSION_KEY: &str = "grainscope-session";

/// Environment variable naming the session file (default: `session.ron` in
/// the platform's data folder for grainscope).
pub const SESSION_ENV: &str = "GRAINSCOPE_SESSION";

/// Where the session is kept.
pub fn session_path() -> Option<PathBuf> {
    match std::env::var_os(SESSION_ENV) {
        Some(p) if !p.is_empty() => Some(PathBuf::from(p)),
        _ => eframe::storage_dir("grainscope").map(|d| d.join("session.ron")),
    }
}

/// What a file or name given to the window stands for.
pub enum Opened {
    /// A scene's state.
    Preset(Box<Preset>),
    /// A lecture.
    Deck(crate::deck::LoadedDeck),
}

/// Resolves a name as the window opens it: a preset (file, shipped name or
/// exported figure), else a deck (file or shipped name).
pub fn open_named(name: &str) -> Result<Opened, String> {
    match resolve(name) {
        Ok(p) => Ok(Opened::Preset(Box::new(p))),
        Err(preset_error) => match crate::deck::resolve(name) {
            Ok(d) => Ok(Opened::Deck(d)),
            Err(crate::deck::DeckError::Read { .. }) | Err(crate::deck::DeckError::Syntax { .. }) => {
                Err(format!("preset not loaded: {preset_error}"))
            }
            Err(deck_error) => Err(format!("deck not loaded: {deck_error}")),
        },
    }
}

/// Opens the explorer window with `files`: presets (files or shipped
/// names), figures exported by grainscope (their embedded state) or a deck
/// (presented at once). A file that cannot be loaded does not stop the
/// window: it opens with the restored session and shows why.
pub fn run(files: Vec<String>) -> anyhow::Result<()> {
    let initial: Vec<Result<Opened, String>> = files
        .iter()
        .map(|f| {
            open_named(f).map_err(|message| {
                let _ = writeln!(std::io::stderr(), "error: {message}");
                message
            })
        })
        .collect();
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1440.0, 920.0])
            .with_title("grainscope")
            .with_drag_and_drop(true),
        ..Default::default()
    };
    eframe::run_native(
        "grainscope",
        options,
        Box::new(move |cc| {
            let platform = NativePlatform::new(session_path());
            let mut app = GrainscopeApp::new(cc.egui_ctx.clone(), Box::new(platform));
            let found = app.restore_session();
            // A session kept by an earlier version in eframe's storage.
            if !found
                && app.state.notices.is_empty()
                && let Some(old) = cc.storage.and_then(|s| eframe::get_value::<crate::session::Session>(s, SESSION_KEY))
            {
                app.state.session = old.repaired();
            }
            for (opened, name) in initial.into_iter().zip(&files) {
                match opened {
                    Ok(Opened::Preset(p)) => app.apply(Command::ApplyPreset(p, name.clone())),
                    Ok(Opened::Deck(d)) => app.apply(Command::Present(Box::new(d), 0)),
                    Err(message) => app.state.notify(message),
                }
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| anyhow::anyhow!("cannot open the window: {e}"))
}
