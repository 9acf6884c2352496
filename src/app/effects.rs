//! Carrying out what commands ask of the world (files, dialogs, jobs) and
//! taking back what the world answers (finished jobs, dialog answers,
//! dropped files).

use super::GrainscopeApp;
use super::command::Command;
use super::jobs::{Done, Job, Lane};
use super::opening;
use super::platform::{Answer, FileKind, Picked};
use super::state::{Effect, Then};
use std::sync::Arc;

impl GrainscopeApp {
    pub(super) fn carry_out(&mut self, effect: Effect) {
        let state = &mut self.state;
        match effect {
            Effect::Pick(kind) => self.platform.pick_file(kind),
            Effect::SaveAs(kind, name, bytes) => self.platform.save_file(kind, &name, bytes),
            Effect::Read(name, then) => match (self.platform.read(&name), opening::shipped(&name)) {
                (Ok(bytes), _) => state.open_bytes(Picked { name, bytes }, then),
                (Err(_), Some(shipped)) if then == Then::Open => state.open_bytes(shipped, then),
                (Err(e), _) => {
                    state.error = Some(match then {
                        Then::Open => format!("preset not loaded: {e}; nothing changed"),
                        Then::Import => format!("{e} (nothing imported)"),
                        Then::EditDeck => format!("deck not opened, nothing changed: {e}"),
                    })
                }
            },
            Effect::Write { name, bytes, done, failed } => match self.platform.write(&name, &bytes) {
                Ok(name) => state.status = format!("{done} {name}"),
                Err(e) => state.error = Some(format!("{failed}: {e}")),
            },
            Effect::WriteAll { folder, files, what } => self.write_all(&folder, &files, what),
            Effect::Submit(job) => {
                let lane = job.lane();
                // A new job on a lane replaces the one before: so does its folder.
                self.computing.folders.retain(|(l, _)| *l != lane);
                match &job {
                    Job::Export { .. } => self.computing.folders.push((lane, state.session.export_dir.clone())),
                    Job::Movie { .. } => self.computing.folders.push((lane, state.movie_folder())),
                    Job::Sweep { .. }
                    | Job::WhatMatters { .. }
                    | Job::Curve { .. }
                    | Job::WholeRange { .. }
                    | Job::Scene { .. } => {}
                }
                self.runner.submit(job);
            }
            Effect::Cancel => {
                self.runner.cancel(Lane::Sweep);
                self.runner.cancel(Lane::Curve);
                self.runner.cancel(Lane::Study);
                state.matters.whole.running = false;
                self.runner.cancel(Lane::Compute);
                self.computing.stale = false;
                self.computing.requested[state.index()] = None;
            }
            Effect::Pause(paused) => self.runner.set_paused(Lane::Compute, paused),
            Effect::ShareLink(query) => match self.platform.share_link(&query) {
                Ok(shared) => {
                    self.state.status = shared.said;
                    self.state.link = Some(crate::app::state::LinkCard::new(shared.address));
                }
                Err(why) => self.state.status = why,
            },
        }
    }

    /// A share of a study's runs came back: if they are the runs of the
    /// study shown (the same parameters, result and design), they extend its
    /// values and its indices, and the next share starts.
    fn whole_range_done(
        &mut self,
        base: crate::scene::SceneParams,
        design: crate::global_sensitivity::Design,
        from: usize,
        values: Vec<crate::global_sensitivity::RunValue>,
    ) {
        let w = &mut self.state.matters.whole;
        let (Some(study), Some((at, output, unit))) = (&w.study, &w.at) else { return };
        if study.design != design || *at != base || w.values.len() != from {
            return;
        }
        let (output, unit, log_output) = (output.clone(), unit.clone(), study.log_output);
        w.values.extend(values);
        match crate::global_sensitivity::answer(&design, &w.values, log_output) {
            Ok(Some(a)) => w.answer = Some(a),
            Ok(None) => {}
            Err(e) => self.state.error = Some(format!("study not analysed: {e}")),
        }
        let done = w.values.len();
        let total = design.runs();
        w.running = done < total;
        self.state.status = format!("{output} over whole ranges: {done} of {total} runs");
        if done < total {
            let next = super::apply_sweep::whole_range_share(base, design, output, unit, done);
            self.carry_out(Effect::Submit(next));
        }
    }

