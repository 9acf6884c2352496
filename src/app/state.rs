//! What the window shows and would keep, without the toolkit: the session
//! (scene, parameters, pins, look), the results on display, messages,
//! history, playback, the deck presented or built, the monomer link and the
//! inspected point. Commands change it ([`AppState::apply`], in
//! `apply.rs`); panels read it. It imports no egui and is tested directly.

use super::command::{InkStroke, Sweep};
use super::history::History;
use super::jobs::Job;
use super::platform::FileKind;
use super::playback::Playback;
use crate::deck::{Deck, LoadedDeck, Slide};
use crate::figure::{Figure, View};
use crate::preset::Preset;
use crate::scene::inspect::Inspection;
use crate::scene::monomer::Card;
use crate::scene::{self, SCENES, SceneError, SceneOutput, SceneParams};
use crate::session::Session;
use std::collections::{HashMap, HashSet};
use std::sync::Arc;

/// A deck being presented.
#[derive(Debug, Clone)]
pub struct Presenter {
    /// The deck, every slide resolved.
    pub deck: LoadedDeck,
    /// The slide shown (0-based).
    pub index: usize,
    /// Whether the speaker notes are shown under the plots.
    pub notes: bool,
    /// Whether the speaker notes are shown in a window of their own, which
    /// the lecturer keeps on a second screen.
    pub notes_window: bool,
    /// Whether lecture mode was on before presenting (restored on leaving).
    pub lecture_before: bool,
    /// The scene and every scene's parameters before presenting: leaving
    /// the deck returns to them.
    pub explorer_before: (String, std::collections::BTreeMap<String, SceneParams>),
    /// The figure shown alone on this slide (the slide's enlarged figure
    /// when it names one, or the one picked), or every panel
    /// ([`crate::session::ALL_PANELS`]); None: as the screen allows.
    pub panel: Option<String>,
    /// Seconds since the deck started.
    pub elapsed: f64,
    /// The length of the talk for a countdown, s (None: no countdown).
    pub countdown: Option<f64>,
}

impl Presenter {
    /// The slide shown.
    pub fn slide(&self) -> &Slide {
        &self.deck.deck.slides[self.index]
    }
}

/// The classroom's own tools: a blank screen, a pointer, ink on the
/// figures, and a slide reached by its number.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Classroom {
    /// The screen is blank (B, or "." as clickers send it).
    pub blank: bool,
    /// A large spot follows the mouse.
    pub pointer: bool,
    /// Dragging over the figures draws ink instead of moving them.
    pub ink: bool,
    /// The strokes drawn; cleared on the next slide.
    pub strokes: Vec<InkStroke>,
    /// Exported figures (PNG, SVG) carry the ink drawn on them.
    pub ink_in_exports: bool,
    /// The digits of a slide number typed so far (Enter goes there).
    pub typed: String,
    /// When the last digit was typed (the presenter's clock, s): a digit
    /// typed more than [`Classroom::DIGIT_PAUSE`] later starts a new number.
    pub typed_at: f64,
}

impl Classroom {
    /// The pause after which a digit starts a new slide number, s.
    pub const DIGIT_PAUSE: f64 = 2.0;
}

/// The deck being built in the window.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckEditor {
    /// Whether the editor window is open.
    pub open: bool,
    /// The deck.
    pub deck: Deck,
    /// Path typed for saving and opening.
    pub path: String,
}

impl Default for DeckEditor {
    fn default() -> Self {
        DeckEditor {
            open: false,
            deck: Deck { title: "My lecture".into(), ..Deck::default() },
            path: "presets/decks/my-lecture.ron".into(),
        }
    }
}

/// The monomer shared between scenes: what the card showed last.
#[derive(Debug, Default)]
pub struct MonomerLink {
    /// The open scene and its card when last seen: a change within the
    /// same scene is an edit to share.
    pub seen: Option<(usize, Option<Card>)>,
}

/// A clicked point and its inspection.
#[derive(Debug, Clone)]
pub struct Inspected {
    /// Index of the scene in [`SCENES`].
    pub scene: usize,
    /// The figure clicked.
    pub figure: String,
    /// What the scene said.
    pub inspection: Inspection,
    /// Where the click was on the screen (points): the card keeps clear of it.
    pub at: [f32; 2],
}

