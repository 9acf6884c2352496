//! The panels: one file each, every one a function of the state that draws
//! it and says what the user did as [`Command`]s. Nothing here changes the
//! state; [`crate::app::GrainscopeApp`] applies the commands after each panel.

pub mod classroom;
pub mod controls;
pub mod deck_editor;
pub mod figures;
pub mod help;
pub mod inspector;
pub mod link;
pub mod look;
pub mod matters;
pub mod monomer_card;
pub mod palette;
pub mod plot;
pub mod presenter;
pub mod scene_panel;
pub mod sketch;
pub mod status;
pub mod top_bar;
pub mod transport;

use super::command::Command;
use super::state::AppState;
use crate::scene::Scalar;
use crate::scene::monomer::Card;

/// How the open scene's computation stands, as the panels show it.
#[derive(Debug, Clone, Copy, Default)]
pub struct Work {
    /// Whether a job computes the open scene (or a sweep).
    pub running: bool,
    /// Whether the open scene's result is older than its parameters.
    pub stale: bool,
    /// Fraction done of the running job.
    pub progress: f64,
    /// Whether the running job is paused.
    pub paused: bool,
    /// Whether the running job can pause.
    pub pausable: bool,
}

/// Whether a window of this size is a phone's screen (portrait or
/// landscape): narrower than 640 points or lower than 480. The figures then
/// take the whole width and the parameters open in a drawer over them.
pub fn compact(size: egui::Vec2) -> bool {
    size.x < 640.0 || size.y < 480.0
}

/// What the panels remember between frames that is not state: layout of
/// the last frame and values kept so as not to compute them every frame.
#[derive(Default)]
pub struct Memo {
    /// Where the plots were drawn in the last frame (screen points).
    pub plot_rects: Vec<egui::Rect>,
    /// Where every plot was drawn in the last frame, by figure id.
    pub plot_frames: Vec<(String, plot::Placed)>,
    /// Shipped presets for the menu: (chapter, title, file, text), parsed once.
    pub shipped_menu: Option<Vec<(crate::scene::Chapter, String, &'static str, &'static str)>>,
    /// The monomer card last shown and its derived values.
    pub card: Option<(Card, Vec<Scalar>)>,
    /// The (lecture, light, compact) look last applied to the context.
    pub look_applied: Option<(bool, bool, bool)>,
    /// Whether this frame lays the window out for a phone's screen
    /// ([`compact`]): one column, the parameters in a drawer.
    pub compact: bool,
    /// Whether the bundled font was given to the context.
    pub fonts_installed: bool,
    /// The stroke of ink being drawn (points as fractions of the window).
    pub ink_stroke: Vec<[f32; 2]>,
    /// The input clock at the last frame, s (the presenter's timer counts from it).
    pub clock: Option<f64>,
}

/// What a panel draws from and reports to.
pub struct Cx<'a> {
    /// The state drawn.
    pub state: &'a AppState,
    /// Layout and values kept between frames.
    pub memo: &'a mut Memo,
    /// The user's actions this frame.
    pub out: &'a mut Vec<Command>,
    /// The computation's progress.
    pub work: Work,
}

impl Cx<'_> {
    /// Whether the lecture look applies: lecture mode, except on a phone's
    /// screen, which keeps its own layout (lecture mode is the projector's).
    pub fn lecture(&self) -> bool {
        self.state.session.lecture && !self.memo.compact
    }

    /// Reports a user action.
    pub fn send(&mut self, command: Command) {
        self.out.push(command);
    }
}
