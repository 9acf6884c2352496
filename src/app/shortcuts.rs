//! Keyboard shortcuts: one table that the window dispatches from, the help
//! overlay lists, tooltips and the command palette quote ([`hint`]), and a
//! test checks for clashes. What each action does is written once, with the
//! action ([`Action::text`]).

use egui::{Key, Modifiers};

/// Where a shortcut applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Everywhere.
    Anywhere,
    /// Exploring scenes (not presenting a deck).
    Explorer,
    /// Presenting a deck.
    Presenter,
}

impl Mode {
    /// Whether shortcuts of the two modes can be active at the same time.
    pub fn overlaps(self, other: Mode) -> bool {
        self == Mode::Anywhere || other == Mode::Anywhere || self == other
    }

    /// Heading in the help overlay.
    pub fn heading(self) -> &'static str {
        match self {
            Mode::Anywhere => "Everywhere",
            Mode::Explorer => "Exploring scenes",
            Mode::Presenter => "Presenting a deck",
        }
    }
}

pub use super::command::Action;

/// A key with the modifiers it needs (none when both are false).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Chord {
    /// The key.
    pub key: Key,
    /// Ctrl (⌘ on macOS).
    pub command: bool,
    /// Shift.
    pub shift: bool,
}

const fn key(key: Key) -> Chord {
    Chord { key, command: false, shift: false }
}

const fn command(key: Key) -> Chord {
    Chord { key, command: true, shift: false }
}

const fn shift(key: Key) -> Chord {
    Chord { key, command: false, shift: true }
}

const fn command_shift(key: Key) -> Chord {
    Chord { key, command: true, shift: true }
}

impl Chord {
    /// The modifiers egui must see.
    pub fn modifiers(self) -> Modifiers {
        let mut m = Modifiers::NONE;
        if self.command {
            m = m.plus(Modifiers::COMMAND);
        }
        if self.shift {
            m = m.plus(Modifiers::SHIFT);
        }
        m
    }

    /// As written in the help overlay, e.g. "Ctrl+Shift+Z".
    pub fn text(self) -> String {
        let name = match self.key {
            Key::ArrowRight => "→".to_string(),
            Key::ArrowLeft => "←".to_string(),
            Key::ArrowUp => "↑".to_string(),
            Key::ArrowDown => "↓".to_string(),
            Key::Questionmark => "?".to_string(),
            Key::Comma => ",".to_string(),
            Key::Period => ".".to_string(),
            Key::OpenBracket => "[".to_string(),
            Key::CloseBracket => "]".to_string(),
            other => other.name().to_string(),
        };
        format!("{}{}{name}", if self.command { "Ctrl+" } else { "" }, if self.shift { "Shift+" } else { "" })
    }
}

/// One shortcut: its keys, what it does and where.
#[derive(Debug, Clone, Copy)]
pub struct Shortcut {
    /// Keys that trigger it (any of them).
    pub keys: &'static [Chord],
    /// What it does.
    pub action: Action,
    /// Where it applies.
    pub mode: Mode,
}

