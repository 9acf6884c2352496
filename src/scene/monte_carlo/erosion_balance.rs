//! Scene "Erosion balance" (thesis Figs. 4.10, 4.11): the projectile
//! distribution of the largest body and ζ (4.34) against Ωt_s(m_max) for
//! three erosion thresholds.

use super::common::{ColumnParams, RunCache};
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::coagulation::Run;
use crate::physics::constants::YEAR;
use crate::scene::core::{Context, Scalar, Scene, SceneError, SceneInfo, SceneOutput, Seeds};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// Parameters of the scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The runs (their v_eros is replaced by the three thresholds below).
    #[param(flatten, except("v_eros"), default = ColumnParams { runs: 1, stop_mass_g: 1e18, ..ColumnParams::default() })]
    pub run: ColumnParams,
    /// erosion threshold of one set of runs
    #[param(label = "v_eros (first)", unit = "m s^-1", shown("m/s", 1.0), range(1.0, 1e4), log, default = 20.0)]
    pub v_eros_1: f64,
    /// erosion threshold of one set of runs
    #[param(label = "v_eros (second)", unit = "m s^-1", shown("m/s", 1.0), range(1.0, 1e4), log, default = 40.0)]
    pub v_eros_2: f64,
    /// erosion threshold of one set of runs
    #[param(label = "v_eros (third)", unit = "m s^-1", shown("m/s", 1.0), range(1.0, 1e4), log, default = 60.0)]
    pub v_eros_3: f64,
}

impl Params {
    fn thresholds(&self) -> [f64; 3] {
        [self.v_eros_1, self.v_eros_2, self.v_eros_3]
    }
}

/// The steady state of a run: medians of Ωt_s(m_max) and m_max over the
/// last 40 % of its duration.
pub fn steady_state(run: &Run) -> (f64, f64) {
    let t_end = run.history.last().map_or(0.0, |s| s.t);
    let tail: Vec<_> = run.history.iter().filter(|s| s.t >= 0.6 * t_end).collect();
    let median = |f: &dyn Fn(&crate::physics::coagulation::Sample) -> f64| {
        let mut v: Vec<f64> = tail.iter().map(|s| f(s)).collect();
        crate::sorting::sort_by_key(&mut v, |a| *a);
        v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
    };
    (median(&|s| s.stokes_max), median(&|s| s.m_max))
}

/// The lowest ζ and the steady state are read off a run's history, whose
/// samples include the snapshot times: more snapshots sample the same run at
/// more times (and the run pauses there to take them, so the samples set by
/// the growth of m_p fall elsewhere).
const SNAPSHOT_SAMPLES: crate::scene::core::Declared = crate::scene::core::Declared {
    scalar: "*",
    parameter: "snapshots",
    kind: crate::scene::core::Irregularity::Moves,
    why: "the lowest ζ and the steady state are taken over the run's history, which is also sampled at every snapshot",
    resolution: None,
};