/// What to do with a file once its bytes are read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Then {
    /// Open it as the user means it (preset, deck, figure, measurements).
    Open,
    /// Import it as measurements.
    Import,
    /// Open it as a deck in the deck editor.
    EditDeck,
}

/// What applying a command asks of the world outside the state: the
/// platform (files, dialogs) and the job runner.
#[derive(Debug)]
pub enum Effect {
    /// Ask the user for a file to open.
    Pick(FileKind),
    /// Ask the user where to save bytes under a suggested name.
    SaveAs(FileKind, String, Vec<u8>),
    /// Read the file the user named, then use it.
    Read(String, Then),
    /// Write bytes under a name the user gave; the status reports it.
    Write {
        /// The name (a path on the desktop).
        name: String,
        /// The content.
        bytes: Vec<u8>,
        /// What the status says on success, before the name.
        done: &'static str,
        /// What the error says on failure, before the reason.
        failed: &'static str,
    },
    /// Write files into the folder the user named (all or nothing).
    WriteAll {
        /// The folder.
        folder: String,
        /// (name, bytes) of each file.
        files: Vec<(String, Vec<u8>)>,
        /// What they are ("export", "movie").
        what: &'static str,
    },
    /// Start a job.
    Submit(Job),
    /// Cancel the open scene's computation.
    Cancel,
    /// Pause or resume the open scene's computation.
    Pause(bool),
    /// Offer the link whose query is given (see [`crate::links`]).
    ShareLink(String),
}

/// The "what matters" view: which scalar, over which factor, and the last
/// answer (for the scene and parameters it was computed at).
#[derive(Debug, Clone, PartialEq)]
pub struct Matters {
    /// The scalar's key.
    pub output: String,
    /// The factor around each parameter's value.
    pub factor: f64,
    /// Whether the view is shown.
    pub open: bool,
    /// The answer: the parameters it holds for, X there, and each parameter's influence.
    pub result: Option<(SceneParams, crate::sensitivity::Matters)>,
    /// Whether the answer is the coarse first pass of a heavy scene (its
    /// cheaper parameters), with the full one still to come.
    pub coarse: bool,
    /// The result against one parameter over its whole range, or a map
    /// over two (parameters, figure).
    pub curve: Option<(SceneParams, crate::figure::Figure)>,
    /// The parameter of the curve (the map's horizontal axis); empty for none.
    pub x: String,
    /// The map's second parameter; empty for a curve.
    pub y: String,
    /// Whether a file just opened asks for the view: computed on the next frame.
    pub reopen: bool,
    /// Whether the view shows its curve or map (else its chart): one at a
    /// time, so that each gets the window's height.
    pub figure: bool,
    /// Whether the view shows its study over whole ranges (before `figure`).
    pub whole_tab: bool,
    /// The study over whole ranges: its settings, runs and indices.
    pub whole: Whole,
}

/// A study over whole ranges in the sensitivity view: the design, the runs
/// done (in design order) and the indices they give so far.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Whole {
    /// The study's settings (the one run, or being set up).
    pub study: Option<crate::sensitivity::WholeRange>,
    /// The parameters and the result's (key, unit) the runs are for.
    pub at: Option<(SceneParams, String, String)>,
    /// The runs done, in design order.
    pub values: Vec<crate::global_sensitivity::RunValue>,
    /// The indices from the runs done.
    pub answer: Option<crate::global_sensitivity::Answer>,
    /// Whether runs are still to come.
    pub running: bool,
}

impl Default for Matters {
    fn default() -> Self {
        Matters {
            output: String::new(),
            factor: 2.0,
            open: false,
            result: None,
            coarse: false,
            curve: None,
            x: String::new(),
            y: String::new(),
            reopen: false,
            figure: false,
            whole_tab: false,
            whole: Whole::default(),
        }
    }
}

impl Matters {
    /// The view as a file remembers it.
    pub fn view(&self) -> crate::sensitivity::View {
        crate::sensitivity::View {
            output: self.output.clone(),
            factor: self.factor,
            x: self.x.clone(),
            y: self.y.clone(),
            whole: self.whole.study.clone().filter(|_| self.whole.answer.is_some() || self.whole_tab),
        }
    }
}

