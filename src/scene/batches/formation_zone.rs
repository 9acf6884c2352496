//! Scene "Formation zone" (thesis Figs. 5.9, 5.10): the outer edge of the
//! region where planetesimals form directly, against disk mass and metallicity.

use super::common::{BATCH_STEPS, BatchParams, batch_quantised, log_grid};
use crate::figure::{Axis, Figure, Scale, Series, Style};
use crate::physics::constants::AU;
use crate::scene::core::{Censored, Context, Declared, Progress, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::disk::common::DiskProfile;
use crate::scene::schema::{Choice, ParamSet};
use serde::{Deserialize, Serialize};

/// What the dashed lines of the formation zone change.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Choice)]
pub enum Contrast {
    /// A second characteristic radius, `r_c_2` (Fig. 5.9).
    #[default]
    #[choice(key = "r_c", label = "second R_c")]
    RC,
    /// The temperature halved (Fig. 5.10).
    #[choice(key = "cold", label = "cold disk (T/2)")]
    Cold,
    /// Surface density slope γ = 3/2 (Fig. 5.10).
    #[choice(key = "slope", label = "slope 3/2")]
    Slope,
    /// α = 10⁻⁵.
    #[choice(key = "alpha", label = "α = 10⁻⁵")]
    Alpha,
}

/// Parameters of the formation-zone scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The base run (disk mass, metallicity and R_c are swept).
    #[param(flatten, except("profile", "disk_mass", "metallicity", "r_c"))]
    pub run: BatchParams,
    /// first disk mass
    #[param(label = "smallest disk mass", unit = "M_sun", range(1e-3, 0.5), log, default = 0.01)]
    pub mass_min: f64,
    /// last disk mass
    #[param(label = "largest disk mass", unit = "M_sun", range(1e-3, 0.5), log, default = 0.2)]
    pub mass_max: f64,
    /// log-spaced
    #[param(label = "disk masses", range(1, 12), default = 5)]
    pub n_mass: usize,
    /// first metallicity
    #[param(label = "smallest Z₀", range(1e-3, 0.1), log, default = 0.01)]
    pub z_min: f64,
    /// last metallicity
    #[param(label = "largest Z₀", range(1e-3, 0.1), log, default = 0.05)]
    pub z_max: f64,
    /// log-spaced
    #[param(label = "metallicities", range(1, 6), default = 3)]
    pub n_z: usize,
    /// first characteristic radius
    #[param(label = "R_c (solid)", unit = "AU", range(5.0, 300.0), log, default = 30.0)]
    pub r_c_1: f64,
    /// second characteristic radius
    #[param(label = "R_c (dashed)", unit = "AU", range(5.0, 300.0), log, default = 100.0)]
    pub r_c_2: f64,
    /// what the dashed lines change (Fig. 5.9: R_c; Fig. 5.10: cold, slope; or alpha)
    ///
    /// What the dashed lines change: "r_c" (R_c = r_c_2), "cold" (temperature
    /// halved), "slope" (γ = 3/2) or "alpha" (α = 10⁻⁵); the last three keep
    /// R_c = r_c_1 (Fig. 5.10).
    #[param(label = "dashed lines")]
    pub contrast: Contrast,
}

