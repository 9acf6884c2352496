//! Parameters shared by the Monte Carlo scenes (thesis Sects. 4.3–4.4): the
//! column, the collision model and the distribution method; and the cache of
//! the last runs, so that switching between these scenes or changing a
//! display parameter does not rerun.

use crate::physics::aggregate::{R_CRIT, Thresholds, TurbulenceModel};
use crate::physics::coagulation::{Column, Compaction, Run, RunConfig, Sample};
use crate::physics::constants::{AU, YEAR};
use crate::physics::monte_carlo::Settings;
use crate::scene::controls::Control;
use crate::scene::core::{Progress, Scalar, SceneError};
use crate::scene::disk::common::{DiskParams, radius_control};
use crate::scene::quantities;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// A Monte Carlo run of a disk column. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ColumnParams {
    /// Disk and monomers.
    pub disk: DiskParams,
    /// Radius of the column, AU (default 5).
    pub radius_au: f64,
    /// "collisional" (hit-and-stick and collisional compaction) or "full" (also gas and self-gravity).
    pub compaction: String,
    /// Erosion threshold v_eros, m s⁻¹ (default 10⁴: no erosion).
    pub v_eros: f64,
    /// Catastrophic fragmentation velocity, m s⁻¹ (default 80, (4.12) for 0.1 µm ice).
    pub v_frag: f64,
    /// Use the monomer's v_frag (4.12) instead of `v_frag`.
    pub v_frag_from_monomer: bool,
    /// Erosion efficiency prefactor c₁ of (4.13) (default 1).
    pub c1: f64,
    /// Include Newton drag (default: with full compaction).
    pub newton: bool,
    /// Use the full Ormel & Cuzzi turbulence form.
    pub ormel_cuzzi: bool,
    /// Groups per mass decade w* (default 40).
    pub groups_per_decade: f64,
    /// Sequence limits f_m = f_φ (default 0.1).
    pub f_limit: f64,
    /// Mass in the column, kg (default 10²¹).
    pub column_mass: f64,
    /// Runs with seeds seed, seed + 1, … (default 2).
    pub runs: usize,
    /// First seed (default 1).
    pub seed: usize,
    /// First snapshot, yr (default 10).
    pub t_first_yr: f64,
    /// Last snapshot and end of the run, yr (default 10⁴).
    pub t_end_yr: f64,
    /// Snapshots, log-spaced (default 7).
    pub snapshots: usize,
    /// Stop when the peak mass reaches this, g (default 10¹⁵).
    pub stop_mass_g: f64,
    /// Safety limit on group events per run, millions (default 5).
    pub max_events_millions: f64,
}

impl Default for ColumnParams {
    fn default() -> Self {
        ColumnParams {
            disk: DiskParams::default(),
            radius_au: 5.0,
            compaction: "full".into(),
            v_eros: 1e4,
            v_frag: 80.0,
            v_frag_from_monomer: false,
            c1: 1.0,
            newton: true,
            ormel_cuzzi: false,
            groups_per_decade: 40.0,
            f_limit: 0.1,
            column_mass: 1e21,
            runs: 2,
            seed: 1,
            t_first_yr: 10.0,
            t_end_yr: 1e4,
            snapshots: 7,
            stop_mass_g: 1e15,
            max_events_millions: 5.0,
        }
    }
}