/// Everything that defines what the user sees.
#[derive(Debug)]
pub struct AppState {
    /// Persisted state: scene, parameters, pins, look and paths.
    pub session: Session,
    /// Default parameters of every scene, in the order of [`SCENES`].
    pub defaults: Vec<SceneParams>,
    /// Where a platform starts a scene from lighter defaults than the
    /// scene's own: what it says about them, in the order of [`SCENES`].
    pub default_notes: Vec<Option<String>>,
    /// The parameters (keys) the lighter defaults of [`AppState::default_notes`]
    /// change, in the order of [`SCENES`].
    pub lighter_keys: Vec<Vec<String>>,
    /// Whether the platform takes typed paths ([`crate::app::platform::Platform::paths`]).
    pub paths: bool,
    /// Every scene's last good result, in the order of [`SCENES`].
    pub outputs: Vec<Option<Arc<SceneOutput>>>,
    /// The status line.
    pub status: String,
    /// The last error, shown instead of the status.
    pub error: Option<String>,
    /// Messages that stay until dismissed.
    pub notices: Vec<String>,
    /// A value typed into a control that was refused: (control key, why).
    pub control_notice: Option<(String, String)>,
    /// The family tool's settings.
    pub sweep: Sweep,
    /// The "what matters" view: its settings and last result.
    pub matters: Matters,
    /// Axes kept fixed while parameters change, by figure id (when locked).
    pub locked: Option<HashMap<String, View>>,
    /// Whether the parameter panel is open over the plots in lecture mode.
    pub lecture_params: bool,
    /// On a phone's screen, whether the parameters drawer covers the figures.
    pub drawer: bool,
    /// Playing the open scene's history.
    pub playback: Playback,
    /// Scenes (by index) whose optional time-cursor marks are shown: those
    /// played or scrubbed.
    pub timeline_shown: HashSet<usize>,
    /// Undo and redo of parameter changes.
    pub history: History,
    /// Whether the list of keyboard shortcuts is shown.
    pub help: bool,
    /// The command palette, while open: the text that filters its actions.
    pub palette: Option<String>,
    /// The link last given to the present state, shown with its QR code.
    pub link: Option<LinkCard>,
    /// The deck being presented.
    pub presenter: Option<Presenter>,
    /// The deck last presented and the slide it was left on, for a clicker's
    /// F5 (start the show) and Shift+F5 (resume it).
    pub shown: Option<(LoadedDeck, usize)>,
    /// The deck being built.
    pub deck_editor: DeckEditor,
    /// Whether a movie is being written.
    pub movie_running: bool,
    /// The monomer shared between scenes.
    pub monomer: MonomerLink,
    /// The point of a figure last clicked, and what the model says there.
    pub inspected: Option<Inspected>,
    /// Whether saving the session failed already (said once).
    pub session_save_failed: bool,
    /// The classroom's tools.
    pub classroom: Classroom,
}

impl Default for AppState {
    fn default() -> Self {
        AppState::new(Session::default())
    }
}

impl AppState {
    /// What the current scene says about the platform's lighter defaults:
    /// their note while the scene runs at them; where a link, a preset or the
    /// user set any of those parameters otherwise, what it runs instead.
    pub fn lighter_note(&self) -> Option<String> {
        let i = self.index();
        let note = self.default_notes[i].as_ref()?;
        let (p, d) = (self.params(), &self.defaults[i]);
        let differing: Vec<String> = self.lighter_keys[i]
            .iter()
            .filter(|k| p.get(k) != d.get(k))
            .filter_map(|k| {
                let (spec, value) = (p.spec(k)?, p.get(k)?);
                Some(format!("{} {}", spec.label, spec.display(&value)))
            })
            .collect();
        Some(if differing.is_empty() {
            note.clone()
        } else {
            format!(
                "Runs as set: {}, not the browser's lighter start (it computes on one thread: a heavier setting can take minutes).",
                differing.join(", ")
            )
        })
    }