/// The fewest batches at which each disk also runs with half as many (at
/// least 10) for the edges' resolution error.
const MIN_COMPARED: usize = 20;

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "formation-zone",
        title: "Formation zone",
        source: "Sect. 5.3.2; Figs. 5.9, 5.10",
        explanation: "The outermost radius at which batches become planetesimals within the run, against \
disk mass, for several metallicities. Solid lines use R_c; the dashed set changes one thing: a second \
R_c (Fig. 5.9), a cold disk with the temperature halved, the slope 3/2 or α = 1e-5 (Fig. 5.10). \
Massive, dust-rich disks form planetesimals further out; a cold disk nearly doubles the zone. All \
disks run in parallel, each also with half the batches: the change estimates the edges' resolution error.",
        heavy: true,
    };

    const DECLARED: &'static [Declared] = &[BATCH_STEPS, batch_quantised("cold")];

    const CENSORED: &'static [Censored] = &[
        Censored { key: "widest_zone", above: None, undefined: Some("no disk of the grid forms planetesimals") },
        Censored {
            key: "widest_zone_error",
            above: None,
            undefined: Some(
                "no disk of the grid forms planetesimals, or fewer than 20 batches (none half as many to run)",
            ),
        },
        Censored {
            key: "edge_error",
            above: None,
            undefined: Some("fewer than 20 batches: no run with half as many (10 at least) to compare with"),
        },
    ];

    /// The coarse setting (a sweep's preview, the coarse audit) runs its
    /// disks at about 120 batches in all (12 to 120 a disk). A grid of one
    /// disk runs it at 120 batches, where the Σ_d kernel keeps its width (at
    /// 40 it is widened to two batch spacings, and Fig. 5.9's widest edge
    /// came out at 29.8 AU instead of 21.4; at 120, 22.4). The window's
    /// first picture is not this ([`Scene::preview`]): the grid's edges at
    /// 12 batches a disk are up to 2–3 times the full run's.
    fn coarse(&self) -> Option<Self> {
        let p = self;
        let grid = Params { n_mass: p.n_mass.min(3), ..p.clone() };
        let mut distinct: Vec<BatchParams> = Vec::new();
        for disk in grid.disks() {
            if !distinct.contains(&disk) {
                distinct.push(disk);
            }
        }
        Some(Params { run: p.run.coarse_within(distinct.len(), 120), ..grid })
    }

    /// No separate preview: the computation offers its first stage (the
    /// final result's own runs at every other disk mass, or each disk with
    /// half the batches) as its first picture. The coarse parameters above
    /// remain the setting of a sweep's preview and the coarse audit.
    fn preview(&self) -> Option<Self> {
        None
    }

    /// The largest edge alone needs no run with half the batches.
    fn scalar(&self, key: &str, progress: &Progress) -> Option<Result<f64, SceneError>> {
        match key {
            "widest_zone" => Some(self.edges(&[self.run.batches], progress).map(|e| widest_of(&e))),
            "disks" => Some(Ok(self.disks().len() as f64)),
            _ => None,
        }
    }

    /// Computes the scene. The runs go in two stages, and the first is
    /// offered as a picture while the second computes ([`Progress::publish`]):
    /// with three disk masses or more, every other mass (the first and last
    /// always) at the full batch count, the final result's own runs at those
    /// masses; with fewer, every disk with half the batches, the final
    /// result's own resolution check. No run is made twice.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let masses = log_grid(p.mass_min, p.mass_max, p.n_mass);
        let zs = log_grid(p.z_min, p.z_max, p.n_z);
        // Every disk also runs with half the batches: the change says how far
        // the edges are from converged (it can understate it where the edge
        // still drifts with the batch count, see the README). Below
        // `MIN_COMPARED` batches there is no half as many to run: the change
        // is undefined.
        let half = p.run.batches / 2;
        let counts: &[usize] = if p.run.batches >= MIN_COMPARED { &[p.run.batches, half] } else { &[p.run.batches] };
        let disks = p.disks();
        let first = p.first_picture(masses.len(), counts.len());
        let first_runs: Vec<usize> = match first {
            FirstPicture::EveryOtherMass(ref shown) => {
                (0..disks.len()).filter(|d| shown.contains(&(d % masses.len()))).collect()
            }
            FirstPicture::HalfTheBatches => (disks.len()..2 * disks.len()).collect(),
            FirstPicture::None => Vec::new(),
        };
        let offer = |edge: &[f64]| {
            let (shown, batches, how) = match &first {
                FirstPicture::EveryOtherMass(shown) => (
                    shown.clone(),
                    p.run.batches,
                    format!("every other disk mass ({} of {})", shown.len(), masses.len()),
                ),
                FirstPicture::HalfTheBatches => ((0..masses.len()).collect(), half, "every disk".to_string()),
                FirstPicture::None => return,
            };
            let shown_masses: Vec<f64> = shown.iter().map(|&mi| masses[mi]).collect();
            // The first stage's runs are the disks shown, in the order of the grid.
            let edges: Vec<f64> = first_runs.iter().map(|&k| edge[k]).collect();
            let mut out = p.output(&shown_masses, &zs, &edges, &vec![f64::NAN; edges.len()], false);
            out.notes.insert(
                0,
                format!(
                    "first picture: {how} at {batches} batches, {} disks; the rest and the runs with half the \
                     batches follow",
                    edges.len()
                ),
            );
            progress.publish(out);
        };
        let all = p.edges_in_stages(counts, &first_runs, &offer, progress)?;
        let (edges, coarser) = all.split_at(disks.len());
        let coarser: Vec<f64> = if coarser.is_empty() { vec![f64::NAN; edges.len()] } else { coarser.to_vec() };
        Ok(p.output(&masses, &zs, edges, &coarser, p.run.batches >= MIN_COMPARED))
    }
}

