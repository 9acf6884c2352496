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

    /// The study over whole ranges a scene starts with: Morris's elementary
    /// effects (r = 20 trajectories on a 4-level grid) over every numeric
    /// parameter that changes a result (those that move the chosen result
    /// where "what matters" has an answer for it here), each over its
    /// documented range (uniform in the logarithm where its control is
    /// logarithmic).
    pub(super) fn default_whole_range(&self) -> crate::sensitivity::WholeRange {
        use crate::global_sensitivity::{Design, Factor, Method};
        use crate::scene::schema::SpecKind;
        let moving: Option<Vec<String>> =
            self.matters.result.as_ref().filter(|(at, _)| at == self.params()).map(|(_, m)| {
                m.rows.iter().filter(|r| r.elasticity.is_some_and(|e| e.abs() >= 5e-4)).map(|r| r.key.clone()).collect()
            });
        let factors = self
            .params()
            .specs()
            .iter()
            .filter(|s| !s.style_only && !s.figure_only)
            .filter(|s| moving.as_ref().is_none_or(|keys| keys.iter().any(|k| k == s.key)))
            .filter_map(|s| match s.kind {
                SpecKind::Number { min, max, log, .. } if min < max && min.is_finite() && max.is_finite() => {
                    Some(Factor { key: s.key.to_string(), log: log && min > 0.0, from: min, to: max })
                }
                _ => None,
            })
            .collect();
        crate::sensitivity::WholeRange {
            design: Design { method: Method::Morris { trajectories: 20, levels: 4 }, factors, seed: 2015 },
            log_output: false,
        }
    }

    /// New settings of the study over whole ranges: its runs so far stand
    /// for other settings, and are dropped.
    pub(super) fn set_whole_range(&mut self, study: crate::sensitivity::WholeRange) {
        let w = &mut self.matters.whole;
        if w.study.as_ref() != Some(&study) {
            *w = super::state::Whole { study: Some(study), ..Default::default() };
        }
    }

    /// Starts the study over whole ranges for the view's result at the
    /// current parameters: its runs go in shares of a tenth (whole Morris
    /// trajectories or Sobol' base samples), each share's values extending
    /// the indices.
    pub(super) fn run_whole_range(&mut self, fx: &mut Vec<Effect>) {
        let Some(study) = self.matters.whole.study.clone() else {
            self.error = Some("the study has no settings yet".into());
            return;
        };
        let output = self.matters.output.clone();
        // The unit labels the runs' column; a view reopened from a file names
        // its result before the scene has computed it.
        let unit = match self.output() {
            Some(o) => match o.scalars.iter().find(|s| s.key == output) {
                Some(s) => s.unit,
                None => {
                    self.error = Some(format!("choose a result of this scene to study (not '{output}')"));
                    return;
                }
            },
            None if !output.is_empty() => "",
            None => {
                self.error = Some("the scene reports no result yet to study".into());
                return;
            }
        };
        if study.design.factors.is_empty() {
            self.error = Some("choose at least one parameter to vary".into());
            return;
        }
        if let Err(e) = study.design.unit_points() {
            self.error = Some(format!("study not started: {e}"));
            return;
        }
        let base = self.params().clone();
        self.matters.whole = super::state::Whole {
            study: Some(study.clone()),
            at: Some((base.clone(), output.clone(), unit.to_string())),
            running: true,
            ..Default::default()
        };
        self.status = format!("{} runs of {} over whole ranges", study.design.runs(), output);
        fx.push(Effect::Submit(whole_range_share(base, study.design, output, unit.to_string(), 0)));
    }

    /// Draws the chosen result against parameter `x` over its range, or over
    /// `x` and `y` as a map (`y` empty: a curve).
    pub(super) fn draw_sensitivity(&mut self, x: String, y: String, fx: &mut Vec<Effect>) {
        self.matters.curve = None;
        self.matters.figure = true;
        self.matters.whole_tab = false;
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
        let whole = self.whole_range_analysis(&preset);
        if self.matters.result.is_none() && self.matters.curve.is_none() && whole.is_none() {
            self.error = Some("nothing to export yet: the view has no result".into());
            return;
        }
        if let Some((_, m)) = &self.matters.result {
            let table = crate::sensitivity::matters_csv(m, &self.matters.output, self.matters.factor);
            let files = vec![(format!("{prefix}what-matters.csv"), stamp.csv(table.as_bytes()))];
            fx.push(Effect::WriteAll { folder: self.session.export_dir.clone(), files, what: "sensitivity table" });
        }
        let mut figures = Vec::new();
        if let Some(a) = &whole {
            let table = crate::sweep_files::indices_csv(a);
            let files = vec![(format!("{prefix}whole-ranges.csv"), stamp.csv(table.as_bytes()))];
            fx.push(Effect::WriteAll { folder: self.session.export_dir.clone(), files, what: "sensitivity indices" });
            figures.push(crate::sweep_files::analysis_figure(a));
        }
        // The curve or map renders on the export lane, as every figure export does.
        if let Some((_, fig)) = &self.matters.curve {
            figures.push(fig.clone());
        }
        if !figures.is_empty() {
            fx.push(Effect::Submit(Job::Export { figures, stamp: Box::new(stamp), prefix }));
        }
    }

    /// The finished study over whole ranges as `grainscope sensitivity`
    /// analyses it (for its table and figure); None while runs are to come.
    fn whole_range_analysis(&self, preset: &Preset) -> Option<crate::sweep_files::Analysis> {
        let w = &self.matters.whole;
        let (study, (_, output, unit), a) = (w.study.as_ref()?, w.at.as_ref()?, w.answer.as_ref()?);
        if w.running || a.runs < a.total {
            return None;
        }
        let program = crate::provenance::program();
        Some(crate::sweep_files::Analysis {
            computed_by: program.clone(),
            program,
            preset: preset.title.clone(),
            output: if study.log_output { format!("ln {output}") } else { output.clone() },
            unit: if study.log_output { String::new() } else { unit.clone() },
            log_output: study.log_output,
            design: study.design.clone(),
            tie: Vec::new(),
            runs: a.runs,
            undefined: a.undefined,
            bounded: a.bounded,
            morris: a.morris.clone(),
            sobol: a.sobol.clone(),
        })
    }
}

/// The job of the share of a study's runs from run `from` on: a tenth of
/// the runs, rounded up to whole Morris trajectories or Sobol' base samples.
pub(super) fn whole_range_share(
    base: crate::scene::SceneParams,
    design: crate::global_sensitivity::Design,
    output: String,
    unit: String,
    from: usize,
) -> Job {
    use crate::global_sensitivity::{Method, sobol_runs_per_sample};
    let d = design.factors.len();
    let block = match design.method {
        Method::Morris { .. } => d + 1,
        Method::Sobol { second_order, .. } => sobol_runs_per_sample(d, second_order),
        Method::Given { .. } => 1,
    };
    let total = design.runs();
    let share = total.div_ceil(10).div_ceil(block).max(2) * block;
    Job::WholeRange {
        base: Box::new(base),
        design: Box::new(design),
        output,
        unit,
        from,
        to: (from + share).min(total),
    }
}
