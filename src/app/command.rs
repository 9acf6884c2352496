//! Every user action as one value. Menus, buttons, keys, the presenter's
//! clicker, dropped files, dialog answers and deck steps all become a
//! [`Command`], applied in one place ([`super::state::AppState::apply`]).
//! The keyboard table ([`super::shortcuts::SHORTCUTS`]) maps keys to the
//! commands of [`Action`], so the help lists exactly what exists.

use super::platform::{FileKind, Picked};
use crate::deck::{Deck, LoadedDeck};
use crate::figure::{Figure, View};
use crate::preset::Preset;
use crate::scene::SceneParams;
use std::collections::HashMap;

/// What a key (or its button) asks for: the commands the keyboard reaches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    /// Show or hide the list of shortcuts.
    Help,
    /// Offer a link that opens the open scene in its present state.
    CopyLink,
    /// Undo the last parameter change.
    Undo,
    /// Redo what was undone.
    Redo,
    /// Play or pause the scene's history.
    PlayPause,
    /// Move the time cursor one step forward.
    StepForward,
    /// Move the time cursor one step back.
    StepBack,
    /// Put the time cursor at the start of the history.
    Rewind,
    /// Next scene in the navigator.
    NextScene,
    /// Previous scene in the navigator.
    PreviousScene,
    /// Lecture mode on or off.
    ToggleLecture,
    /// Leave lecture mode, presenter mode or the help overlay.
    Leave,
    /// Reset the open scene's parameters to their defaults.
    ResetScene,
    /// Export the open scene's figures (PNG, SVG, CSV) to the export folder.
    Export,
    /// Next slide.
    NextSlide,
    /// Previous slide.
    PreviousSlide,
    /// First slide.
    FirstSlide,
    /// Last slide.
    LastSlide,
    /// Slide n (1–9).
    Slide(usize),
    /// Speaker notes on or off.
    ToggleNotes,
    /// Speaker notes in a window of their own on or off.
    NotesWindow,
    /// Restore the slide as the deck defines it.
    ResetSlide,
    /// Open the sensitivity view: what matters for the chosen result.
    Sensitivity,
    /// Open or close the command palette.
    Palette,
    /// Keep the open scene's model curves for comparison.
    Pin,
    /// Remove the open scene's pins.
    ClearPins,
    /// Write the played history as a movie into the export folder.
    Movie,
    /// Reset every scene's parameters.
    ResetAll,
    /// Open a preset, deck, figure or measurements file.
    OpenFile,
    /// Save the open scene as a preset.
    SavePreset,
    /// Light theme on or off.
    ToggleTheme,
    /// The deck editor on or off.
    DeckEditor,
    /// Blank the screen, or bring it back.
    Blank,
    /// The pointer (a large spot that follows the mouse) on or off.
    Pointer,
    /// Drawing ink on the figures on or off.
    Ink,
    /// Remove the last stroke of ink.
    UndoInk,
    /// Remove all ink.
    ClearInk,
    /// Exported figures carry the ink drawn on them, or not.
    InkInExports,
    /// The digit 0 of a slide number (Enter goes there).
    Zero,
    /// Go to the slide whose number was typed.
    GoToTyped,
    /// The presenter's timer from 0:00 (when the talk really starts).
    RestartTimer,
    /// Start the show: the deck from its first slide (as a clicker's F5 asks).
    StartShow,
    /// Resume the show: the deck from the slide last shown (a clicker's Shift+F5).
    ResumeShow,
}

/// An action's name and what it does: the one text every button, tooltip,
/// the help overlay and the command palette show for it.
#[derive(Debug, Clone, Copy)]
pub struct ActionText {
    /// Name, as a button or the palette shows it.
    pub name: &'static str,
    /// What it does, as a tooltip or the help shows it (its keys are added from the shortcut table).
    pub does: &'static str,
}

