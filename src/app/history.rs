//! Undo and redo of parameter changes. The window shows the history each
//! frame in which no pointer button is held, so a whole slider drag is one
//! step; moving the time cursor (by hand or by playing) is not a change.

use crate::scene::SceneParams;
use std::collections::HashMap;

/// Steps kept for undo.
pub const DEPTH: usize = 500;

/// One step: the states of the scenes it changed, by scene id.
pub type Step = Vec<(String, SceneParams)>;

/// Undo and redo stacks over every scene's parameters.
#[derive(Debug, Default)]
pub struct History {
    undo: Vec<Step>,
    redo: Vec<Step>,
    /// The last state of each scene seen at rest.
    baseline: HashMap<String, SceneParams>,
}

/// Whether two parameter sets differ other than in their time cursor.
fn differ(a: &SceneParams, b: &SceneParams) -> bool {
    let (mut a, mut b) = (a.clone(), b.clone());
    for p in [&mut a, &mut b] {
        if let Some(c) = p.cursor_mut() {
            *c = 0.0;
        }
    }
    a != b
}

impl History {
    /// Notes the state of scene `id` at rest: a change since the last state
    /// seen becomes one undo step (and clears the redo stack).
    pub fn observe(&mut self, id: &str, now: &SceneParams) {
        match self.baseline.get(id) {
            // Most frames change nothing: equal sets need no closer look.
            Some(before) if before != now && differ(before, now) => {
                let step = vec![(id.to_string(), before.clone())];
                self.push(step);
                self.redo.clear();
                self.baseline.insert(id.to_string(), now.clone());
            }
            Some(_) => {}
            None => {
                self.baseline.insert(id.to_string(), now.clone());
            }
        }
    }

    /// Records a change of several scenes at once (e.g. "reset all"): the
    /// states before it, and the states after it as the new baselines.
    pub fn record(&mut self, before: Step, after: &[(String, SceneParams)]) {
        if before.is_empty() {
            return;
        }
        self.push(before);
        self.redo.clear();
        for (id, p) in after {
            self.baseline.insert(id.clone(), p.clone());
        }
    }

    fn push(&mut self, step: Step) {
        self.undo.push(step);
        if self.undo.len() > DEPTH {
            self.undo.remove(0);
        }
    }

    /// The states to restore to undo the last step; `current` gives each
    /// scene's state now (kept for redo).
    pub fn undo(&mut self, current: impl Fn(&str) -> SceneParams) -> Option<Step> {
        let step = self.undo.pop()?;
        self.redo.push(step.iter().map(|(id, _)| (id.clone(), current(id))).collect());
        self.rebase(&step);
        Some(step)
    }

    /// The states to restore to redo the last undone step.
    pub fn redo(&mut self, current: impl Fn(&str) -> SceneParams) -> Option<Step> {
        let step = self.redo.pop()?;
        self.undo.push(step.iter().map(|(id, _)| (id.clone(), current(id))).collect());
        self.rebase(&step);
        Some(step)
    }

    fn rebase(&mut self, step: &Step) {
        for (id, p) in step {
            self.baseline.insert(id.clone(), p.clone());
        }
    }

    /// Steps that can be undone and redone.
    pub fn depth(&self) -> (usize, usize) {
        (self.undo.len(), self.redo.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn with_velocity(v: f64) -> SceneParams {
        let mut p = SceneParams::default_for("hysteresis").expect("scene");
        p.set("velocity", &v.to_string()).expect("valid");
        p
    }

    /// Changes become steps that undo and redo in order; a cursor move is
    /// not a step; a new change after an undo clears the redo stack.
    #[test]
    fn changes_undo_and_redo_in_order() {
        let mut h = History::default();
        let mut now = with_velocity(8.0);
        h.observe("hysteresis", &now);
        for v in [4.0, 2.0, 1.0] {
            now = with_velocity(v);
            h.observe("hysteresis", &now);
        }
        let mut moved = now.clone();
        *moved.cursor_mut().expect("cursor") = 0.9;
        h.observe("hysteresis", &moved);
        assert_eq!(h.depth(), (3, 0));
        let current = |_: &str| moved.clone();
        let back = h.undo(current).expect("a step");
        assert_eq!(back[0].1, with_velocity(2.0));
        assert_eq!(h.depth(), (2, 1));
        let again = h.redo(|_| with_velocity(2.0)).expect("redo");
        assert_eq!(again[0].1, moved);
        h.undo(|_| moved.clone());
        h.observe("hysteresis", &with_velocity(3.0));
        assert_eq!(h.depth(), (3, 0), "a new change clears redo");
    }

    /// At least a hundred steps are kept, and the oldest go first.
    #[test]
    fn the_history_is_deep_but_bounded() {
        let mut h = History::default();
        for k in 0..=DEPTH + 20 {
            h.observe("hysteresis", &with_velocity(1.0 + k as f64 * 0.01));
        }
        assert_eq!(h.depth().0, DEPTH);
        const { assert!(DEPTH >= 100) };
    }
}
