//! The commands of the sensitivity tools: a family of curves over one
//! parameter, "what matters" for a result, and a result against one
//! parameter over its range. Each becomes a job on the sweep lane.

use super::jobs::Job;
use super::state::{AppState, Effect};
use crate::scene::{ControlKind, SCENES};
use crate::sweep::{Plan, Spacing, Vary};

impl AppState {
    /// Draws a family of the open scene's curves over the family tool's values.
    pub(super) fn draw_family(&mut self, fx: &mut Vec<Effect>) {
        let base = self.params().clone();
        let (from, to, n) = (self.sweep.from, self.sweep.to, self.sweep.steps.clamp(2, 12));
        // Log-spaced where the control is logarithmic (and the range positive).
        let log = {
            let mut p = base.clone();
            let controls = p.controls();
            controls.iter().any(|c| c.key == self.sweep.key && matches!(c.kind, ControlKind::Number { log: true, .. }))
        };
        let spacing = if log && from > 0.0 && to > 0.0 { Spacing::Log } else { Spacing::Lin };
        let vary = Vary { key: self.sweep.key.clone(), spacing, from, to, n };
        // Every value is checked before starting, so a bad range is reported at once.
        match Plan::new(base, vec![vary]) {
            Ok(plan) => {
                fx.push(Effect::Submit(Job::Sweep { plan: Box::new(plan), first_color: self.session.pins.len() + 1 }))
            }
            Err(e) => self.error = Some(format!("sweep not started: {e}")),
        }
    }

    /// Computes what matters for the chosen result (a heavy scene's coarse
    /// parameters first), and shows the view.
    pub(super) fn what_matters(&mut self, fx: &mut Vec<Effect>) {
        if self.matters.output.is_empty() {
            self.error = Some("choose the result whose dependence to show".into());
            return;
        }
        self.matters.open = true;
        let coarse = SCENES[self.index()].heavy && self.params().coarse().is_some();
        fx.push(Effect::Submit(Job::WhatMatters {
            base: Box::new(self.params().clone()),
            output: self.matters.output.clone(),
            factor: self.matters.factor,
            coarse,
        }));
    }

    /// Draws the chosen result against parameter `key` over its range.
    pub(super) fn matters_curve(&mut self, key: String, fx: &mut Vec<Effect>) {
        self.matters.curve = None;
        fx.push(Effect::Submit(Job::Curve {
            base: Box::new(self.params().clone()),
            output: self.matters.output.clone(),
            key,
        }));
    }
}