    fn write_all(&mut self, folder: &str, files: &[(String, Vec<u8>)], what: &str) {
        let state = &mut self.state;
        match (self.platform.write_all(folder, files), what) {
            (Ok(names), "figure") => state.status = format!("exported {}", names.join(", ")),
            (Ok(names), _) => {
                state.status =
                    format!("wrote the {what}: {} files, {}", names.len(), names.last().cloned().unwrap_or_default())
            }
            (Err(e), "figure") => state.error = Some(format!("export failed, earlier files untouched: {e}")),
            (Err(e), _) => state.error = Some(format!("{what} not written, earlier files untouched: {e}")),
        }
    }

    /// Takes finished jobs, dialog answers, dropped files and the running
    /// job's intermediate result.
    pub(super) fn poll(&mut self, ctx: &egui::Context) {
        for finished in self.runner.poll() {
            let folder = self.computing.folders.iter().position(|(l, _)| *l == finished.lane);
            let folder = folder.map(|k| self.computing.folders.remove(k).1).unwrap_or_default();
            if finished.lane == Lane::Movie {
                self.state.movie_running = false;
            }
            match finished.result {
                Ok(Done::Scene(i, o)) => {
                    self.computing.stale = false;
                    self.state.finish(i, Ok(o));
                }
                Ok(Done::Sweep(pins)) => {
                    self.state.status = format!("swept {} values", pins.len());
                    self.state.session.pins.extend(pins);
                }
                Ok(Done::Matters(base, answer, coarse)) => {
                    let m = &mut self.state.matters;
                    self.state.status = if coarse {
                        format!("what matters for {}: a coarse first answer; computing the full one", m.output)
                    } else {
                        format!("what matters for {}: {} parameters", m.output, answer.rows.len())
                    };
                    m.coarse = coarse;
                    let (output, factor) = (m.output.clone(), m.factor);
                    m.result = Some(((*base).clone(), answer));
                    if coarse {
                        self.carry_out(Effect::Submit(Job::WhatMatters { base, output, factor, coarse: false }));
                    }
                }
                Ok(Done::WholeRange(base, design, from, values)) => self.whole_range_done(*base, *design, from, values),
                Ok(Done::Curve(base, fig)) => {
                    self.state.status = format!("drew {}", fig.title);
                    self.state.matters.curve = Some((*base, *fig));
                }
                Ok(Done::Files(what, files)) => self.write_all(&folder, &files, &what),
                Err(e) if finished.lane == Lane::Study => {
                    self.state.matters.whole.running = false;
                    if e != crate::app::jobs::JobError::Cancelled {
                        self.state.error = Some(format!("study stopped: {e}"));
                    }
                }
                Err(e) if matches!(finished.lane, Lane::Sweep | Lane::Curve) => {
                    self.state.error = Some(format!("not computed: {e}"));
                }
                Err(e) if finished.lane == Lane::Compute => {
                    self.computing.stale = false;
                    self.state.error = Some(e.to_string());
                }
                Err(e) => {
                    let what = if finished.lane == Lane::Movie { "movie" } else { "export" };
                    self.state.error = Some(format!("{what} not written, earlier files untouched: {e}"));
                }
            }
        }
        for answer in self.platform.poll() {
            match answer {
                Answer::Opened(FileKind::Measurements, picked) => self.state.open_bytes(picked, Then::Import),
                Answer::Opened(_, picked) => self.apply(Command::OpenBytes(picked)),
                Answer::Saved(FileKind::Preset, name) => self.state.status = format!("saved preset to {name}"),
                Answer::Saved(_, name) => self.state.status = format!("exported {name}"),
                Answer::Failed(FileKind::Preset, e) => self.state.error = Some(format!("preset not saved: {e}")),
                Answer::Failed(_, e) => self.state.error = Some(format!("file not used, nothing changed: {e}")),
                Answer::Cancelled => {
                    self.state.status =
                        "no file chosen (cancelled, or no file dialog on this desktop: type a path instead)".into()
                }
            }
        }
        let dropped: Vec<Command> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path())
                .filter(|p| !p.as_os_str().is_empty())
                .map(|p| Command::OpenPath(p.display().to_string()))
                .collect()
        });
        for c in dropped {
            self.apply(c);
        }
        if self.runner.busy(Lane::Sweep) || self.runner.busy(Lane::Curve) || self.runner.busy(Lane::Study) {
            ctx.request_repaint_after(self.runner.redraw_every());
        }
        if self.runner.busy(Lane::Compute) {
            // A long run offers intermediate results: draw them as they come.
            if let (Some(i), Some(part)) = (self.computing.live_scene, self.runner.partial(Lane::Compute))
                && !self.state.outputs[i].as_ref().is_some_and(|o| Arc::ptr_eq(o, &part))
            {
                self.state.outputs[i] = Some(part);
            }
            ctx.request_repaint_after(self.runner.redraw_every());
        }
    }
}