    /// The state of a window opening `session`.
    pub fn new(session: Session) -> Self {
        let n = SCENES.len();
        AppState {
            session,
            defaults: SCENES.iter().filter_map(|s| SceneParams::default_for(s.id)).collect(),
            default_notes: vec![None; n],
            lighter_keys: vec![Vec::new(); n],
            paths: true,
            outputs: vec![None; n],
            status: String::new(),
            error: None,
            notices: Vec::new(),
            control_notice: None,
            sweep: Sweep::default(),
            matters: Matters::default(),
            locked: None,
            lecture_params: false,
            drawer: false,
            playback: Playback::default(),
            timeline_shown: HashSet::new(),
            history: History::default(),
            help: false,
            palette: None,
            link: None,
            presenter: None,
            shown: None,
            deck_editor: DeckEditor::default(),
            movie_running: false,
            monomer: MonomerLink::default(),
            inspected: None,
            session_save_failed: false,
            classroom: Classroom::default(),
        }
    }

    /// Index of the open scene in [`SCENES`].
    pub fn index(&self) -> usize {
        self.session.index()
    }

    /// The current scene's parameters.
    pub fn params(&self) -> &SceneParams {
        match self.session.params.get(&self.session.scene) {
            Some(p) => p,
            None => &self.defaults[self.index()],
        }
    }

    /// The current scene's parameters, for editing.
    pub fn params_mut(&mut self) -> &mut SceneParams {
        let i = self.index();
        let default = &self.defaults[i];
        self.session.params.entry(SCENES[i].id.to_string()).or_insert_with(|| default.clone())
    }

    /// The parameters of scene `i` of [`SCENES`].
    pub fn params_of(&self, i: usize) -> &SceneParams {
        self.session.params.get(SCENES[i].id).unwrap_or(&self.defaults[i])
    }

    /// The current scene's last good output.
    pub fn output(&self) -> Option<&SceneOutput> {
        self.outputs[self.index()].as_deref()
    }

    /// The open scene's state as a preset.
    pub fn current_preset(&self) -> Preset {
        let params = self.params().clone();
        Preset { title: params.info().title.to_string(), description: String::new(), scene: params, sensitivity: None }
    }

    /// The open scene's time cursor (fraction of its history), if it has one.
    pub fn time(&self) -> Option<f64> {
        self.params().clone().cursor_mut().map(|c| *c)
    }

    /// The open scene's figures as drawn: with the time cursor's marks when
    /// they are shown.
    pub fn drawn_figures(&self, out: &SceneOutput) -> Vec<Figure> {
        let mut figures = out.figures.clone();
        if let Some(c) = self.shown_cursor(out) {
            c.apply(&mut figures);
        }
        figures
    }

    /// The open scene's time cursor over `out` when its marks are shown.
    pub fn shown_cursor(&self, out: &SceneOutput) -> Option<scene::Cursor> {
        self.params().cursor(out).filter(|c| self.marks_shown(c))
    }

    /// Whether a cursor's marks are drawn: always, or once the open scene's
    /// history was played or scrubbed.
    pub fn marks_shown(&self, cursor: &scene::Cursor) -> bool {
        !cursor.optional || self.timeline_shown.contains(&self.index())
    }

    /// The current inspection, if it belongs to the open scene.
    pub fn inspection(&self) -> Option<&Inspection> {
        self.inspected.as_ref().filter(|i| i.scene == self.index()).map(|i| &i.inspection)
    }

    /// The ring around the inspected point on figure `figure`.
    pub fn inspected_mark(&self, figure: &str) -> Option<scene::Mark> {
        let i = self.inspected.as_ref().filter(|i| i.scene == self.index() && i.figure == figure)?;
        Some(scene::Mark::Point(i.inspection.point, None))
    }

    /// How many scenes share the monomer (have a card and keep no own monomer).
    pub fn scenes_sharing_monomer(&self) -> usize {
        (0..SCENES.len())
            .filter(|&k| self.params_of(k).monomer_card().is_some() && !self.params_of(k).own_monomer())
            .count()
    }

    /// Shows a message that stays until dismissed.
    pub fn notify(&mut self, message: String) {
        if !self.notices.contains(&message) {
            self.notices.push(message);
        }
    }

