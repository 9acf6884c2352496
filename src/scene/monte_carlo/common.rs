//! Parameters shared by the Monte Carlo scenes (thesis Sects. 4.3–4.4): the
//! column, the collision model and the distribution method; and the cache of
//! the last runs, so that switching between these scenes or changing a
//! display parameter does not rerun.

use crate::physics::aggregate::{R_CRIT, Thresholds, TurbulenceModel};
use crate::physics::coagulation::{Column, Compaction, Run, RunConfig, Sample};
use crate::physics::constants::{AU, YEAR};
use crate::physics::monte_carlo::Settings;
use crate::scene::core::{Progress, Scalar, SceneError, Seeds};
use crate::scene::disk::common::DiskParams;
use crate::scene::quantities;
use crate::scene::schema::{Choice, ParamSet};
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// How a column's aggregates are compressed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Choice)]
pub enum ColumnCompaction {
    /// Hit-and-stick and collisional compaction only (Fig. 4.4).
    #[choice(key = "collisional", label = "collisional only (Fig. 4.4)")]
    Collisional,
    /// Also the gas ram pressure and self-gravity (Fig. 4.6).
    #[default]
    #[choice(key = "full", label = "with gas and self-gravity (Fig. 4.6)")]
    Full,
}

/// A Monte Carlo run of a disk column. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct ColumnParams {
    /// Disk and monomers.
    #[param(flatten)]
    pub disk: DiskParams,
    /// radius of the column
    #[param(quantity = quantities::disk_radius, default = 5.0)]
    pub radius_au: f64,
    /// how aggregates are compressed
    #[param(label = "compaction")]
    pub compaction: ColumnCompaction,
    /// projectiles below R_crit = 10⁻² of the target's mass erode above it (10⁴ m/s: none)
    #[param(quantity = quantities::v_eros, label = "erosion threshold v_eros", default = 1e4)]
    pub v_eros: f64,
    /// similar-size collisions above it shatter (80 m/s for 0.1 µm ice)
    #[param(quantity = quantities::v_frag, default = 80.0)]
    pub v_frag: f64,
    /// use v_frag = 20 (E_break/m₀)^{1/2} (4.12) of the monomer card instead of the number above
    #[param(label = "v_frag from the monomer", default = false)]
    pub v_frag_from_monomer: bool,
    /// ε_eros = c₁ v/v_eros (4.13)
    #[param(label = "erosion prefactor c₁", range(0.1, 10.0), log, default = 1.0)]
    pub c1: f64,
    /// include Re_p > 1 drag
    #[param(label = "Newton drag", default = true)]
    pub newton: bool,
    /// full turbulence closed form
    #[param(label = "Ormel & Cuzzi form", default = false)]
    pub ormel_cuzzi: bool,
    /// resolution of the distribution method (4.26); cost grows about as w*²
    #[param(quantity = quantities::groups_per_decade, default = 40.0)]
    pub groups_per_decade: f64,
    /// largest relative change of a particle per group event (4.22)–(4.24)
    #[param(numerical, label = "sequence limit f_m = f_φ", range(0.01, 1.0), log, default = 0.1)]
    pub f_limit: f64,
    /// mass in the simulated column; sets its area M/Σ_d
    #[param(numerical, label = "column mass", unit = "kg", range(1e10, 1e30), log, default = 1e21)]
    pub column_mass: f64,
    /// independent seeds, run in parallel
    #[param(numerical, label = "runs", range(1.0, 16.0), default = 2)]
    pub runs: usize,
    /// runs use seed, seed + 1, …
    #[param(numerical, label = "first seed", range(0.0, 1_000_000.0), default = 1)]
    pub seed: usize,
    /// time of the first snapshot
    #[param(label = "first snapshot", unit = "yr", shown("yr", 1.0), range(1e-2, 1e6), log, default = 10.0)]
    pub t_first_yr: f64,
    /// end of the run
    #[param(label = "last snapshot", unit = "yr", shown("yr", 1.0), range(1e-1, 1e7), log, default = 1e4)]
    pub t_end_yr: f64,
    /// log-spaced in time
    #[param(figure_only, label = "snapshots", range(1.0, 12.0), default = 7)]
    pub snapshots: usize,
    /// the run ends when m_p reaches it
    #[param(label = "stop at peak mass", unit = "kg", shown("g", 1e3), range(1e-10, 1e25), log, default = 1e15)]
    pub stop_mass_g: f64,
    /// group events per run at most
    #[param(numerical, label = "event limit", shown("million", 1.0), range(0.01, 1000.0), log, default = 5.0)]
    pub max_events_millions: f64,
}

/// The preview's resolution: at most this many groups per decade w*.
pub const COARSE_GROUPS_PER_DECADE: f64 = 10.0;

/// The preview's number of runs at most.
pub const COARSE_RUNS: usize = 2;

/// The preview's event limit per run at most, in millions (a column with
/// erosion at w* = 10 reaches it in about 5 s on one core; without erosion a
/// thesis column needs a quarter of it).
pub const COARSE_EVENTS_MILLIONS: f64 = 0.2;

