//! The commands of the sensitivity tools: a family of curves over one
//! parameter, "what matters" for a result, and a result against one
//! parameter over its range. Each becomes a job on the sweep lane.

use super::jobs::Job;
use super::state::{AppState, Effect};
use crate::preset::Preset;
use crate::scene::SCENES;
use crate::sweep::{Plan, Spacing, Vary};

impl AppState {
    /// Draws a family of the open scene's curves over the family tool's values.
    pub(super) fn draw_family(&mut self, fx: &mut Vec<Effect>) {
        let base = self.params().clone();
        let (from, to, n) = (self.sweep.from, self.sweep.to, self.sweep.steps.clamp(2, 12));
        // Log-spaced where the control is logarithmic (and the range positive).
        let log = base
            .spec(&self.sweep.key)
            .is_some_and(|s| matches!(s.kind, crate::scene::schema::SpecKind::Number { log: true, .. }));
        let spacing = if log && from > 0.0 && to > 0.0 { Spacing::Log } else { Spacing::Lin };
        let vary = Vary::range(&self.sweep.key, spacing, from, to, n);
        // Every value is checked before starting, so a bad range is reported at once.
        match Plan::new(base, vec![vary]) {
            Ok(plan) => {
                fx.push(Effect::Submit(Job::Sweep { plan: Box::new(plan), first_color: self.session.pins.len() + 1 }))
            }
            Err(e) => self.error = Some(format!("sweep not started: {e}")),
        }
    }

    /// Opens the sensitivity view and computes what matters for the chosen
    /// result (the first result of the scene when none is chosen; a heavy
    /// scene's coarse parameters first).
    pub(super) fn what_matters(&mut self, fx: &mut Vec<Effect>) {
        // A result of another scene (or none) gives way to the scene's first.
        let first = self.output().and_then(|o| o.scalars.first()).map(|s| s.key.to_string());
        let foreign = self.output().is_some_and(|o| !o.scalars.iter().any(|s| s.key == self.matters.output));
        if self.matters.output.is_empty() || foreign {
            match first {
                Some(k) => self.matters.output = k,
                None => {
                    self.error = Some("the scene reports no result yet to ask what matters for".into());
                    return;
                }
            }
        }
        self.matters.open = true;
        self.matters.figure = false;
        let coarse = SCENES[self.index()].heavy && self.params().coarse().is_some();
        fx.push(Effect::Submit(Job::WhatMatters {
            base: Box::new(self.params().clone()),
            output: self.matters.output.clone(),
            factor: self.matters.factor,
            coarse,
        }));
    }

    /// Draws the chosen result against parameter `x` over its range, or over
    /// `x` and `y` as a map (`y` empty: a curve).
    pub(super) fn draw_sensitivity(&mut self, x: String, y: String, fx: &mut Vec<Effect>) {
        self.matters.curve = None;
        self.matters.figure = true;
        self.matters.x = x.clone();
        self.matters.y = y.clone();
        fx.push(Effect::Submit(Job::Curve {
            base: Box::new(self.params().clone()),
            output: self.matters.output.clone(),
            key: x,
            second: (!y.is_empty()).then_some(y),
        }));
    }

    /// Writes the sensitivity view to the export folder: its curve or map
    /// as PNG, SVG and CSV and the "what matters" table as CSV, each file
    /// carrying the scene's state and the view, so that opening any of them
    /// reopens the view.
    pub(super) fn export_sensitivity(&mut self, fx: &mut Vec<Effect>) {
        let preset = Preset { sensitivity: Some(self.matters.view()), ..self.current_preset() };
        let stamp = match crate::provenance::Stamp::of(&preset) {
            Ok(s) => s,
            Err(e) => {
                self.error = Some(format!("export failed: {e}"));
                return;
            }
        };
        let prefix = format!("{}-{}-", self.params().info().id, self.matters.output);
        if self.matters.result.is_none() && self.matters.curve.is_none() {
            self.error = Some("nothing to export yet: the view has no result".into());
            return;
        }
        if let Some((_, m)) = &self.matters.result {
            let table = crate::sensitivity::matters_csv(m, &self.matters.output, self.matters.factor);
            let files = vec![(format!("{prefix}what-matters.csv"), stamp.csv(table.as_bytes()))];
            fx.push(Effect::WriteAll { folder: self.session.export_dir.clone(), files, what: "sensitivity table" });
        }
        // The curve or map renders on the export lane, as every figure export does.
        if let Some((_, fig)) = &self.matters.curve {
            let figures = vec![fig.clone()];
            fx.push(Effect::Submit(Job::Export { figures, stamp: Box::new(stamp), prefix }));
        }
    }
}