    /// Takes a scene's result (or its error, keeping the last good result).
    pub fn finish(&mut self, i: usize, result: Result<SceneOutput, SceneError>) {
        match result {
            Ok(o) => {
                self.outputs[i] = Some(Arc::new(o));
                self.error = None;
            }
            Err(e) => self.error = Some(format!("{}: {e} (showing the last good result)", SCENES[i].title)),
        }
    }

    /// Notes the open scene's parameters at rest (no pointer held): a change
    /// since the last rest is one undo step, and a monomer edit is shared.
    pub fn at_rest(&mut self, pointer_down: bool) {
        self.link_monomer();
        if !pointer_down {
            let now = self.params().clone();
            self.history.observe(&self.session.scene, &now);
        }
    }

    /// Shares an edit of the open scene's monomer with every linked scene.
    fn link_monomer(&mut self) {
        let i = self.index();
        let card = self.params().monomer_card();
        let previous = self.monomer.seen.replace((i, card.clone()));
        let (Some(card), false) = (card, self.params().own_monomer()) else { return };
        if let Some((j, Some(before))) = previous
            && j == i
            && before != card
        {
            self.share_monomer(i, &card);
        }
    }

    /// Gives every other scene that shares the monomer the card `card`;
    /// returns how many changed.
    pub fn share_monomer(&mut self, from: usize, card: &Card) -> usize {
        let mut changed = 0;
        for (k, info) in SCENES.iter().enumerate() {
            if k == from {
                continue;
            }
            let mut q = self.params_of(k).clone();
            if q.own_monomer() || q.monomer_card().is_none_or(|c| c == *card) {
                continue;
            }
            if q.set_monomer_card(card) {
                self.session.params.insert(info.id.to_string(), q);
                changed += 1;
            }
        }
        changed
    }
}

/// A link to a state, as the Link card shows it: the address and its QR code.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkCard {
    /// The whole address.
    pub address: String,
    /// The QR code's modules, row by row, `true` for dark (none when the
    /// address is too long for one).
    pub modules: Option<QrModules>,
}

/// The modules of a QR code.
#[derive(Debug, Clone, PartialEq)]
pub struct QrModules {
    /// Modules per side.
    pub width: usize,
    /// `width × width` modules, row by row, `true` for dark.
    pub dark: Vec<bool>,
}

impl LinkCard {
    /// The card of `address`, with error correction M (a code on a projected
    /// slide survives a poor camera), or L when the address needs the room.
    pub fn new(address: String) -> LinkCard {
        let code = [qrcode::EcLevel::M, qrcode::EcLevel::L]
            .into_iter()
            .find_map(|level| qrcode::QrCode::with_error_correction_level(address.as_bytes(), level).ok());
        let modules = code.map(|code| QrModules {
            width: code.width(),
            dark: code.to_colors().into_iter().map(|c| c == qrcode::Color::Dark).collect(),
        });
        LinkCard { address, modules }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether the 7×7 finder pattern (dark ring, light ring, dark 3×3 core)
    /// sits with its corner at (row, col).
    fn finder_at(m: &QrModules, row: usize, col: usize) -> bool {
        (0..7).all(|r| {
            (0..7).all(|c| {
                let ring = r.min(c).min(6 - r).min(6 - c);
                m.dark[(row + r) * m.width + col + c] == (ring != 1)
            })
        })
    }

    #[test]
    fn a_link_card_holds_a_standard_qr_code_or_says_it_has_none() {
        let card = LinkCard::new("https://example.org/grainscope/?scene=hysteresis&velocity=0.015".into());
        let m = card.modules.expect("a short address has a code");
        assert_eq!(m.dark.len(), m.width * m.width);
        assert_eq!((m.width - 17) % 4, 0, "width 17 + 4 × version");
        let far = m.width - 7;
        assert!(finder_at(&m, 0, 0) && finder_at(&m, 0, far) && finder_at(&m, far, 0));
        assert!(!finder_at(&m, far, far), "three finders, not four");
        // Longer addresses need larger codes; past the largest, none.
        let longer = LinkCard::new(format!("https://example.org/?state={}", "x".repeat(1500)));
        assert!(longer.modules.expect("1.5 kB fits").width > m.width);
        assert_eq!(LinkCard::new("x".repeat(3000)).modules, None);
    }
}