/// The runs of the formation zone's first picture.
#[derive(Debug, Clone, PartialEq)]
enum FirstPicture {
    /// These mass indices (every other one, the first and last always) at
    /// the full batch count.
    EveryOtherMass(Vec<usize>),
    /// Every disk with half the batches.
    HalfTheBatches,
    /// None: fewer than three masses and no run with half the batches.
    None,
}

/// Outer edges (AU) of the runs this process has made, by the whole
/// configuration of the run (`BatchConfig`'s `Debug` text, every number to
/// the last digit): a run depends on nothing else, so a parameter that does
/// not reach the run (a grid point the grid does not use, a monomer property
/// the batch model does not read) costs no run when "what matters", a sweep
/// or the window asks again. At most 4096 edges are kept; the memory starts
/// afresh when full. The WebAssembly module has none (it keeps within its
/// size budget without the `Debug` text of a configuration): the browser
/// runs each edge again.
#[cfg(not(target_arch = "wasm32"))]
mod edge_memory {
    use super::BatchParams;
    use std::collections::HashMap;
    use std::sync::{Mutex, OnceLock};

    fn memory() -> &'static Mutex<HashMap<String, f64>> {
        static MEMORY: OnceLock<Mutex<HashMap<String, f64>>> = OnceLock::new();
        MEMORY.get_or_init(Default::default)
    }

    fn key(run: &BatchParams) -> String {
        format!("{:?}", run.config())
    }

    /// The edge of an earlier run with the same configuration, AU.
    pub fn recall(run: &BatchParams) -> Option<f64> {
        memory().lock().ok()?.get(&key(run)).copied()
    }

    /// Keeps the edge (AU) of a finished run.
    pub fn keep(run: &BatchParams, edge: f64) {
        if let Ok(mut memory) = memory().lock() {
            if memory.len() >= 4096 {
                memory.clear();
            }
            memory.insert(key(run), edge);
        }
    }
}

/// The WebAssembly module's stand-in: nothing is remembered.
#[cfg(target_arch = "wasm32")]
mod edge_memory {
    use super::BatchParams;

    /// Always `None`.
    pub fn recall(_: &BatchParams) -> Option<f64> {
        None
    }

    /// Keeps nothing.
    pub fn keep(_: &BatchParams, _: f64) {}
}

/// The largest edge of a grid, AU; NaN (undefined) where no disk of the grid
/// forms planetesimals.
fn widest_of(edges: &[f64]) -> f64 {
    Some(edges.iter().copied().fold(0.0, f64::max)).filter(|&r| r > 0.0).unwrap_or(f64::NAN)
}

