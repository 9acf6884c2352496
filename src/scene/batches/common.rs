//! Parameters shared by the global dust-batch scenes (thesis ch. 5).

use crate::physics::batches::{BatchConfig, BatchRun, KERNEL_HALF_WIDTH, Smoothing, run};
use crate::physics::constants::{AU, YEAR};
use crate::physics::growth::{GrowthModel, Porosity};
use crate::scene::core::{Declared, Irregularity, Progress, SceneError};
use crate::scene::disk::common::{DiskParams, DiskProfile};
use crate::scene::quantities;
use crate::scene::schema::{Choice, ParamSet};
use serde::{Deserialize, Serialize};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// How the batches' aggregates grow.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Choice)]
pub enum Growth {
    /// Porous growth and compaction (App. 5.C).
    #[default]
    #[choice(key = "porous", label = "porous (App. 5.C)")]
    Porous,
    /// Compact particles, φ = 1.
    #[choice(key = "compact", label = "compact (φ = 1)")]
    Compact,
}

/// How the dust surface density (5.7) is read from the batches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Choice)]
pub enum SurfaceDensityEstimate {
    /// A triangular kernel of half-width `smoothing` in ln R.
    #[default]
    #[choice(key = "kernel", label = "kernel (±smoothing)")]
    Kernel,
    /// Each batch's annulus and two neighbours' (at least ±5 %), as earlier versions.
    #[choice(key = "annuli", label = "neighbour annuli (older presets)")]
    Annuli,
}

/// A batch-model run. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct BatchParams {
    /// Disk and monomers (default: the truncated power law, 0.01 M☉, R_c = 30 AU, γ = 1, Z₀ = 0.02).
    #[param(flatten, except("dlnm"), default = DiskParams { profile: DiskProfile::PowerLaw, metallicity: 0.02, ..DiskParams::default() })]
    pub disk: DiskParams,
    /// porosity treatment
    #[param(label = "growth")]
    pub growth: Growth,
    /// off: drift only (Fig. 5.1)
    #[param(label = "coagulation", default = true)]
    pub coagulation: bool,
    /// fragmentation or bouncing threshold: same-size collisions above it stop growth (1e4: none)
    #[param(quantity = quantities::v_frag, label = "growth barrier v_frag", default = 1e4)]
    pub v_frag: f64,
    /// use v_frag = 20 (E_break/m₀)^{1/2} (4.12) of the monomer card instead of the number above
    #[param(label = "v_frag from the monomer", default = false)]
    pub v_frag_from_monomer: bool,
    /// collisions with monomers above it stop growth (1e4: none)
    #[param(quantity = quantities::v_eros, default = 1e4)]
    pub v_eros: f64,
    /// count differential settling at one dust scale height among the relative velocities (ch. 4); off: the midplane velocities of App. 5.B
    ///
    /// Count differential settling at one dust scale height among the
    /// relative velocities, as ch. 4 does. Default off: App. 5.B's
    /// velocities at the midplane (Brownian motion, turbulence, radial and
    /// azimuthal drift). A preset without this key was written when the batch
    /// scenes always counted settling, and keeps doing so.
    #[serde(default = "settling_in_presets_without_the_key")]
    #[param(label = "settling in Δv", default = false)]
    pub settling: bool,
    /// initial radius of the first batch
    #[param(below = r_out_au, label = "innermost batch", unit = "AU", range(1.1, 100.0), log, default = 3.0)]
    pub r_in_au: f64,
    /// initial radius of the last batch
    #[param(label = "outermost batch", unit = "AU", range(2.0, 1000.0), log, default = 200.0)]
    pub r_out_au: f64,
    /// number of batches (10²–10³ in the thesis)
    ///
    /// Number of batches (default 500: the zone edge of Fig. 5.9's disks
    /// within 5 % of its converged value with the kernel estimate). A preset
    /// without this key was written when the default was 250 and keeps it.
    #[serde(default = "batches_in_presets_without_the_key")]
    #[param(numerical, label = "batches", range(10.0, 2000.0), default = 500)]
    pub batches: usize,
    /// how the dust surface density (5.7) is read from the batches: a kernel of fixed width (converges with the batch count) or the annuli of earlier versions
    ///
    /// How the dust surface density (5.7) is read from the batches: "kernel"
    /// (a triangular kernel of half-width `smoothing` in ln R) or "annuli"
    /// (each batch's annulus and two neighbours', at least ±5 %: the estimate
    /// of earlier versions, whose zone edge moves with the batch count and the
    /// step). A preset without this key was written with the annuli and keeps
    /// them.
    #[serde(default = "annuli_in_presets_without_the_key")]
    #[param(label = "Σ_d estimate")]
    pub surface_density: SurfaceDensityEstimate,
    /// half-width in ln R of the kernel over which Σ_d is averaged (at least two batch spacings); wider kernels let pile-ups reach further out
    ///
    /// Half-width of the Σ_d kernel in ln R (default 0.1, at least two initial
    /// batch spacings): the radial scale over which the batch model sees the
    /// dust, a model choice that sets how far a pile-up of drifting batches
    /// reaches.
    #[param(label = "Σ_d smoothing", range(0.02, 0.5), log, default = KERNEL_HALF_WIDTH)]
    pub smoothing: f64,
    /// time followed
    #[param(quantity = quantities::duration, default = 1e6)]
    pub duration_yr: f64,
    /// mass growth per step of a batch (second-order scheme)
    ///
    /// Growth per step, Δln m (default 0.2; the disk's own step is not used
    /// here). With the kernel estimate of Σ_d the zone edge of 500 batches
    /// moves by under 5 % from 0.2 to 0.1.
    #[param(numerical, label = "step Δln m", range(0.01, 1.0), log, default = 0.2)]
    pub dlnm: f64,
}