impl ColumnParams {
    /// The documented parameters.
    pub fn controls(&mut self, d: &Self) -> Vec<Control<'_>> {
        let mut c = self.disk.controls(&d.disk);
        let yr = ("yr", 1.0);
        c.push(radius_control(&mut self.radius_au, "radius of the column").default(d.radius_au));
        c.push(
            Control::choice(
                "compaction",
                "compaction",
                &mut self.compaction,
                vec![("collisional", "collisional only (Fig. 4.4)"), ("full", "with gas and self-gravity (Fig. 4.6)")],
            )
            .default(d.compaction.clone())
            .doc("how aggregates are compressed"),
        );
        c.push(
            quantities::v_eros(&mut self.v_eros)
                .default(d.v_eros)
                .labelled("erosion threshold v_eros")
                .doc("projectiles below R_crit = 10⁻² of the target's mass erode above it (10⁴: none)"),
        );
        c.push(
            quantities::v_frag(&mut self.v_frag)
                .default(d.v_frag)
                .doc("similar-size collisions above it shatter (80 m/s for 0.1 µm ice)"),
        );
        c.push(
            Control::toggle("v_frag_from_monomer", "v_frag from the monomer", &mut self.v_frag_from_monomer)
                .default(d.v_frag_from_monomer)
                .doc("use v_frag = 20 (E_break/m₀)^{1/2} (4.12) of the monomer card instead of the number above"),
        );
        c.push(
            Control::number("c1", "erosion prefactor c₁", &mut self.c1)
                .default(d.c1)
                .range(0.1, 10.0)
                .log()
                .doc("ε_eros = c₁ v/v_eros (4.13)"),
        );
        c.push(
            Control::toggle("newton", "Newton drag", &mut self.newton).default(d.newton).doc("include Re_p > 1 drag"),
        );
        c.push(
            Control::toggle("ormel_cuzzi", "Ormel & Cuzzi form", &mut self.ormel_cuzzi)
                .default(d.ormel_cuzzi)
                .doc("full turbulence closed form"),
        );
        c.push(
            quantities::groups_per_decade(&mut self.groups_per_decade)
                .default(d.groups_per_decade)
                .doc("resolution of the distribution method (4.26); cost grows about as w*²"),
        );
        c.push(
            Control::number("f_limit", "sequence limit f_m = f_φ", &mut self.f_limit)
                .default(d.f_limit)
                .range(0.01, 1.0)
                .log()
                .doc("largest relative change of a particle per group event (4.22)–(4.24)"),
        );
        c.push(
            Control::number("column_mass", "column mass", &mut self.column_mass)
                .default(d.column_mass)
                .unit("kg")
                .range(1e10, 1e30)
                .log()
                .doc("mass in the simulated column; sets its area M/Σ_d"),
        );
        c.push(
            Control::count("runs", "runs", &mut self.runs)
                .default(d.runs)
                .range(1.0, 16.0)
                .doc("independent seeds, run in parallel"),
        );
        c.push(
            Control::count("seed", "first seed", &mut self.seed)
                .default(d.seed)
                .range(0.0, 1_000_000.0)
                .doc("runs use seed, seed + 1, …"),
        );
        c.push(
            Control::number("t_first_yr", "first snapshot", &mut self.t_first_yr)
                .default(d.t_first_yr)
                .unit("yr")
                .shown(yr.0, yr.1)
                .range(1e-2, 1e6)
                .log()
                .doc("time of the first snapshot"),
        );
        c.push(
            Control::number("t_end_yr", "last snapshot", &mut self.t_end_yr)
                .default(d.t_end_yr)
                .unit("yr")
                .shown(yr.0, yr.1)
                .range(1e-1, 1e7)
                .log()
                .doc("end of the run"),
        );
        c.push(
            Control::count("snapshots", "snapshots", &mut self.snapshots)
                .default(d.snapshots)
                .range(1.0, 12.0)
                .doc("log-spaced in time"),
        );
        c.push(
            Control::number("stop_mass_g", "stop at peak mass", &mut self.stop_mass_g)
                .default(d.stop_mass_g)
                .unit("kg")
                .shown("g", 1e3)
                .range(1e-10, 1e25)
                .log()
                .doc("the run ends when m_p reaches it"),
        );
        c.push(
            Control::number("max_events_millions", "event limit", &mut self.max_events_millions)
                .default(d.max_events_millions)
                .shown("million", 1.0)
                .range(0.01, 1000.0)
                .log()
                .doc("group events per run at most"),
        );
        c
    }

    /// The run configuration.
    pub fn config(&self) -> Result<RunConfig, SceneError> {
        if self.t_end_yr < self.t_first_yr {
            return Err(SceneError::Physics(crate::physics::PhysicsError::Invalid(
                "the last snapshot must not come before the first".into(),
            )));
        }
        let disk = self.disk.disk();
        let full = self.compaction == "full";
        let column = Column {
            env: disk.local(self.radius_au * AU),
            monomer: self.disk.monomer(),
            thresholds: Thresholds {
                v_frag: self.disk.fragmentation_velocity(self.v_frag, self.v_frag_from_monomer),
                v_eros: self.v_eros,
                v_bounce: f64::INFINITY,
                r_crit: R_CRIT,
            },
            c1: self.c1,
            compaction: if full { Compaction::Full } else { Compaction::Collisional },
            turbulence: if self.ormel_cuzzi { TurbulenceModel::OrmelCuzzi } else { TurbulenceModel::Thesis },
            epsilon: 0.1,
            newton: self.newton,
        };
        let snapshots =
            crate::scene::core::logspace(self.t_first_yr * YEAR, self.t_end_yr * YEAR, self.snapshots.max(2))
                .into_iter()
                .skip(if self.snapshots == 1 { 1 } else { 0 })
                .collect();
        Ok(RunConfig {
            column,
            column_mass: self.column_mass,
            settings: Settings {
                groups_per_decade: self.groups_per_decade,
                f_m: self.f_limit,
                f_phi: self.f_limit,
                rezoom_every: 100,
                seed: self.seed as u64,
                group_mass_cap: 1.0,
            },
            snapshots,
            history_per_decade: 8,
            max_events: (self.max_events_millions * 1e6) as u64,
            stop_mass: self.stop_mass_g * 1e-3,
        })
    }

    /// Runs all seeds on the worker, reporting progress and stopping on cancel.
    pub fn run(&self, progress: &Progress) -> Result<Vec<Run>, SceneError> {
        self.run_observed(progress, &|_| {})
    }

    /// As [`ColumnParams::run`], handing the first run so far to `observe`.
    pub fn run_observed(&self, progress: &Progress, observe: &(dyn Fn(&Run) + Sync)) -> Result<Vec<Run>, SceneError> {
        let cfg = self.config()?;
        let runs = cfg.run_seeds_observed(
            self.runs.max(1),
            &|f| {
                progress.set(f);
                progress.wait_while_paused();
                !progress.cancelled()
            },
            observe,
        )?;
        progress.check()?;
        Ok(runs)
    }
}

