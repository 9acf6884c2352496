//! The commands of presenting a deck and of building one in the editor.

use super::command::DeckEdit;
use super::opening;
use super::state::{AppState, Classroom, Effect, Presenter, Then};
use crate::deck::{LoadedDeck, Slide};
use crate::scene::SCENES;
use std::path::Path;

impl AppState {
    /// Starts presenting `deck` at slide `at` (0-based): the lecture look,
    /// the slide's state applied.
    pub fn present(&mut self, deck: LoadedDeck, at: usize) {
        let (lecture_before, explorer_before) = match self.presenter.take() {
            Some(p) => (p.lecture_before, p.explorer_before),
            None => (self.session.lecture, (self.session.scene.clone(), self.session.params.clone())),
        };
        let n = deck.deck.slides.len();
        self.presenter = Some(Presenter {
            deck,
            index: 0,
            notes: false,
            notes_window: false,
            lecture_before,
            explorer_before,
            panel: None,
            elapsed: 0.0,
            countdown: None,
        });
        self.session.lecture = true;
        self.go_to_slide(at.min(n.saturating_sub(1)));
    }

    /// Shows slide `i` as the deck defines it (its scene and parameters).
    pub(super) fn go_to_slide(&mut self, i: usize) {
        let Some(p) = &mut self.presenter else { return };
        let Some(params) = p.deck.params.get(i).cloned() else { return };
        p.index = i;
        p.panel = p.deck.deck.slides[i].enlarge.clone();
        // Ink belongs to the slide it was drawn on.
        self.classroom.strokes.clear();
        let title = p.deck.deck.slides[i].title.clone();
        let id = params.info().id;
        self.session.params.insert(id.to_string(), params);
        if let Some(k) = SCENES.iter().position(|s| s.id == id) {
            self.open_scene(k);
        }
        self.playback.playing = false;
        self.status = format!("slide {}: {title}", i + 1);
        self.error = None;
    }

    /// Leaves presenter mode: back to the scene, parameters and lecture
    /// mode the user had before the deck.
    pub(super) fn stop_presenting(&mut self) {
        if let Some(p) = self.presenter.take() {
            self.session.lecture = p.lecture_before;
            self.shown = Some((p.deck, p.index));
            let (scene, params) = p.explorer_before;
            self.session.params = params;
            if let Some(k) = SCENES.iter().position(|s| s.id == scene) {
                self.open_scene(k);
            }
            self.status = "left the deck: back to the scene as it was".into();
        }
    }

    /// A clicker's F5 (`resume` false) or Shift+F5 (true): presents the deck
    /// being shown from its first slide, or the deck last presented from its
    /// first slide or the slide it was left on, or else the deck being built.
    pub(super) fn start_show(&mut self, resume: bool) {
        if self.presenter.is_some() {
            if !resume {
                self.go_to_slide(0);
            }
            return;
        }
        if let Some((deck, at)) = self.shown.take() {
            self.present(deck, if resume { at } else { 0 });
        } else if !self.deck_editor.deck.slides.is_empty() {
            let base = Path::new(&self.deck_editor.path).parent().map(Path::to_path_buf);
            match opening::resolve_all(&self.deck_editor.deck, base.as_deref()) {
                Ok(deck) => self.present(deck, 0),
                Err(e) => self.error = Some(e),
            }
        } else {
            self.status = "no deck to present yet: open one (Open…) or build one (Deck)".into();
        }
    }

    /// Moves `by` slides (stays at the ends).
    /// Adds a digit to the slide number being typed (the last three kept; a
    /// digit after a pause starts a new number).
    pub(super) fn type_digit(&mut self, digit: char) {
        let now = self.presenter.as_ref().map_or(0.0, |p| p.elapsed);
        let tools = &mut self.classroom;
        if now - tools.typed_at > Classroom::DIGIT_PAUSE {
            tools.typed.clear();
        }
        tools.typed_at = now;
        let typed = &mut tools.typed;
        typed.push(digit);
        if typed.len() > 3 {
            typed.remove(0);
        }
    }

    /// Goes to the slide whose number was typed, or says there is none.
    pub(super) fn go_to_typed(&mut self) {
        let typed = std::mem::take(&mut self.classroom.typed);
        let Some(n) = self.presenter.as_ref().map(|p| p.deck.deck.slides.len()) else { return };
        match typed.parse::<usize>() {
            Ok(k) if (1..=n).contains(&k) => self.go_to_slide(k - 1),
            Ok(k) => self.status = format!("no slide {k}: the deck has slides 1 to {n}"),
            Err(_) => self.status = "type a slide's number, then Enter".into(),
        }
    }

    pub(super) fn step_slide(&mut self, by: isize) {
        let Some(p) = &self.presenter else { return };
        let n = p.deck.deck.slides.len() as isize;
        let next = (p.index as isize + by).clamp(0, n - 1) as usize;
        if next != p.index {
            self.go_to_slide(next);
        }
    }

    pub(super) fn edit_deck(&mut self, edit: DeckEdit, fx: &mut Vec<Effect>) {
        let editor = &mut self.deck_editor;
        match edit {
            DeckEdit::Show(open) => editor.open = open,
            DeckEdit::Replace(deck) => editor.deck = *deck,
            DeckEdit::Swap(a, b) if a.max(b) < editor.deck.slides.len() => editor.deck.slides.swap(a, b),
            DeckEdit::Remove(i) if i < editor.deck.slides.len() => {
                editor.deck.slides.remove(i);
            }
            DeckEdit::Swap(..) | DeckEdit::Remove(_) => {}
            DeckEdit::AddCurrent => {
                let params = self.params().clone();
                let title = params.info().title.to_string();
                self.deck_editor.deck.slides.push(Slide { title, scene: Some(params), ..Slide::default() });
                self.status = format!("added slide {}", self.deck_editor.deck.slides.len());
            }
            DeckEdit::Present(i) => {
                let base = Path::new(&editor.path).parent().map(Path::to_path_buf);
                match opening::resolve_all(&editor.deck, base.as_deref()) {
                    Ok(deck) => self.present(deck, i),
                    Err(e) => self.error = Some(e),
                }
            }
            DeckEdit::Save => match editor.deck.to_ron() {
                Ok(text) => fx.push(Effect::Write {
                    name: editor.path.clone(),
                    bytes: text.into_bytes(),
                    done: "saved deck to",
                    failed: "deck not saved",
                }),
                Err(e) => self.error = Some(format!("deck not saved: {e}")),
            },
            DeckEdit::OpenFile => fx.push(Effect::Read(editor.path.clone(), Then::EditDeck)),
            DeckEdit::Shipped(file) => match crate::deck::resolve(file) {
                Ok(d) => self.deck_editor.deck = d.deck,
                Err(e) => self.error = Some(e.to_string()),
            },
        }
    }
}