/// Every shortcut of the window.
pub const SHORTCUTS: &[Shortcut] = &[
    Shortcut { keys: &[key(Key::F2)], action: Action::Palette, mode: Mode::Anywhere },
    // A clicker's "start the show" keys; the web page keeps them from the browser.
    Shortcut { keys: &[key(Key::F5)], action: Action::StartShow, mode: Mode::Anywhere },
    Shortcut { keys: &[shift(Key::F5)], action: Action::ResumeShow, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::Questionmark), key(Key::H)], action: Action::Help, mode: Mode::Anywhere },
    Shortcut { keys: &[command(Key::Z)], action: Action::Undo, mode: Mode::Anywhere },
    Shortcut { keys: &[command_shift(Key::Z), command(Key::Y)], action: Action::Redo, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::P)], action: Action::PlayPause, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::CloseBracket)], action: Action::StepForward, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::OpenBracket)], action: Action::StepBack, mode: Mode::Anywhere },
    // Presentation clickers send B or "." for a blank screen.
    Shortcut { keys: &[key(Key::B), key(Key::Period)], action: Action::Blank, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::O)], action: Action::Pointer, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::I)], action: Action::Ink, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::U)], action: Action::UndoInk, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::C)], action: Action::ClearInk, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::Home)], action: Action::Rewind, mode: Mode::Explorer },
    Shortcut { keys: &[key(Key::Space)], action: Action::PlayPause, mode: Mode::Explorer },
    Shortcut { keys: &[key(Key::PageDown)], action: Action::NextScene, mode: Mode::Explorer },
    Shortcut { keys: &[key(Key::PageUp)], action: Action::PreviousScene, mode: Mode::Explorer },
    Shortcut { keys: &[key(Key::L)], action: Action::ToggleLecture, mode: Mode::Explorer },
    Shortcut { keys: &[key(Key::Escape)], action: Action::Leave, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::Q)], action: Action::CopyLink, mode: Mode::Anywhere },
    Shortcut { keys: &[key(Key::R)], action: Action::ResetScene, mode: Mode::Explorer },
    Shortcut { keys: &[key(Key::M)], action: Action::Sensitivity, mode: Mode::Explorer },
    Shortcut { keys: &[key(Key::E)], action: Action::Export, mode: Mode::Anywhere },
    Shortcut {
        keys: &[key(Key::ArrowRight), key(Key::PageDown), key(Key::Space), key(Key::ArrowDown)],
        action: Action::NextSlide,
        mode: Mode::Presenter,
    },
    Shortcut {
        keys: &[key(Key::ArrowLeft), key(Key::PageUp), key(Key::Backspace), key(Key::ArrowUp)],
        action: Action::PreviousSlide,
        mode: Mode::Presenter,
    },
    Shortcut { keys: &[key(Key::Home)], action: Action::FirstSlide, mode: Mode::Presenter },
    Shortcut { keys: &[key(Key::End)], action: Action::LastSlide, mode: Mode::Presenter },
    Shortcut {
        keys: &[
            key(Key::Num1),
            key(Key::Num2),
            key(Key::Num3),
            key(Key::Num4),
            key(Key::Num5),
            key(Key::Num6),
            key(Key::Num7),
            key(Key::Num8),
            key(Key::Num9),
        ],
        action: Action::Slide(0),
        mode: Mode::Presenter,
    },
    Shortcut { keys: &[key(Key::Num0)], action: Action::Zero, mode: Mode::Presenter },
    Shortcut { keys: &[key(Key::Enter)], action: Action::GoToTyped, mode: Mode::Presenter },
    Shortcut { keys: &[key(Key::T)], action: Action::RestartTimer, mode: Mode::Presenter },
    Shortcut { keys: &[key(Key::N)], action: Action::ToggleNotes, mode: Mode::Presenter },
    Shortcut { keys: &[key(Key::W)], action: Action::NotesWindow, mode: Mode::Presenter },
    Shortcut { keys: &[key(Key::R)], action: Action::ResetSlide, mode: Mode::Presenter },
];