/// The mean of `values` over the runs (NaN for none), as the other column
/// scenes average their scalars over the runs.
fn mean(values: impl ExactSizeIterator<Item = f64>) -> f64 {
    let n = values.len();
    if n == 0 { f64::NAN } else { values.sum::<f64>() / n as f64 }
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "erosion-balance",
        title: "Erosion balance",
        source: "Sect. 4.4.2; Figs. 4.10, 4.11",
        explanation: "Why erosion stops the largest bodies. The projectile distribution of the largest body m_max \
gives, for every projectile mass, the rate at which collisions change m_max: positive where projectiles \
stick, negative where projectiles below R_crit = 10⁻² m_max hit faster than v_eros and excavate \
ε_eros = c₁ v/v_eros projectile masses (4.13). ζ = (ΣC₊ − ΣC₋)/(ΣC₊ + ΣC₋) (4.34) is 1 without erosion, \
    0 at balance, −1 for erosion only. Plotted against Ωt_s(m_max) for three thresholds: at 20 m/s ζ turns \
negative near Ωt_s ~ 1 and the largest bodies settle into a steady state; at 40 m/s they reach ~10× larger \
masses first; at 60 m/s erosion is never strong enough to stop growth.",
        heavy: true,
    };

    const DECLARED: &'static [crate::scene::core::Declared] = super::common::column_declared![SNAPSHOT_SAMPLES];
    const PAUSABLE: bool = true;

    /// The runs at w* ≤ 10, at most two seeds and 0.2 million events a run.
    fn coarse(&self) -> Option<Self> {
        Some(Params { run: self.run.coarse()?, ..self.clone() })
    }

    fn seeds(&mut self) -> Option<Seeds<'_>> {
        Some(self.run.seeds())
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let cache: &mut RunCache = ctx.caches.get();
        // The three thresholds run side by side; cached sets are reused.
        let params: Vec<ColumnParams> =
            p.thresholds().iter().map(|&v| ColumnParams { v_eros: v, ..p.run.clone() }).collect();
        let missing: Vec<&ColumnParams> = params.iter().filter(|q| !cache.contains(q)).collect();
        // Every run of every threshold is a unit of its own: a browser shares
        // them among its workers, and natively they take turns on the cores.
        let numbered: Vec<(&ColumnParams, usize)> =
            missing.iter().flat_map(|q| (0..q.runs.max(1)).map(move |s| (*q, s))).collect();
        let fractions: Vec<std::sync::atomic::AtomicU32> =
            numbered.iter().map(|_| std::sync::atomic::AtomicU32::new(0)).collect();
        // Live view: every threshold's first run so far (cached ones complete).
        let so_far: std::sync::Mutex<Vec<(f64, Arc<Vec<Run>>)>> = std::sync::Mutex::new(
            p.thresholds()
                .into_iter()
                .zip(&params)
                .map(|(v, q)| {
                    let done = if cache.contains(q) { cache.get(q, progress).ok() } else { None };
                    (v, done.unwrap_or_default())
                })
                .collect(),
        );
        let units: Vec<usize> = (0..numbered.len()).collect();
        let fresh: Vec<Run> = progress.units_longest_first(&units, |&u, turn| {
            let (q, s) = numbered[u];
            let cfg = q.config()?;
            let slot = params.iter().position(|x| x == q).unwrap_or(0);
            let observe = |run: &Run| {
                if let Ok(mut sets) = so_far.lock() {
                    if let Some(set) = sets.get_mut(slot) {
                        set.1 = Arc::new(vec![run.clone()]);
                    }
                    let mut out = output(p, &sets);
                    let t = run.history.last().map_or(0.0, |s| s.t) / YEAR;
                    out.notes.insert(
                        0,
                        format!(
                            "running: v_eros = {} m/s at {} yr (live view)",
                            crate::figure::human(q.v_eros),
                            crate::figure::human(t)
                        ),
                    );
                    progress.publish(out);
                }
            };
            let run = cfg.run_number(
                s,
                &|_, f| {
                    turn.tick(f);
                    fractions[u].store((f * 1e6) as u32, std::sync::atomic::Ordering::Relaxed);
                    let sum: f64 =
                        fractions.iter().map(|a| a.load(std::sync::atomic::Ordering::Relaxed) as f64 / 1e6).sum();
                    progress.set(sum / fractions.len() as f64);
                    progress.wait_while_paused();
                    !progress.cancelled()
                },
                &observe,
            )?;
            progress.check()?;
            Ok(run)
        })?;
        let mut fresh = fresh.into_iter();
        for q in missing {
            let runs: Vec<Run> = fresh.by_ref().take(q.runs.max(1)).collect();
            cache.insert(q.clone(), runs);
        }
        let mut sets: Vec<(f64, Arc<Vec<Run>>)> = Vec::new();
        for (v, q) in p.thresholds().into_iter().zip(&params) {
            sets.push((v, cache.get(q, progress)?));
        }
        Ok(output(p, &sets))
    }
}

