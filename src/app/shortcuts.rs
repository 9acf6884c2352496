//! Keyboard shortcuts: one table that the window dispatches from, the help
//! overlay lists, and a test checks for clashes.

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
    /// Description in the help overlay.
    pub text: &'static str,
}

/// Every shortcut of the window.
pub const SHORTCUTS: &[Shortcut] = &[
    Shortcut {
        keys: &[key(Key::Questionmark), key(Key::H)],
        action: Action::Help,
        mode: Mode::Anywhere,
        text: "show or hide this list",
    },
    Shortcut {
        keys: &[command(Key::Z)],
        action: Action::Undo,
        mode: Mode::Anywhere,
        text: "undo the last parameter change",
    },
    Shortcut {
        keys: &[command_shift(Key::Z), command(Key::Y)],
        action: Action::Redo,
        mode: Mode::Anywhere,
        text: "redo",
    },
    Shortcut {
        keys: &[key(Key::P)],
        action: Action::PlayPause,
        mode: Mode::Anywhere,
        text: "play or pause the history (collision, rocking, runs)",
    },
    Shortcut {
        keys: &[key(Key::Period)],
        action: Action::StepForward,
        mode: Mode::Anywhere,
        text: "step the time cursor forward",
    },
    Shortcut {
        keys: &[key(Key::Comma)],
        action: Action::StepBack,
        mode: Mode::Anywhere,
        text: "step the time cursor back",
    },
    Shortcut {
        keys: &[key(Key::Home)],
        action: Action::Rewind,
        mode: Mode::Explorer,
        text: "time cursor to the start",
    },
    Shortcut {
        keys: &[key(Key::Space)],
        action: Action::PlayPause,
        mode: Mode::Explorer,
        text: "play or pause the history",
    },
    Shortcut { keys: &[key(Key::PageDown)], action: Action::NextScene, mode: Mode::Explorer, text: "next scene" },
    Shortcut { keys: &[key(Key::PageUp)], action: Action::PreviousScene, mode: Mode::Explorer, text: "previous scene" },
    Shortcut {
        keys: &[key(Key::L)],
        action: Action::ToggleLecture,
        mode: Mode::Explorer,
        text: "lecture mode on or off",
    },
    Shortcut {
        keys: &[key(Key::Escape)],
        action: Action::Leave,
        mode: Mode::Anywhere,
        text: "close this list or the link, leave presenter or lecture mode",
    },
    Shortcut {
        keys: &[key(Key::Q)],
        action: Action::CopyLink,
        mode: Mode::Anywhere,
        text: "a link and QR code that open this state (browser version)",
    },
    Shortcut {
        keys: &[key(Key::R)],
        action: Action::ResetScene,
        mode: Mode::Explorer,
        text: "reset the scene's parameters",
    },
    Shortcut {
        keys: &[key(Key::M)],
        action: Action::Sensitivity,
        mode: Mode::Explorer,
        text: "sensitivity: what matters for the chosen result, its curve or map",
    },
    Shortcut {
        keys: &[key(Key::E)],
        action: Action::Export,
        mode: Mode::Anywhere,
        text: "export the scene's figures (PNG, SVG, CSV) to the export folder",
    },
    Shortcut {
        keys: &[key(Key::ArrowRight), key(Key::PageDown), key(Key::Space), key(Key::ArrowDown)],
        action: Action::NextSlide,
        mode: Mode::Presenter,
        text: "next slide",
    },
    Shortcut {
        keys: &[key(Key::ArrowLeft), key(Key::PageUp), key(Key::Backspace), key(Key::ArrowUp)],
        action: Action::PreviousSlide,
        mode: Mode::Presenter,
        text: "previous slide",
    },
    Shortcut { keys: &[key(Key::Home)], action: Action::FirstSlide, mode: Mode::Presenter, text: "first slide" },
    Shortcut { keys: &[key(Key::End)], action: Action::LastSlide, mode: Mode::Presenter, text: "last slide" },
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
        text: "slide 1–9",
    },
    Shortcut {
        keys: &[key(Key::N)],
        action: Action::ToggleNotes,
        mode: Mode::Presenter,
        text: "speaker notes on or off",
    },
    Shortcut {
        keys: &[key(Key::W)],
        action: Action::NotesWindow,
        mode: Mode::Presenter,
        text: "speaker notes in a window of their own (for a second screen)",
    },
    Shortcut {
        keys: &[key(Key::R)],
        action: Action::ResetSlide,
        mode: Mode::Presenter,
        text: "reset the slide as the deck defines it",
    },
];

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
                            a.text,
                            a.mode,
                            b.text,
                            b.mode
                        );
                    }
                }
            }
        }
    }

    /// Every key works in a browser tab too: none is one the browser keeps
    /// for itself (reload, close, address bar, tabs, find, print, help…).
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
        for s in SHORTCUTS {
            for k in s.keys {
                let kept = function.contains(&k.key) || (k.command && with_ctrl.contains(&k.key));
                assert!(!kept, "{} ('{}') is a key a browser keeps", k.text(), s.text);
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
}
