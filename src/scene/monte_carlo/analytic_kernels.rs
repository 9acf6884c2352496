//! Scene "Kernel tests": the Monte Carlo distribution method against the
//! exact solutions of the Smoluchowski equation for the constant, linear and
//! product kernels (thesis Sect. 4.3; Ormel & Spaans 2008).

use crate::figure::{Axis, Figure, Series, Style};
use crate::parallel::prelude::*;
use crate::physics::PhysicsError;
use crate::physics::monte_carlo::{Analytic, Body, Engine, Settings};
use crate::scene::core::{Context, Progress, Scalar, Scene, SceneError, SceneInfo, SceneOutput, Seeds};
use crate::scene::quantities;
use crate::scene::schema::{Choice, ParamSet};
use serde::{Deserialize, Serialize};

/// The analytic test problem: a kernel with a known solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Choice)]
pub enum TestKernel {
    /// K = 1.
    #[default]
    #[choice(key = "constant", label = "constant K = 1")]
    Constant,
    /// K = m₁ + m₂.
    #[choice(key = "linear", label = "linear K = m₁ + m₂")]
    Linear,
    /// K = m₁m₂ (gels at t = 1).
    #[choice(key = "product", label = "product K = m₁m₂")]
    Product,
}

/// Parameters of the scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// the analytic test problem
    #[param(label = "kernel")]
    pub kernel: TestKernel,
    /// in units 1/(K₀N₀); the product kernel gels at t = 1
    #[param(label = "time t", shown("", 1.0), range(1e-3, 1e5), log, default = 1000.0)]
    pub time: f64,
    /// monomers in the simulated volume
    #[param(numerical, label = "initial particles N₀V", shown("", 1.0), range(1e3, 1e100), log, default = 1e20)]
    pub particles: f64,
    /// resolution of the distribution method (4.26)
    #[param(quantity = quantities::groups_per_decade, default = 60.0)]
    pub groups_per_decade: f64,
    /// (4.22)
    #[param(numerical, label = "sequence limit f_m", shown("", 1.0), range(0.01, 1.0), log, default = 0.1)]
    pub f_m: f64,
    /// independent seeds, run in parallel
    #[param(numerical, label = "runs", range(1.0, 64.0), default = 8)]
    pub runs: usize,
    /// runs use seed, seed + 1, …
    #[param(numerical, label = "first seed", range(0.0, 1_000_000.0), default = 1)]
    pub seed: usize,
    /// histogram
    #[param(label = "bins per decade", range(1.0, 10.0), default = 2)]
    pub bins_per_decade: usize,
    /// caps the zoom factor so that no group holds more of the total mass; 1 = (4.26) alone. 10⁻³ brings the constant and product kernels within 5 % at ~100 times the cost
    ///
    /// Largest share of the total mass one group may hold, ε_M
    /// (dimensionless, 10⁻⁴–1; default 1: no cap, the method of Sect. 4.3).
    #[param(numerical, label = "largest group mass share ε_M", shown("", 1.0), range(1e-4, 1.0), log, default = 1.0)]
    pub group_mass_cap: f64,
}

impl Params {
    fn analytic(&self) -> Analytic {
        match self.kernel {
            TestKernel::Constant => Analytic::Constant,
            TestKernel::Linear => Analytic::Linear,
            TestKernel::Product => Analytic::Product,
        }
    }
}

/// Per bin: (lower edge, upper edge, mean mass density, σ, exact).
pub type Bins = Vec<(f64, f64, f64, f64, f64)>;