impl Params {
    /// The run of every disk of the grid: both disk sets (solid, then
    /// dashed), each metallicity, each disk mass.
    fn disks(&self) -> Vec<BatchParams> {
        let p = self;
        let masses = log_grid(p.mass_min, p.mass_max, p.n_mass);
        let zs = log_grid(p.z_min, p.z_max, p.n_z);
        let mut disks = Vec::with_capacity(2 * zs.len() * masses.len());
        for c in 0..2 {
            for &z in &zs {
                for &m in &masses {
                    let mut b = p.run.clone();
                    b.disk.profile = DiskProfile::PowerLaw;
                    b.disk.disk_mass = m;
                    b.disk.metallicity = z;
                    b.disk.r_c = p.r_c_1;
                    if c == 1 {
                        match p.contrast {
                            Contrast::Cold => b.disk.cold = !b.disk.cold,
                            Contrast::Slope => b.disk.slope = 1.5,
                            Contrast::Alpha => b.disk.alpha = 1e-5,
                            Contrast::RC => b.disk.r_c = p.r_c_2,
                        }
                    }
                    disks.push(b);
                }
            }
        }
        disks
    }

    /// The runs of the first picture for a grid of `n_mass` masses and
    /// `n_counts` batch counts (2: each disk also with half the batches).
    fn first_picture(&self, n_mass: usize, n_counts: usize) -> FirstPicture {
        if n_mass >= 3 {
            let mut shown: Vec<usize> = (0..n_mass).step_by(2).collect();
            if shown.last() != Some(&(n_mass - 1)) {
                shown.push(n_mass - 1);
            }
            FirstPicture::EveryOtherMass(shown)
        } else if n_counts == 2 {
            FirstPicture::HalfTheBatches
        } else {
            FirstPicture::None
        }
    }