impl Action {
    /// Every action the palette offers, in its order (the slides by number aside).
    pub const ALL: &'static [Action] = &[
        Action::Palette,
        Action::Help,
        Action::Undo,
        Action::Redo,
        Action::ResetScene,
        Action::ResetAll,
        Action::OpenFile,
        Action::SavePreset,
        Action::Export,
        Action::CopyLink,
        Action::Pin,
        Action::ClearPins,
        Action::Sensitivity,
        Action::PlayPause,
        Action::StepForward,
        Action::StepBack,
        Action::Rewind,
        Action::Movie,
        Action::NextScene,
        Action::PreviousScene,
        Action::ToggleLecture,
        Action::ToggleTheme,
        Action::DeckEditor,
        Action::Leave,
        Action::NextSlide,
        Action::PreviousSlide,
        Action::FirstSlide,
        Action::LastSlide,
        Action::ToggleNotes,
        Action::NotesWindow,
        Action::ResetSlide,
        Action::RestartTimer,
        Action::StartShow,
        Action::ResumeShow,
        Action::Blank,
        Action::Pointer,
        Action::Ink,
        Action::UndoInk,
        Action::ClearInk,
        Action::InkInExports,
    ];

    /// The action's name and what it does.
    pub fn text(self) -> ActionText {
        let (name, does) = match self {
            Action::Help => ("Keys", "show or hide the list of keyboard shortcuts"),
            Action::CopyLink => ("Link", "a link and QR code that open this state in the browser version"),
            Action::Undo => ("Undo", "undo the last parameter change"),
            Action::Redo => ("Redo", "redo what was undone"),
            Action::PlayPause => ("Play or pause", "play or pause the history (collision, rocking, runs)"),
            Action::StepForward => ("Step forward", "step the time cursor forward"),
            Action::StepBack => ("Step back", "step the time cursor back"),
            Action::Rewind => ("To the start", "time cursor to the start"),
            Action::NextScene => ("Next scene", "the next scene of the list"),
            Action::PreviousScene => ("Previous scene", "the previous scene of the list"),
            Action::ToggleLecture => ("Lecture mode", "plots fill the screen in a light high-contrast theme"),
            Action::Leave => ("Leave", "close this list or the link, leave presenter or lecture mode"),
            Action::ResetScene => ("Reset to defaults", "this scene's parameters to their defaults"),
            Action::Export => ("Export", "export the scene's figures (PNG, SVG, CSV) to the export folder"),
            Action::NextSlide => ("Next slide", "the next slide"),
            Action::PreviousSlide => ("Previous slide", "the previous slide"),
            Action::FirstSlide => ("First slide", "the first slide"),
            Action::LastSlide => ("Last slide", "the last slide"),
            Action::Slide(_) => ("Slide n", "slide 1–9"),
            Action::ToggleNotes => ("Notes", "speaker notes under the plots on or off"),
            Action::NotesWindow => ("Notes window", "speaker notes in a window of their own, for a second screen"),
            Action::ResetSlide => ("Reset slide", "the slide as the deck defines it"),
            Action::Sensitivity => ("Sensitivity", "what matters for the chosen result, its curve or map"),
            Action::Palette => ("Commands", "find and run any command by name"),
            Action::Pin => ("Pin", "keep the scene's curves to compare with the next change"),
            Action::ClearPins => ("Clear pins", "remove the scene's pinned curves"),
            Action::Movie => (
                "Movie",
                "write 48 frames of the history (PNG) and an animated PNG into the export folder (in a browser: one animated PNG of every figure)",
            ),
            Action::ResetAll => ("Reset all", "every scene's parameters to their defaults (Undo brings them back)"),
            Action::OpenFile => ("Open…", "open a preset, deck, exported figure or measurements file"),
            Action::SavePreset => ("Save preset…", "save this scene's state as a preset file"),
            Action::ToggleTheme => ("Light theme", "light or dark theme"),
            Action::DeckEditor => ("Deck", "build a lecture from the window's states"),
            Action::Blank => ("Blank", "blank the screen; any key or a click brings it back"),
            Action::Pointer => ("Pointer", "a large spot that follows the mouse"),
            Action::Ink => ("Ink", "draw on the figures with the mouse, a pen or a finger (cleared on the next slide)"),
            Action::UndoInk => ("Undo ink", "remove the last stroke of ink"),
            Action::ClearInk => ("Clear ink", "remove all ink"),
            Action::InkInExports => ("Ink in exports", "exported figures (PNG, SVG) carry the ink drawn on them"),
            Action::Zero => ("0", "the digit 0 of a slide number"),
            Action::GoToTyped => ("Go to slide", "the slide whose number was typed (its digits, then Enter)"),
            Action::RestartTimer => ("Restart timer", "the presenter's timer from 0:00"),
            Action::StartShow => (
                "Start show",
                "present the deck from its first slide (the deck last presented, or the one being built)",
            ),
            Action::ResumeShow => ("Resume show", "present the deck again from the slide last shown"),
        };
        ActionText { name, does }
    }

    /// Whether the action applies while presenting a deck (true), while
    /// exploring (false), or in both (None).
    pub fn presenting(self) -> Option<bool> {
        match self {
            Action::NextSlide
            | Action::PreviousSlide
            | Action::FirstSlide
            | Action::LastSlide
            | Action::Slide(_)
            | Action::ToggleNotes
            | Action::NotesWindow
            | Action::ResetSlide
            | Action::Zero
            | Action::GoToTyped
            | Action::RestartTimer => Some(true),
            Action::NextScene
            | Action::PreviousScene
            | Action::ResetScene
            | Action::ResetAll
            | Action::Pin
            | Action::ClearPins
            | Action::Sensitivity
            | Action::DeckEditor
            | Action::OpenFile
            | Action::SavePreset => Some(false),
            _ => None,
        }
    }
}