/// The figures, scalars and notes of runs for each threshold (v_eros, runs).
fn output(p: &Params, sets: &[(f64, Arc<Vec<Run>>)]) -> SceneOutput {
    let mut zeta = Figure::new(
        "zeta",
        "ζ of the largest body against its Stokes number",
        Axis::log("Ωt_s(m_max)", ""),
        Axis::linear("ζ (4.34)", ""),
    );
    let mut scalars = Vec::new();
    let keys =
        [("st_1", "m_max_1", "zeta_min_1"), ("st_2", "m_max_2", "zeta_min_2"), ("st_3", "m_max_3", "zeta_min_3")];
    for (k, (v, runs)) in sets.iter().enumerate() {
        for (j, r) in runs.iter().enumerate() {
            let name = if j == 0 { format!("v_eros = {} m/s", crate::figure::human(*v)) } else { String::new() };
            let pts = r.history.iter().map(|s| [s.stokes_max, s.zeta]).collect();
            zeta = zeta.with(Series::new(name, pts, Style::Line, k));
        }
        if let Some(r) = runs.first() {
            let (st, _) = steady_state(r);
            zeta = zeta.with(Series::new("", vec![[st, r.history.last().map_or(1.0, |s| s.zeta)]], Style::Marker, k));
            // Over several runs, the mean of the runs' values.
            let steady: Vec<(f64, f64)> = runs.iter().map(steady_state).collect();
            let st = mean(steady.iter().map(|s| s.0));
            let m = mean(steady.iter().map(|s| s.1));
            let zmin = mean(runs.iter().map(|r| r.history.iter().map(|s| s.zeta).fold(1.0, f64::min)));
            scalars.push(Scalar { key: keys[k].0, label: "steady Ωt_s(m_max)", value: st, unit: "" });
            scalars.push(Scalar { key: keys[k].1, label: "steady m_max", value: m, unit: "kg" });
            scalars.push(Scalar { key: keys[k].2, label: "lowest ζ", value: zmin, unit: "" });
        }
    }
    scalars.push(super::common::at_event_limit(sets.iter().flat_map(|(_, runs)| runs.iter())));
    // ζ = 0, where gains and losses balance, across the Stokes numbers
    // reached: the axis spans growth and erosion from the first live view on.
    let reached = sets.iter().flat_map(|(_, runs)| runs.iter()).flat_map(|r| r.history.iter()).map(|s| s.stokes_max);
    let (lo, hi) = reached.filter(|s| *s > 0.0).fold((f64::INFINITY, 0.0f64), |(lo, hi), s| (lo.min(s), hi.max(s)));
    if lo < hi {
        zeta = zeta.with(Series::new("ζ = 0: gain and loss balance", vec![[lo, 0.0], [hi, 0.0]], Style::Dashed, 6));
    }
    let mut proj = Figure::new(
        "projectile-distribution",
        &format!("Projectile distribution of m_max (v_eros = {} m/s)", p.v_eros_1),
        Axis::log("projectile mass", "g"),
        Axis::linear("share of |dm_max/dt|", ""),
    );
    if let Some(r) = sets.first().and_then(|s| s.1.first()) {
        for (k, snap) in r.snapshots.iter().enumerate() {
            let norm: f64 = snap.projectiles.iter().map(|q| q.1.abs()).sum();
            if norm > 0.0 {
                let pts = snap.projectiles.iter().map(|q| [q.0 * 1e3, q.1 / norm]).collect();
                let label = format!(
                    "{} yr, Ωt_s = {}, ζ = {}",
                    crate::figure::human(snap.t / YEAR),
                    crate::figure::human(snap.sample.stokes_max),
                    crate::figure::human(snap.sample.zeta)
                );
                proj = proj.with(Series::new(label, pts, Style::Points, k));
            }
        }
    }
    let mut notes = Vec::new();
    for (v, runs) in sets {
        for line in super::common::endings(runs) {
            notes.push(format!("v_eros = {} m/s, {line}", crate::figure::human(*v)));
        }
    }
    SceneOutput {
        warnings: Vec::new(),
        scalars,
        figures: vec![zeta, proj],
        notes,
        extra: crate::scene::core::Extra::None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scene declares what every column declares and the snapshots'
    /// share in its history.
    #[test]
    fn the_scene_declares_what_every_column_declares() {
        let own = super::super::common::declared_beyond_column(<Params as Scene>::DECLARED);
        assert_eq!(own, [SNAPSHOT_SAMPLES]);
    }

    #[test]
    fn the_mean_is_over_the_runs() {
        assert_eq!(mean([3.0, 1.0, 2.0].into_iter()), 2.0);
        assert_eq!(mean([4.0, 1.0].into_iter()), 2.5);
        assert!(mean(std::iter::empty()).is_nan());
    }
}