/// Runs the engine and bins the mass per unit volume.
pub fn run(p: &Params, progress: &Progress) -> Result<(Bins, f64), SceneError> {
    if p.kernel == TestKernel::Product && p.time >= 1.0 {
        return Err(crate::scene::ParamError::Inconsistent(format!(
            "time = {}: the product kernel gels at t = 1, choose t < 1",
            crate::scene::spec::short(p.time)
        ))
        .into());
    }
    let kernel = p.analytic();
    let n = p.bins_per_decade.max(1) as f64;
    let done = std::sync::atomic::AtomicUsize::new(0);
    let runs: Vec<(std::collections::BTreeMap<i64, f64>, u64)> = (0..p.runs.max(1))
        .into_par_iter()
        .map(|k| {
            let settings = Settings {
                groups_per_decade: p.groups_per_decade,
                f_m: p.f_m,
                seed: (p.seed + k) as u64,
                group_mass_cap: p.group_mass_cap,
                ..Settings::default()
            };
            let mut e = Engine::new(kernel, Body { mass: 1.0, filling: 1.0 }, p.particles, p.particles, settings)
                .map_err(|e| PhysicsError::Invalid(e.to_string()))?;
            while e.time() < p.time {
                progress.check()?;
                if !e.run_until(p.time, 1000) {
                    break;
                }
            }
            let mut bins = std::collections::BTreeMap::new();
            for f in e.families() {
                *bins.entry((f.mass.log10() * n).floor() as i64).or_insert(0.0) += f.mass * f.particles() / e.volume();
            }
            let finished = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress.set(finished as f64 / p.runs.max(1) as f64);
            Ok((bins, e.events()))
        })
        .collect::<Result<_, SceneError>>()?;
    let keys: std::collections::BTreeSet<i64> = runs.iter().flat_map(|r| r.0.keys().copied()).collect();
    let count = runs.len() as f64;
    let bins = keys
        .into_iter()
        .map(|b| {
            let v: Vec<f64> = runs.iter().map(|r| r.0.get(&b).copied().unwrap_or(0.0)).collect();
            let mean = v.iter().sum::<f64>() / count;
            let sd = if v.len() > 1 {
                (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (count - 1.0)).sqrt()
            } else {
                0.0
            };
            let (lo, hi) = (10f64.powf(b as f64 / n), 10f64.powf((b + 1) as f64 / n));
            (lo, hi, mean, sd, kernel.exact_mass_between(lo, hi, p.time))
        })
        .collect();
    let events = runs.iter().map(|r| r.1 as f64).sum::<f64>() / count;
    Ok((bins, events))
}

/// Largest relative error over the bins that hold `core` of the exact mass.
pub fn core_error(bins: &Bins, core: f64) -> f64 {
    let total: f64 = bins.iter().map(|b| b.4).sum();
    let mut sorted = bins.clone();
    crate::sorting::sort_by_key(&mut sorted, |a| -a.4);
    let mut held = 0.0;
    let mut worst: f64 = 0.0;
    for b in sorted {
        if held >= core * total {
            break;
        }
        held += b.4;
        worst = worst.max((b.2 / b.4 - 1.0).abs());
    }
    worst
}