/// A text field of the window whose content is kept in the session.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    /// The preset path for Load and Save.
    PresetPath,
    /// The measurements path for Load data.
    DataPath,
    /// The folder quick exports go to.
    ExportDir,
    /// The deck editor's file.
    DeckPath,
}

/// A change to the deck being built.
#[derive(Debug, Clone, PartialEq)]
pub enum DeckEdit {
    /// Show or hide the editor.
    Show(bool),
    /// The deck's title and slides as edited in place (titles, notes).
    Replace(Box<Deck>),
    /// Swap two slides.
    Swap(usize, usize),
    /// Remove a slide.
    Remove(usize),
    /// Append the window's current state as a slide.
    AddCurrent,
    /// Present the deck from a slide.
    Present(usize),
    /// Save it to the deck file.
    Save,
    /// Open the deck file into the editor.
    OpenFile,
    /// Open a shipped deck into the editor.
    Shipped(&'static str),
}

/// Every user action.
#[derive(Debug, Clone)]
pub enum Command {
    /// A keyboard action (or the button that does the same).
    Act(Action),
    /// Open scene `i` of [`crate::scene::SCENES`].
    OpenScene(usize),
    /// The open scene's parameters as edited in its controls.
    SetParams(Box<SceneParams>),
    /// A value typed into control `key` was refused (why).
    Refuse {
        /// The control.
        key: String,
        /// The message shown under it.
        message: String,
    },
    /// Control `key` took a valid value: its refusal notice goes.
    Accept(String),
    /// Open `params`'s scene with those parameters (from a card or link).
    OpenParams(Box<SceneParams>, String),
    /// Switch to a preset (shipped or read), naming where it came from.
    ApplyPreset(Box<Preset>, String),
    /// Present a deck from slide `at`.
    Present(Box<LoadedDeck>, usize),
    /// Go to slide `i` of the deck presented.
    GoToSlide(usize),
    /// Leave presenter mode.
    StopPresenting,
    /// Open a file given as bytes (dropped, picked, or read from a typed path).
    OpenBytes(Picked),
    /// Open the file at a path the user typed (or dropped, where drops are paths).
    OpenPath(String),
    /// Import measurements from the data path.
    LoadDataPath,
    /// Ask the platform for a file to open.
    Pick(FileKind),
    /// Save the open scene as a preset at the preset path.
    SavePresetPath,
    /// Save the open scene as a preset where the user chooses.
    SavePresetAs,
    /// Clear the open scene's measurements.
    ClearData,
    /// Export one figure as drawn into the export folder (png, svg or csv).
    ExportFigure(Box<Figure>, &'static str),
    /// Export one figure as drawn where the user chooses.
    SaveFigureAs(Box<Figure>),
    /// Write the played history as a movie into the export folder.
    Movie,
    /// Keep the open scene's model curves for comparison.
    Pin,
    /// Remove the open scene's pins.
    ClearPins,
    /// The family tool's settings.
    SetSweep(Sweep),
    /// Draw a family over the sweep's values.
    DrawFamily,
    /// The scalar and factor of the "what matters" view.
    SetMatters(String, f64),
    /// Compute what matters for the open scene's scalar, and show it.
    WhatMatters,
    /// Close the "what matters" view.
    CloseMatters,
    /// Show the open scene's figure with this identifier alone, or every
    /// panel at once ([`crate::session::ALL_PANELS`]); remembered per scene.
    ShowPanel(String),
    /// Show the view's curve or map (true) or its "what matters" chart.
    MattersFigure(bool),
    /// Show the view's study over whole ranges (true) or leave it.
    MattersWhole(bool),
    /// The settings of the study over whole ranges.
    SetWholeRange(Box<crate::sensitivity::WholeRange>),
    /// Run the study over whole ranges for the view's result at the
    /// current parameters: the indices fill in as runs finish.
    RunWholeRange,
    /// Draw the "what matters" result against parameter `x` over its range,
    /// or over `x` and `y` as a map (`y` empty: a curve).
    DrawSensitivity(String, String),
    /// Export the sensitivity view (its curve or map as PNG, SVG and CSV,
    /// and the "what matters" table as CSV), each file carrying the view.
    ExportSensitivity,
    /// Reset every scene's parameters.
    ResetAll,
    /// Light theme on or off.
    SetLight(bool),
    /// Lecture mode on or off.
    SetLecture(bool),
    /// The parameter panel over the plots in lecture mode on or off.
    SetLectureParams(bool),
    /// On a phone's screen: the parameters drawer open (over the figures) or closed.
    SetDrawer(bool),
    /// The shortcut list on or off.
    SetHelp(bool),
    /// The command palette open with this filter text, or closed (None).
    SetPalette(Option<String>),
    /// Closes the Link card.
    HideLink,
    /// A text field's new content.
    SetText(Field, String),
    /// The time cursor at a fraction of the history.
    SetTime(f64),
    /// Playback paused (by a step, a scrub or a button).
    StopPlaying,
    /// Playback speed.
    SetSpeed(f64),
    /// Playback loops or not.
    SetLooping(bool),
    /// Advance a playing history by a frame's seconds.
    Tick(f64),
    /// Keep every plot's range (the views) or follow the data (none).
    LockAxes(Option<HashMap<String, View>>),
    /// Inspect a point of a figure: (figure id, point in axis units, where on the screen).
    Inspect(String, [f64; 2], [f32; 2]),
    /// Close the inspection card.
    CloseInspection,
    /// Dismiss notice `i`.
    Dismiss(usize),
    /// The deck editor.
    Deck(DeckEdit),
    /// Close the speaker notes' own window.
    CloseNotesWindow,
    /// A finished stroke of ink.
    InkStroke(InkStroke),
    /// Whether exported figures carry the ink drawn on them.
    SetInkInExports(bool),
    /// Seconds passed (the presenter's timer).
    Clock(f64),
    /// The length of the talk for the presenter's countdown, s (None: none).
    SetCountdown(Option<f64>),
    /// Pause or resume the running computation.
    PauseJob(bool),
    /// Cancel the running computation.
    CancelJob,
}

/// Settings of the family tool: one curve set per value of `key`.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// The parameter swept.
    pub key: String,
    /// First value (SI).
    pub from: f64,
    /// Last value (SI).
    pub to: f64,
    /// Number of values (2–12).
    pub steps: usize,
}

impl Default for Sweep {
    fn default() -> Self {
        Sweep { key: "velocity".into(), from: 1.0, to: 10.0, steps: 5 }
    }
}

/// A stroke of ink.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct InkStroke {
    /// Its points as fractions of the window's width and height (so that it
    /// stays on the figure when the window is resized).
    pub points: Vec<[f32; 2]>,
    /// The same stroke in the axis units of each figure it was drawn on
    /// (figure id, points), for exports.
    pub on: Vec<(String, Vec<[f64; 2]>)>,
}