/// The keys of `action` where `mode` applies, as the help writes them
/// ("Ctrl+Z", "→, Page Down"); empty if it has none.
pub fn keys(action: Action, mode: Mode) -> String {
    SHORTCUTS
        .iter()
        .filter(|s| s.action == action && s.mode.overlaps(mode))
        .map(|s| match s.action {
            Action::Slide(_) => "1 … 9".to_string(),
            _ => s.keys.iter().map(|k| k.text()).collect::<Vec<_>>().join(", "),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// A tooltip: what `action` does, with its keys where `mode` applies
/// ("undo the last parameter change (Ctrl+Z)").
pub fn hint(action: Action, mode: Mode) -> String {
    let does = action.text().does;
    match keys(action, mode) {
        k if k.is_empty() => does.to_string(),
        k => format!("{does} ({k})"),
    }
}

/// The actions whose keys were pressed this frame in `mode` (each key
/// press consumed, so no widget sees it too).
pub fn pressed(ctx: &egui::Context, mode: Mode) -> Vec<Action> {
    let mut out = Vec::new();
    ctx.input_mut(|input| {
        for s in SHORTCUTS.iter().filter(|s| s.mode.overlaps(mode)) {
            for (k, chord) in s.keys.iter().enumerate() {
                // Exact modifiers: Ctrl+Z must not also fire Ctrl+Shift+Z.
                let wanted = chord.modifiers();
                // A key typed with Shift on most layouts ("?") ignores Shift.
                let typed_with_shift = chord.key == Key::Questionmark;
                let hit = input.events.iter().any(|e| {
                    matches!(e, egui::Event::Key { key, pressed: true, modifiers, .. }
                        if *key == chord.key
                            && (modifiers.matches_exact(wanted)
                                || (typed_with_shift && modifiers.matches_logically(wanted))))
                });
                if hit {
                    input.consume_key(wanted, chord.key);
                    out.push(match s.action {
                        Action::Slide(_) => Action::Slide(k),
                        a => a,
                    });
                }
            }
        }
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No key does two things where both could apply.
    #[test]
    fn no_two_shortcuts_clash() {
        for (i, a) in SHORTCUTS.iter().enumerate() {
            for (j, b) in SHORTCUTS.iter().enumerate() {
                for (m, ka) in a.keys.iter().enumerate() {
                    for (n, kb) in b.keys.iter().enumerate() {
                        if (i, m) == (j, n) {
                            continue;
                        }
                        let same_action = a.action == b.action;
                        assert!(
                            ka != kb || !a.mode.overlaps(b.mode) || same_action,
                            "{} does '{}' ({:?}) and '{}' ({:?})",
                            ka.text(),
                            a.action.text().name,
                            a.mode,
                            b.action.text().name,
                            b.mode
                        );
                    }
                }
            }
        }
    }

    /// Every key works in a browser tab too: none is one the browser keeps
    /// for itself (reload, close, address bar, tabs, find, print, help…),
    /// except a clicker's F5 and Shift+F5, which the web page takes from the
    /// browser before it reloads.
    #[test]
    fn no_key_is_one_a_browser_keeps() {
        let function = [Key::F1, Key::F3, Key::F5, Key::F6, Key::F7, Key::F11, Key::F12];
        let with_ctrl = [
            Key::D,
            Key::E,
            Key::F,
            Key::G,
            Key::H,
            Key::J,
            Key::K,
            Key::L,
            Key::N,
            Key::O,
            Key::P,
            Key::Q,
            Key::R,
            Key::S,
            Key::T,
            Key::U,
            Key::W,
            Key::Tab,
            Key::Num1,
            Key::Num2,
            Key::Num3,
            Key::Num4,
            Key::Num5,
            Key::Num6,
            Key::Num7,
            Key::Num8,
            Key::Num9,
            Key::Plus,
            Key::Minus,
            Key::Num0,
        ];
        let page = include_str!("../../web/index.html");
        for s in SHORTCUTS {
            for k in s.keys {
                if k.key == Key::F5 && !k.command && matches!(s.action, Action::StartShow | Action::ResumeShow) {
                    assert!(
                        page.contains("\"F5\"") && page.contains("preventDefault"),
                        "the page keeps F5 from the browser"
                    );
                    continue;
                }
                let kept = function.contains(&k.key) || (k.command && with_ctrl.contains(&k.key));
                assert!(!kept, "{} ('{}') is a key a browser keeps", k.text(), s.action.text().name);
            }
        }
    }

    /// The help overlay names every key once per mode.
    #[test]
    fn every_key_has_a_readable_name() {
        for s in SHORTCUTS {
            for k in s.keys {
                assert!(!k.text().is_empty() && !k.text().contains("Key"), "{:?}", k);
            }
        }
        assert_eq!(command_shift(Key::Z).text(), "Ctrl+Shift+Z");
    }

    /// Every action has a name and a meaning, the palette offers each once,
    /// and a tooltip quotes the keys of the table.
    #[test]
    fn every_action_describes_itself() {
        for (i, a) in Action::ALL.iter().enumerate() {
            let t = a.text();
            assert!(!t.name.is_empty() && !t.does.is_empty(), "{a:?}");
            assert!(!Action::ALL[..i].contains(a), "{a:?} listed twice");
        }
        for s in SHORTCUTS {
            // Digits and Enter make a slide's number: not commands of their own.
            if !matches!(s.action, Action::Slide(_) | Action::Zero | Action::GoToTyped) {
                assert!(Action::ALL.contains(&s.action), "{:?} has keys but is not in the palette", s.action);
            }
        }
        assert_eq!(hint(Action::Undo, Mode::Explorer), "undo the last parameter change (Ctrl+Z)");
        assert_eq!(hint(Action::PlayPause, Mode::Presenter), format!("{} (P)", Action::PlayPause.text().does));
        assert_eq!(keys(Action::PlayPause, Mode::Explorer), "P, Space");
        assert_eq!(keys(Action::Pin, Mode::Explorer), "");
    }

    /// No panel types a key into its text: every key a tooltip names comes
    /// from the table ([`hint`], [`keys`]), so that none can drift.
    #[test]
    fn no_panel_writes_a_key_by_hand() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/app/ui");
        // A key as a hint writes it: "(P)", "(Space, P)".
        let mut names: Vec<String> = SHORTCUTS
            .iter()
            .flat_map(|s| s.keys.iter().map(|k| k.text()))
            .flat_map(|k| [format!("({k})"), format!("({k},"), format!(", {k})")])
            .collect();
        names.extend(["(Esc".into(), "(Ctrl+".into(), "toggles".into()]);
        let files = std::fs::read_dir(&dir).expect("src/app/ui");
        for f in files.flatten().filter(|f| f.path().extension().is_some_and(|e| e == "rs")) {
            let text = std::fs::read_to_string(f.path()).expect("a panel");
            // The string literal each tooltip starts with (on its line or the next).
            for (at, _) in text.match_indices("on_hover_text(") {
                let rest = text[at + "on_hover_text(".len()..].trim_start();
                let rest = rest.strip_prefix("format!(").unwrap_or(rest).trim_start();
                let Some(literal) = rest.strip_prefix('"').and_then(|r| r.split('"').next()) else { continue };
                for n in &names {
                    assert!(!literal.contains(n.as_str()), "{}: a key typed by hand: {literal}", f.path().display());
                }
            }
        }
    }
}