fn lowest_centre(bins: &Bins) -> f64 {
    bins.first().map_or(1.0, |b| (b.0 * b.1).sqrt())
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "kernel-tests",
        title: "Monte Carlo kernel tests",
        source: "Sect. 4.3; Ormel & Spaans (2008)",
        explanation: "The engine of the Monte Carlo scenes on problems with exact answers. Starting from N₀ \
monomers (units m₀ = 1, N₀ = 1 per unit volume), K = 1 gives N(k, t) = (t/2)^{k−1}/(1 + t/2)^{k+1}; \
K = m₁ + m₂ gives N_k = g [k(1 − g)]^{k−1} e^{−k(1−g)}/k! with g = e^{−t}; K = m₁m₂ gives \
N_k = (kt)^{k−1} e^{−kt}/(k·k!) before gelation at t = 1. Shown: the mass fraction per ln m, \
m²N(m), of the runs (mean, dashed ±1σ) and exact, and the relative error per bin. The error shrinks as \
the groups per decade w* grow; the low-mass tail stays resolved far below the peak.",
        heavy: true,
    };

    const DECLARED: &'static [crate::scene::core::Declared] = &[super::common::EVENT_COUNT];

    /// Capped runs take seconds each: first the uncapped method with at most
    /// two runs (milliseconds).
    fn coarse(&self) -> Option<Self> {
        let p = self;
        let c = Params { group_mass_cap: 1.0, runs: p.runs.min(2), ..p.clone() };
        (c != *p).then_some(c)
    }

    fn seeds(&mut self) -> Option<Seeds<'_>> {
        Some(Seeds { first: &mut self.seed, runs: &mut self.runs })
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let (bins, events) = run(p, progress)?;
        let kernel = p.analytic();
        let per_ln = |b: &(f64, f64, f64, f64, f64), v: f64| v / (b.1 / b.0).ln();
        let centre = |b: &(f64, f64, f64, f64, f64)| (b.0 * b.1).sqrt();
        let mut fig = Figure::new(
            "kernel-mass-spectrum",
            &format!("{} kernel at t = {}", Choice::key(&p.kernel), p.time),
            Axis::log("mass m/m₀", ""),
            Axis::log("m²N(m) (mass per ln m)", ""),
        );
        let mean: Vec<[f64; 2]> = bins.iter().filter(|b| b.2 > 0.0).map(|b| [centre(b), per_ln(b, b.2)]).collect();
        let exact_bins: Vec<[f64; 2]> =
            bins.iter().filter(|b| b.4 > 0.0).map(|b| [centre(b), per_ln(b, b.4)]).collect();
        fig = fig.with(Series::new("Monte Carlo", mean, Style::Points, 0)).with(Series::new(
            "exact, same bins",
            exact_bins,
            Style::Line,
            1,
        ));
        if p.runs > 1 {
            let hi = bins.iter().filter(|b| b.2 > 0.0).map(|b| [centre(b), per_ln(b, b.2 + b.3)]).collect();
            let lo = bins.iter().filter(|b| b.2 > b.3).map(|b| [centre(b), per_ln(b, b.2 - b.3)]).collect();
            fig = fig.with(Series::new("±1σ", hi, Style::Dashed, 0)).with(Series::new("", lo, Style::Dashed, 0));
        }
        // The exact k²N_k as a smooth curve where k is large enough to be continuous.
        let top = bins.last().map_or(10.0, |b| b.1) * 10.0;
        let floor = 1e-8 * bins.iter().map(|b| per_ln(b, b.4)).fold(0.0, f64::max);
        let curve: Vec<[f64; 2]> = crate::scene::core::logspace(100.0, top.max(1e3), 200)
            .into_iter()
            .map(|k| [k, kernel.exact_mass_per_ln(k, p.time)])
            .filter(|q| q[1] > floor)
            .collect();
        fig = fig.with(Series::new("exact", curve, Style::Dashed, 1));
        let mut err = Figure::new(
            "kernel-error",
            "Relative error per bin",
            Axis::log("mass m/m₀", ""),
            Axis::linear("run/exact − 1", ""),
        );
        // Bins holding at least 10⁻⁴ of the mass (further out the exact values
        // are too small for the runs to sample).
        let total: f64 = bins.iter().map(|b| b.4).sum();
        let e: Vec<[f64; 2]> =
            bins.iter().filter(|b| b.4 > 1e-4 * total && b.2 > 0.0).map(|b| [centre(b), b.2 / b.4 - 1.0]).collect();
        let bars: Vec<[f64; 2]> = bins
            .iter()
            .filter(|b| b.4 > 1e-4 * total && b.2 > 0.0 && p.runs > 1)
            .flat_map(|b| {
                let se = b.3 / (p.runs as f64).sqrt() / b.4;
                [[centre(b), b.2 / b.4 - 1.0 + se], [centre(b), b.2 / b.4 - 1.0 - se]]
            })
            .collect();
        err = err.with(Series::new("mean of the runs", e, Style::Points, 0));
        if !bars.is_empty() {
            err = err.with(Series::new("± standard error", bars, Style::Marker, 6));
        }
        err = err.with(Series::new("", vec![[lowest_centre(&bins), 0.0], [top / 10.0, 0.0]], Style::Dashed, 6));
        let peak = bins.iter().max_by(|a, b| a.2.total_cmp(&b.2)).map_or(1.0, centre);
        let lowest = bins.iter().find(|b| b.2 > 0.0).map_or(1.0, centre);
        let scalars = vec![
            Scalar {
                key: "core_error",
                label: "worst error, bins holding 0.9 of the mass",
                value: core_error(&bins, 0.9),
                unit: "",
            },
            Scalar {
                key: "decades",
                label: "decades resolved below the peak",
                value: (peak / lowest).log10(),
                unit: "",
            },
            Scalar { key: "events", label: "group events per run", value: events, unit: "" },
        ];
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig, err],
            notes: Vec::new(),
            extra: crate::scene::core::Extra::None,
        })
    }
}