    /// The scene's output for edges (AU) at `masses` (the disks in the order
    /// of [`Params::disks`], each set and metallicity over `masses`), with
    /// the edges of the runs with half the batches in `coarser` (NaN where
    /// not run) and whether they were run (`compared`).
    fn output(&self, masses: &[f64], zs: &[f64], edges: &[f64], coarser: &[f64], compared: bool) -> SceneOutput {
        let p = self;
        let mut fig = Figure::new(
            "formation-zone",
            "Outer edge of planetesimal formation (Figs. 5.9, 5.10)",
            Axis::log("disk mass", "M☉"),
            Axis::linear("outer edge", "AU"),
        )
        // Metallicity is the colour (a colour bar), the disk set the line style.
        .family("metallicity Z₀", "", Scale::Log);
        let mut scalars = Vec::new();
        for c in 0..2 {
            for (zi, z) in zs.iter().enumerate() {
                let pts: Vec<[f64; 2]> = masses
                    .iter()
                    .enumerate()
                    .map(|(mi, m)| [*m, edges[(c * zs.len() + zi) * masses.len() + mi]])
                    .collect();
                let label = match (c, p.contrast) {
                    (1, Contrast::Cold) => format!("R_c = {} AU, cold", crate::figure::human(p.r_c_1)),
                    (1, Contrast::Slope) => format!("R_c = {} AU, slope 3/2", crate::figure::human(p.r_c_1)),
                    (1, Contrast::Alpha) => format!("R_c = {} AU, α = 10⁻⁵", crate::figure::human(p.r_c_1)),
                    (1, _) => format!("R_c = {} AU", crate::figure::human(p.r_c_2)),
                    _ => format!("R_c = {} AU", crate::figure::human(p.r_c_1)),
                };
                fig = fig.with(
                    Series::new(
                        format!("Z₀ = {}, {label}", crate::figure::human(*z)),
                        pts,
                        if c == 0 { Style::Line } else { Style::Dashed },
                        zi,
                    )
                    .at(*z)
                    .keyed(label),
                );
            }
        }
        let widest = widest_of(edges);
        let widest_error = (widest - widest_of(coarser)).abs();
        let largest_error =
            if compared { edges.iter().zip(coarser).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) } else { f64::NAN };
        scalars.push(Scalar { key: "widest_zone", label: "largest outer edge on the grid", value: widest, unit: "AU" });
        scalars.push(Scalar {
            key: "widest_zone_error",
            label: "its change with half the batches",
            value: if widest.is_nan() { f64::NAN } else { widest_error },
            unit: "AU",
        });
        scalars.push(Scalar {
            key: "edge_error",
            label: "largest change with half the batches",
            value: largest_error,
            unit: "AU",
        });
        scalars.push(Scalar { key: "disks", label: "disks run", value: edges.len() as f64, unit: "" });
        SceneOutput { scalars, figures: vec![fig], ..Default::default() }
    }

    /// The outer edge of every disk of [`Params::disks`], AU (0 where none
    /// forms), at each batch count of `counts` in turn. A disk that equals
    /// another (the dashed set with the solid set's R_c, say) runs once.
    fn edges(&self, counts: &[usize], progress: &Progress) -> Result<Vec<f64>, SceneError> {
        self.edges_in_stages(counts, &[], &|_| {}, progress)
    }

    /// As [`Params::edges`], in two stages: first the runs numbered in
    /// `first` (in the order of `edges`' result), then `offer` is given
    /// their edges (by the same numbers; NaN for the rest), then the rest. Each stage's
    /// distinct runs are one map of units (a browser shares them among its
    /// workers).
    fn edges_in_stages(
        &self,
        counts: &[usize],
        first: &[usize],
        offer: &dyn Fn(&[f64]),
        progress: &Progress,
    ) -> Result<Vec<f64>, SceneError> {
        let disks = self.disks();
        let runs: Vec<BatchParams> = counts
            .iter()
            .flat_map(|&batches| disks.iter().map(move |d| BatchParams { batches, ..d.clone() }))
            .collect();
        let mut distinct: Vec<BatchParams> = Vec::new();
        let mut which: Vec<usize> = vec![0; runs.len()];
        let order = first.iter().copied().chain((0..runs.len()).filter(|k| !first.contains(k)));
        let mut staged = 0;
        for (n, k) in order.enumerate() {
            which[k] = match distinct.iter().position(|d| *d == runs[k]) {
                Some(i) => i,
                None => {
                    distinct.push(runs[k].clone());
                    distinct.len() - 1
                }
            };
            if n + 1 == first.len() {
                staged = distinct.len();
            }
        }
        let done = std::sync::atomic::AtomicUsize::new(0);
        let total = distinct.len();
        let edge_of = |b: &BatchParams| {
            if let Some(edge) = edge_memory::recall(b) {
                let finished = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
                progress.set(finished as f64 / total.max(1) as f64);
                return Ok(edge);
            }
            let edge = b.edge_in_sweep(progress, &done, total)? / AU;
            edge_memory::keep(b, edge);
            Ok(edge)
        };
        // Each disk is a unit of its own: a browser shares them among its workers.
        let mut edges: Vec<f64> = progress.units(&distinct[..staged], edge_of)?;
        // Every run of the first stage is done, here or (a browser's later
        // rounds) by the processes that shared it, each of which counts its
        // share: progress never goes back.
        let credit = staged / progress.sharers();
        if done.fetch_max(credit, std::sync::atomic::Ordering::Relaxed) < credit {
            progress.set(credit as f64 / total.max(1) as f64);
        }
        if staged > 0 && staged < total {
            let known: Vec<f64> = which.iter().map(|&i| edges.get(i).copied().unwrap_or(f64::NAN)).collect();
            offer(&known);
        }
        edges.extend(progress.units(&distinct[staged..], edge_of)?);
        Ok(which.into_iter().map(|i| edges[i]).collect())
    }
}