/// The relative velocities of a batch preset that does not name `settling`:
/// those of the batch scenes before the key existed, with settling.
fn settling_in_presets_without_the_key() -> bool {
    true
}

/// The surface density of a batch preset that does not name
/// `surface_density`: the annuli of the versions that wrote it.
fn annuli_in_presets_without_the_key() -> SurfaceDensityEstimate {
    SurfaceDensityEstimate::Annuli
}

/// The batch count of a preset that does not name `batches`: the default of
/// the versions that wrote it.
fn batches_in_presets_without_the_key() -> usize {
    250
}

/// Batches in all that a preview of a sweep runs (its first picture within
/// about 0.1 s on two cores).
const PREVIEW_BATCHES: usize = 120;

impl BatchParams {
    /// The run of a preview: at most 40 batches.
    pub fn coarse(&self) -> BatchParams {
        self.coarse_over(1)
    }

    /// The run of each of `disks` disks in the preview of a sweep: about 120
    /// batches in all, 12 to 40 per disk, never more than the full run.
    pub fn coarse_over(&self, disks: usize) -> BatchParams {
        self.coarse_within(disks, 40)
    }

    /// The run of each of `disks` disks in a preview of about 120 batches in
    /// all, 12 to `most` per disk, never more than the full run.
    pub fn coarse_within(&self, disks: usize, most: usize) -> BatchParams {
        let per_disk = (PREVIEW_BATCHES / disks.max(1)).clamp(12, most.max(12));
        BatchParams { batches: self.batches.min(per_disk), ..self.clone() }
    }

    /// The run configuration.
    pub fn config(&self) -> BatchConfig {
        let porosity = match self.growth {
            Growth::Compact => Porosity::Compact,
            Growth::Porous => Porosity::Full,
        };
        let mut model = GrowthModel::chapter4(porosity);
        model.disk = self.disk.disk();
        model.monomer = self.disk.monomer();
        let v_frag = self.disk.fragmentation_velocity(self.v_frag, self.v_frag_from_monomer);
        model.thresholds.v_frag = v_frag;
        model.thresholds.v_bounce = v_frag;
        model.thresholds.v_eros = self.v_eros;
        model.settling = self.settling;
        model.dlnm = self.dlnm;
        model.midpoint = true;
        BatchConfig {
            model,
            r_in: self.r_in_au * AU,
            r_out: self.r_out_au * AU,
            batches: self.batches,
            t_end: self.duration_yr * YEAR,
            coagulation: self.coagulation,
            smoothing: if self.surface_density == SurfaceDensityEstimate::Annuli {
                Smoothing::ANNULI
            } else {
                Smoothing::Kernel { half_width: self.smoothing }
            },
            frames_per_decade: 40,
            offset: 0.0,
        }
    }