/// An observer for [`RunCache::get_observed`] that publishes the scene output
/// `build` makes of the first run so far, with a note that it is running.
pub fn live_view<'a>(
    progress: &'a Progress,
    build: impl Fn(&[Run]) -> crate::scene::core::SceneOutput + Sync + 'a,
) -> impl Fn(&Run) + Sync + 'a {
    move |run: &Run| {
        let mut out = build(std::slice::from_ref(run));
        let t = run.history.last().map_or(0.0, |s| s.t) / YEAR;
        out.notes.insert(
            0,
            format!("running: seed {} at {} yr (live view of the first run)", run.seed, crate::figure::human(t)),
        );
        progress.publish(out);
    }
}

/// The last Monte Carlo runs, shared by the Monte Carlo scenes: up to four
/// parameter sets are kept (the erosion scene runs three thresholds).
#[derive(Debug, Default)]
pub struct RunCache {
    last: Vec<(ColumnParams, Arc<Vec<Run>>)>,
}

impl RunCache {
    /// The runs for `p`, computed only if not cached.
    pub fn get(&mut self, p: &ColumnParams, progress: &Progress) -> Result<Arc<Vec<Run>>, SceneError> {
        self.get_observed(p, progress, &|_| {})
    }

    /// As [`RunCache::get`], handing the first run so far to `observe` while it computes.
    pub fn get_observed(
        &mut self,
        p: &ColumnParams,
        progress: &Progress,
        observe: &(dyn Fn(&Run) + Sync),
    ) -> Result<Arc<Vec<Run>>, SceneError> {
        if let Some((_, runs)) = self.last.iter().find(|(key, _)| key == p) {
            progress.set(1.0);
            return Ok(Arc::clone(runs));
        }
        let runs = p.run_observed(progress, observe)?;
        Ok(self.insert(p.clone(), runs))
    }

    /// Whether runs for `p` are cached.
    pub fn contains(&self, p: &ColumnParams) -> bool {
        self.last.iter().any(|(key, _)| key == p)
    }

    /// Stores runs computed elsewhere.
    pub fn insert(&mut self, p: ColumnParams, runs: Vec<Run>) -> Arc<Vec<Run>> {
        let runs = Arc::new(runs);
        self.last.retain(|(key, _)| *key != p);
        self.last.push((p, Arc::clone(&runs)));
        if self.last.len() > 4 {
            self.last.remove(0);
        }
        runs
    }
}

/// Summary scalars of a set of runs (from their last samples).
pub fn summary(runs: &[Run]) -> Vec<Scalar> {
    let last: Vec<&Sample> = runs.iter().filter_map(|r| r.history.last()).collect();
    let mean = |f: &dyn Fn(&Sample) -> f64| last.iter().map(|s| f(s)).sum::<f64>() / last.len().max(1) as f64;
    let worst_mass = runs.iter().flat_map(|r| r.history.iter()).map(|s| s.mass_error.abs()).fold(0.0, f64::max);
    vec![
        Scalar { key: "t_end", label: "time reached", value: mean(&|s| s.t), unit: "s" },
        Scalar { key: "m_p", label: "peak mass m_p", value: mean(&|s| s.m_p), unit: "kg" },
        Scalar { key: "phi_p", label: "peak filling factor φ_p", value: mean(&|s| s.phi_p), unit: "" },
        Scalar { key: "m_max", label: "largest mass", value: mean(&|s| s.m_max), unit: "kg" },
        Scalar { key: "stokes_max", label: "Ωt_s of the largest", value: mean(&|s| s.stokes_max), unit: "" },
        Scalar { key: "zeta", label: "ζ of the largest (4.34)", value: mean(&|s| s.zeta), unit: "" },
        Scalar { key: "events", label: "group events per run", value: mean(&|s| s.events as f64), unit: "" },
        Scalar { key: "families", label: "families", value: mean(&|s| s.families as f64), unit: "" },
        Scalar { key: "mass_error", label: "largest |ΔM|/M", value: worst_mass, unit: "" },
    ]
}

/// Notes on how the runs ended.
pub fn endings(runs: &[Run]) -> Vec<String> {
    runs.iter()
        .map(|r| {
            format!(
                "seed {}: {} after {} group events ({} sticking, {} erosive, {} shattering; {} merges, {} re-zooms)",
                r.seed,
                r.ended,
                r.events,
                r.tally.stick,
                r.tally.erode,
                r.tally.shatter,
                r.tally.merges,
                r.tally.rezooms
            )
        })
        .collect()
}