impl ColumnParams {
    /// The cheaper setting a heavy Monte Carlo scene shows first and audits
    /// at: w* ≤ [`COARSE_GROUPS_PER_DECADE`], at most [`COARSE_RUNS`] runs and
    /// at most [`COARSE_EVENTS_MILLIONS`] million events a run (about a
    /// second for a thesis column without erosion on two cores, at most
    /// about five with erosion, against a minute or more at w* = 40–60);
    /// None where the runs are already that light.
    pub fn coarse(&self) -> Option<ColumnParams> {
        let c = ColumnParams {
            groups_per_decade: self.groups_per_decade.min(COARSE_GROUPS_PER_DECADE),
            runs: self.runs.min(COARSE_RUNS),
            max_events_millions: self.max_events_millions.min(COARSE_EVENTS_MILLIONS),
            ..self.clone()
        };
        (c != *self).then_some(c)
    }

    /// The seeds of the runs.
    pub fn seeds(&mut self) -> Seeds<'_> {
        Seeds { first: &mut self.seed, runs: &mut self.runs }
    }

    /// The run configuration.
    pub fn config(&self) -> Result<RunConfig, SceneError> {
        if self.t_end_yr < self.t_first_yr {
            // Two settings that contradict each other, as a range's ends the
            // wrong way round: the input's fault, not the model's.
            return Err(SceneError::Param(crate::scene::ParamError::Inconsistent(
                "t_first_yr/t_end_yr: the last snapshot must not come before the first".into(),
            )));
        }
        let disk = self.disk.disk();
        let full = self.compaction == ColumnCompaction::Full;
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
        // Each run is a unit of its own: a browser shares them among its
        // workers; natively they take turns on the cores.
        let runs = cfg.run_seeds_mapped(
            self.runs.max(1),
            &|f| {
                progress.set(f);
                progress.wait_while_paused();
                !progress.cancelled()
            },
            observe,
            |seeds, run| progress.units_longest_first(seeds, |k, turn| run(k, turn).map_err(SceneError::from)),
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

/// The runs of `p` from the scene's cache (computed only if not cached),
/// each run's progress drawn live by `output` as it computes.
pub fn runs_shown_live(
    p: &ColumnParams,
    ctx: &mut crate::scene::core::Context<'_>,
    output: impl Fn(&[Run]) -> crate::scene::core::SceneOutput + Sync,
) -> Result<Arc<Vec<Run>>, SceneError> {
    let progress = ctx.progress;
    let live = live_view(progress, output);
    let cache: &mut RunCache = ctx.caches.get();
    cache.get_observed(p, progress, &live)
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
        at_event_limit(runs.iter()),
    ]
}

/// The scalar `runs_at_event_limit`: how many of `runs` the event limit
/// stopped (their scalars are where they stopped).
pub fn at_event_limit<'a>(runs: impl Iterator<Item = &'a Run>) -> Scalar {
    Scalar {
        key: "runs_at_event_limit",
        label: "runs stopped by the event limit",
        value: runs.filter(|r| r.ended == crate::physics::coagulation::ENDED_AT_EVENT_LIMIT).count() as f64,
        unit: "",
    }
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

/// The declarations of a column scene: every column's ([`COLUMN_DECLARED`])
/// followed by the scene's own, as one constant slice. The event limit
/// comes before the thresholds of the physics: any other step is first
/// checked against it (at four and sixteen times the limit), and falls to
/// those only where the limit does not explain it.
macro_rules! column_declared {
    ($($own:expr),* $(,)?) => {
        &[
            $crate::scene::monte_carlo::common::EVENT_COUNT,
            $crate::scene::monte_carlo::common::FAMILY_COUNT,
            $crate::scene::monte_carlo::common::EVENT_LIMIT,
            $crate::scene::monte_carlo::common::EROSION_ONSET,
            $crate::scene::monte_carlo::common::STOP_OUT_OF_REACH,
            $crate::scene::monte_carlo::common::FRAGMENTATION_BARRIER,
            $($own),*
        ]
    };
}
pub(crate) use column_declared;

/// What the continuity audit finds in a column's scalars that is the method
/// or the physics, not a defect.
pub const COLUMN_DECLARED: &[crate::scene::core::Declared] = column_declared![];

/// What a column scene declares beyond [`COLUMN_DECLARED`], after checking
/// that its declarations start with those (a test helper: every column scene
/// must declare what every column declares).
#[cfg(test)]
pub fn declared_beyond_column(own: &'static [crate::scene::core::Declared]) -> &'static [crate::scene::core::Declared] {
    assert!(own.len() >= COLUMN_DECLARED.len(), "the scene declares less than every column declares");
    assert_eq!(&own[..COLUMN_DECLARED.len()], COLUMN_DECLARED);
    &own[COLUMN_DECLARED.len()..]
}

/// The first snapshot's time sets what the figures draw, not the scalars:
/// those come from the end of the runs, and the runs take the same random
/// path whatever the snapshot times.
pub const FIRST_SNAPSHOT: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "*",
    parameter: "t_first_yr",
    kind: crate::scene::core::Irregularity::Ignored,
    why: "it sets only when the first snapshot is drawn: the scalars come from the end of the runs",
    resolution: None,
};

/// The number of families is a diagnostic of the distribution method: the
/// zoom factors z* = [log₂(N₁₀/w*)] (4.26) change by whole numbers as w*
/// (or anything that moves N₁₀) crosses a power of two, and the families
/// merge or split with them. Any parameter that changes the distribution's
/// width changes their number: an erosive column at v_eros = 0.017 m/s,
/// where nearly every collision erodes, ends with 38 families, one at
/// 0.025 m/s with 146, at the same event limit or at sixteen times it.
pub const FAMILY_COUNT: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "families",
    parameter: "*",
    kind: crate::scene::core::Irregularity::Step,
    why: "a diagnostic, the families of the method: zoom factors z* = [log₂(N₁₀/w*)] (4.26) change by whole numbers",
    resolution: None,
};