    /// Runs the model with progress and cancellation.
    pub fn run(&self, progress: &Progress) -> Result<BatchRun, SceneError> {
        self.run_reporting(progress, &|f| progress.set(f))
    }

    /// Runs the model as one of `total` runs of a sweep: progress counts the
    /// finished runs (in `done`), so parallel runs report one monotonic figure.
    pub fn run_in_sweep(&self, progress: &Progress, done: &AtomicUsize, total: usize) -> Result<BatchRun, SceneError> {
        Self::counted(&self.config(), progress, done, total)
    }

    /// The outermost radius at which planetesimals formed, m (0 if none), as
    /// one of `total` runs of a sweep (see [`BatchParams::run_in_sweep`]).
    /// The run keeps no frames but its end state: the same fates to the last
    /// bit, without the memory and the diagnostics of every frame.
    pub fn edge_in_sweep(&self, progress: &Progress, done: &AtomicUsize, total: usize) -> Result<f64, SceneError> {
        let cfg = BatchConfig { frames_per_decade: 0, ..self.config() };
        Ok(Self::counted(&cfg, progress, done, total)?.outermost_planetesimals())
    }

    /// Runs `cfg` as one of `total` runs of a sweep, counting it in `done`.
    fn counted(
        cfg: &BatchConfig,
        progress: &Progress,
        done: &AtomicUsize,
        total: usize,
    ) -> Result<BatchRun, SceneError> {
        let r = Self::run_config(cfg, progress, &|_| {})?;
        let finished = done.fetch_add(1, Ordering::Relaxed) + 1;
        progress.set(finished as f64 / total.max(1) as f64);
        Ok(r)
    }

    fn run_reporting(&self, progress: &Progress, report: &(dyn Fn(f64) + Sync)) -> Result<BatchRun, SceneError> {
        Self::run_config(&self.config(), progress, report)
    }

    fn run_config(
        cfg: &BatchConfig,
        progress: &Progress,
        report: &(dyn Fn(f64) + Sync),
    ) -> Result<BatchRun, SceneError> {
        let keep = |f: f64| {
            report(f);
            progress.cancelled()
        };
        match run(cfg, &keep) {
            Ok(r) => Ok(r),
            Err(_) if progress.cancelled() => Err(SceneError::Cancelled),
            Err(e) => Err(e.into()),
        }
    }
}

/// `n` log-spaced values from `lo` to `hi` (just `lo` when n ≤ 1).
pub fn log_grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n <= 1 { vec![lo] } else { crate::scene::core::logspace(lo, hi.max(lo * 1.000001), n) }
}

/// The last batch run, shared by the batch scenes: a change of a display
/// parameter (colouring, thinning) or a switch between them reuses it.
#[derive(Debug, Default)]
pub struct RunCache {
    last: Option<(BatchParams, Arc<BatchRun>)>,
}

impl RunCache {
    /// The run for `p`, computed only if `p` differs from the cached one.
    pub fn get(&mut self, p: &BatchParams, progress: &Progress) -> Result<Arc<BatchRun>, SceneError> {
        if let Some((key, run)) = &self.last
            && key == p
        {
            progress.set(1.0);
            return Ok(Arc::clone(run));
        }
        let run = Arc::new(p.run(progress)?);
        self.last = Some((p.clone(), Arc::clone(&run)));
        Ok(run)
    }
}

/// What a click near a batch sample shows: the batch nearest `at` on figure
/// `fig`, where `place` gives a sample's point on that figure (axis units).
pub fn inspect_batch(
    p: &BatchParams,
    run: &BatchRun,
    fig: &crate::figure::Figure,
    at: [f64; 2],
    place: &dyn Fn(f64, &crate::physics::batches::BatchSample) -> [f64; 2],
) -> Option<crate::scene::inspect::Inspection> {
    use crate::physics::batches::Fate;
    use crate::scene::inspect::{self, Inspection};
    let samples = run.frames.iter().flat_map(|f| f.batches.iter().enumerate().map(move |(b, s)| (f.t, b, s)));
    let candidates: Vec<(f64, usize, &crate::physics::batches::BatchSample)> =
        samples.filter(|(_, _, s)| s.dust && s.mass > 0.0).collect();
    let (k, _) = inspect::nearest(fig, candidates.iter().map(|(t, _, s)| place(*t, s)), at, 0.05)?;
    let (t, b, s) = candidates[k];
    let mut rows = vec![
        inspect::row(
            "batch",
            format!("{} of {}, from {} AU", b + 1, run.masses.len(), crate::figure::human(run.initial_radii[b] / AU)),
        ),
        inspect::row("time t", inspect::value(t / YEAR, "yr")),
    ];
    rows.extend(crate::scene::disk::common::aggregate_rows(&p.disk, s.r, s.mass, s.filling, s.t_grow));
    rows.push(inspect::row("midplane ρ*_d/ρ_g (5.13)", inspect::value(s.loading, "")));
    rows.push(inspect::row("streaming-instability conditions", if s.si { "met" } else { "not met" }.to_string()));
    let fate = match run.fates.get(b) {
        Some(Fate::Planetesimals { t, r }) => format!(
            "this batch forms planetesimals at {} AU after {} yr",
            crate::figure::human(r / AU),
            crate::figure::human(t / YEAR)
        ),
        Some(Fate::Lost { t }) => format!(
            "this batch drifts inside the inner edge ({} AU) after {} yr",
            crate::figure::human(p.config().model.inner_edge / AU),
            crate::figure::human(t / YEAR)
        ),
        Some(Fate::Dust) | None => format!("this batch is still dust at {} yr", crate::figure::human(p.duration_yr)),
    };
    Some(Inspection {
        title: format!("Batch {} at t = {} yr", b + 1, crate::figure::human(t / YEAR)),
        rows,
        bars: None,
        outcome: Some(fate),
        actions: vec![crate::scene::registry::column_action(&p.disk, s.r / AU)],
        point: place(t, s),
    })
}

/// The size factor of markers along the drawn paths of `n` batches, every
/// `every`-th drawn: full size up to 40 paths, shrinking as √(40/paths) to
/// 0.4, so that markers on crowded radii stay apart.
pub fn marker_size(n: usize, every: usize) -> f64 {
    (40.0 / n.div_ceil(every.max(1)).max(1) as f64).sqrt().clamp(0.4, 1.0)
}

/// Why the batch scenes' results move in steps (the continuity audit's
/// finding, declared as the model's nature): the dust is N batches, each of
/// which is lost at the inner edge, turns into planetesimals or stays dust
/// as a whole.
const WHOLE_BATCHES: &str = "the dust is N batches, each lost at the inner edge, turned into planetesimals or left as dust \
     as a whole: fractions, loadings and radii move in steps where one batch changes its fate or its frame (about 1/N of \
     the dust mass), steps that shrink as N grows";

/// Steps of every batch scalar along every parameter: [`WHOLE_BATCHES`].
/// The audit holds each such step to it: at four times the batches the
/// step's bracket must change by less than half as much.
pub const BATCH_STEPS: Declared =
    Declared { scalar: "*", parameter: "*", kind: Irregularity::Step, why: WHOLE_BATCHES, resolution: Some("batches") };

/// A physical parameter whose change moves no batch across a fate at few
/// batches (the audit's coarse setting), so that every scalar stays exactly
/// equal while the figures change: [`WHOLE_BATCHES`].
pub const fn batch_quantised(parameter: &'static str) -> Declared {
    Declared { scalar: "*", parameter, kind: Irregularity::Ignored, why: WHOLE_BATCHES, resolution: None }
}