/// Erosion acts only where a projectile hits faster than v_eros (4.13):
/// above the fastest collision a run reaches, nothing erodes and ζ (4.34)
/// is 1 exactly; just below it, erosion balances growth. The small
/// projectiles all hit the largest bodies at nearly the speed of those
/// bodies through the gas, so their erosion starts at once as v_eros falls
/// below it, and the end of the run steps with ζ: in `mc-fig-4-4` (preview
/// setting) the time at which m_p reaches the stop mass moves from 4 400 to
/// 5 100 years between v_eros = 79 and 53 m/s, and further at a higher event
/// limit.
pub const EROSION_ONSET: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "*",
    parameter: "v_eros",
    kind: crate::scene::core::Irregularity::Step,
    why: "a threshold: above the fastest collision of the run nothing erodes and ζ = 1 exactly (4.13), (4.34); the largest bodies meet small projectiles all at nearly their own speed, so their erosion, and the end of the run, switch on at once",
    resolution: None,
};

/// The fragmentation barrier: collisions of particles within a mass ratio of
/// 10⁻² shatter at v ≥ v_frag. Where the fastest of them between the peak's
/// bodies near Ωt_s ≈ 1 exceeds v_frag, the peak stalls there and only a few
/// lucky bodies pass; where v_frag exceeds it, the peak grows through. The
/// end of a run (its mass, filling factor, Stokes number and time) therefore
/// steps where v_frag crosses that speed: about 48.7 m/s at 5 AU in
/// `mc-fig-5-2-porosity` at w* = 10, where runs of 200 000 group events
/// mostly end with m_p = 10⁷–10⁹ kg below it (a lucky one passes) and all
/// reach the stop mass of 10¹² kg above it, while less similar pairs still
/// shatter on both sides.
pub const FRAGMENTATION_BARRIER: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "*",
    parameter: "v_frag",
    kind: crate::scene::core::Irregularity::Step,
    why: "a threshold, the fragmentation barrier: below the speed of the peak's collisions with similar bodies (mass ratio ≥ 10⁻²) near Ωt_s ≈ 1 growth stalls there and only lucky bodies pass; above it the peak grows through",
    resolution: None,
};

/// A run stops when its peak mass reaches the stop mass; a column holding
/// less mass than that never does and runs to its last snapshot.
pub const STOP_OUT_OF_REACH: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "t_end",
    parameter: "column_mass",
    kind: crate::scene::core::Irregularity::Step,
    why: "a run stops when m_p reaches the stop mass; a column lighter than it never does and runs to the last snapshot",
    resolution: None,
};

/// A run that reaches the event limit ends there, and its scalars are where
/// it stopped (the notes name the runs that did). Where a change of any
/// parameter moves a run across the limit, they step: an erosive column at
/// v_eros = 0.017 m/s (`mc-fig-4-4` at the preview's 0.2 million events)
/// stops after 900 years where one at 0.025 m/s reaches its last snapshot
/// at 10⁴ years. A step of the event limit, not of the physics: the audit
/// checks that it shrinks at four (or sixteen) times the limit; where it
/// does not, the step is open unless a threshold of the physics declared
/// after this one covers it.
pub const EVENT_LIMIT: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "*",
    parameter: "*",
    kind: crate::scene::core::Irregularity::Step,
    why: "the event limit: a run that reaches it ends there, and its scalars are where it stopped",
    resolution: Some("max_events_millions"),
};

/// The Monte Carlo scenes' event count is a diagnostic: a whole number per
/// run (the mean over runs), which steps with the grouping (`groups_per_decade`)
/// and the random path.
pub const EVENT_COUNT: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "events",
    parameter: "*",
    kind: crate::scene::core::Irregularity::Step,
    why: "a diagnostic, the group events of a run: whole numbers, with the grouping and the random path",
    resolution: None,
};
