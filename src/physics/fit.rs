//! Fitting γ, T_vis and Y to measured coefficients of restitution, as in
//! thesis Sect. 2.4.1: χ² of (2.31) on a logarithmic grid, the uncertainty of
//! each parameter as the range over which χ² stays below twice its minimum,
//! then a local refinement of the best grid point.

use super::PhysicsError;
use super::collision::{Options, Setup, collide};
use super::experiments::Bounded;
use super::plasticity::{e_combined, e_plastic, yield_velocity};
use crate::parallel::prelude::*;
use serde::{Deserialize, Serialize};
use std::sync::atomic::{AtomicUsize, Ordering};

/// One measured collision.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Measurement {
    /// Impact velocity, m s⁻¹.
    pub velocity: f64,
    /// Measured coefficient of restitution.
    pub restitution: f64,
    /// Its uncertainty, if given (shown, not used by the χ² of (2.31)).
    #[serde(default)]
    pub uncertainty: Option<f64>,
}

/// The search over one parameter: a log-spaced grid, or a fixed value.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Search {
    /// Smallest value (SI).
    pub min: f64,
    /// Largest value (SI).
    pub max: f64,
    /// Grid points (≥ 2 unless fixed).
    pub points: usize,
    /// Hold the parameter at this value instead.
    pub fixed: Option<f64>,
}

impl Search {
    /// The grid values.
    pub fn values(&self) -> Vec<f64> {
        match self.fixed {
            Some(x) => vec![x],
            None => {
                let n = self.points.max(2);
                let (a, b) = (self.min.ln(), self.max.ln());
                (0..n).map(|i| (a + (b - a) * i as f64 / (n - 1) as f64).exp()).collect()
            }
        }
    }
}

/// Why a fit failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitError {
    /// The model failed.
    #[error(transparent)]
    Physics(#[from] PhysicsError),
    /// No usable data.
    #[error("no measurements to fit")]
    NoData,
    /// A search range is empty or not positive.
    #[error("{0}: the search range must satisfy 0 < min < max")]
    BadRange(&'static str),
    /// The caller cancelled.
    #[error("cancelled")]
    Cancelled,
}

/// The result of a fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// Grid values of γ (J m⁻²), T_vis (s) and Y (Pa).
    pub grids: [Vec<f64>; 3],
    /// χ² on the grid, index `(i·n_T + j)·n_Y + k`.
    pub chi2: Vec<f64>,
    /// Best grid point (γ, T_vis, Y).
    pub grid_best: [f64; 3],
    /// Refined best fit (γ, T_vis, Y).
    pub best: [f64; 3],
    /// χ² of the refined best fit.
    pub chi2_min: f64,
    /// Each parameter's range with χ² < 2 χ²_min, as a value or a one-sided limit.
    pub ranges: [Bounded; 3],
    /// Collisions integrated.
    pub collisions: usize,
    /// Number of measurements fitted.
    pub points: usize,
    /// Number of fitted (not fixed) parameters.
    pub free: usize,
}

impl Fit {
    /// Whether there are no more measurements than free parameters: any
    /// such data can be matched exactly, so the fit determines nothing.
    pub fn under_determined(&self) -> bool {
        self.free > 0 && self.points <= self.free
    }

    /// A warning for an under-determined fit, naming the counts.
    pub fn warning(&self) -> Option<String> {
        self.under_determined().then(|| {
            format!(
                "under-determined fit: {} measurement{} for {} free parameter{}; any such data can be matched, \
                 so no range is reported. Add measurements or hold parameters fixed.",
                self.points,
                if self.points == 1 { "" } else { "s" },
                self.free,
                if self.free == 1 { "" } else { "s" },
            )
        })
    }

    /// χ² at grid indices (i, j, k).
    pub fn chi2_at(&self, i: usize, j: usize, k: usize) -> f64 {
        self.chi2[(i * self.grids[1].len() + j) * self.grids[2].len() + k]
    }
}

/// The model restitution e (2.30) of each measurement for γ, T_vis, Y.
pub fn model_restitution(
    setup_for: &(dyn Fn(f64, f64, Option<f64>) -> Option<Setup> + Sync),
    params: [f64; 3],
    velocities: &[f64],
    opts: &Options,
) -> Result<Vec<f64>, PhysicsError> {
    let setup = setup_for(params[0], params[1], Some(params[2])).ok_or(PhysicsError::InvalidParameter {
        name: "material",
        value: 0.0,
        reason: "unknown material",
    })?;
    let v_y = yield_velocity(&setup.pair, params[2]);
    velocities
        .iter()
        .map(|&v| {
            let e_a = collide(&setup, v, opts)?.e_adhesive;
            Ok(if e_a > 0.0 { e_combined(e_a, e_plastic(v, v_y)) } else { 0.0 })
        })
        .collect()
}

fn chi2(model: &[f64], data: &[Measurement]) -> f64 {
    model.iter().zip(data).map(|(m, d)| (d.restitution - m).powi(2)).sum::<f64>() / data.len() as f64
}

/// Fits γ, T_vis and Y. `setup_for(γ, T_vis, Y)` builds the model for the
/// fixed materials and geometry; `progress(fraction)` returns false to cancel.
pub fn fit(
    setup_for: &(dyn Fn(f64, f64, Option<f64>) -> Option<Setup> + Sync),
    data: &[Measurement],
    searches: [Search; 3],
    opts: &Options,
    progress: &(dyn Fn(f64) -> bool + Sync),
) -> Result<Fit, FitError> {
    if data.is_empty() {
        return Err(FitError::NoData);
    }
    for (s, name) in searches.iter().zip(["gamma", "t_vis", "yield_strength"]) {
        let ok = match s.fixed {
            Some(x) => x.is_finite() && x > 0.0,
            None => s.min > 0.0 && s.max > s.min && s.max.is_finite(),
        };
        if !ok {
            return Err(FitError::BadRange(name));
        }
    }
    let grids = [searches[0].values(), searches[1].values(), searches[2].values()];
    let (ng, nt, ny) = (grids[0].len(), grids[1].len(), grids[2].len());
    let velocities: Vec<f64> = data.iter().map(|d| d.velocity).collect();
    let pairs: Vec<(usize, usize)> = (0..ng).flat_map(|i| (0..nt).map(move |j| (i, j))).collect();
    let done = AtomicUsize::new(0);
    // e_A depends on γ and T_vis only; Y enters through the closed-form e_P.
    let rows: Vec<Vec<f64>> = pairs
        .par_iter()
        .map(|&(i, j)| {
            if !progress(done.load(Ordering::Relaxed) as f64 / pairs.len() as f64) {
                return Err(FitError::Cancelled);
            }
            let setup = setup_for(grids[0][i], grids[1][j], None).ok_or(FitError::BadRange("materials"))?;
            let e_a: Vec<f64> =
                velocities.iter().map(|&v| collide(&setup, v, opts).map(|c| c.e_adhesive)).collect::<Result<_, _>>()?;
            let row = grids[2]
                .iter()
                .map(|&y| {
                    let v_y = yield_velocity(&setup.pair, y);
                    let model: Vec<f64> = e_a
                        .iter()
                        .zip(&velocities)
                        .map(|(&ea, &v)| if ea > 0.0 { e_combined(ea, e_plastic(v, v_y)) } else { 0.0 })
                        .collect();
                    chi2(&model, data)
                })
                .collect();
            done.fetch_add(1, Ordering::Relaxed);
            Ok(row)
        })
        .collect::<Result<_, FitError>>()?;
    let chi2_grid: Vec<f64> = rows.into_iter().flatten().collect();
    let (best_index, &grid_min) =
        chi2_grid.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)).ok_or(FitError::NoData)?;
    let (i, j, k) = (best_index / (nt * ny), (best_index / ny) % nt, best_index % ny);
    let grid_best = [grids[0][i], grids[1][j], grids[2][k]];
    let mut collisions = ng * nt * data.len();

    // Local refinement in log space over the free parameters, kept in the grid box.
    let free: Vec<usize> = (0..3).filter(|&p| searches[p].fixed.is_none()).collect();
    let bounds: Vec<(f64, f64)> = free.iter().map(|&p| (searches[p].min.ln(), searches[p].max.ln())).collect();
    let to_params = |x: &[f64]| {
        let mut p = grid_best;
        for (n, &f) in free.iter().enumerate() {
            p[f] = x[n].clamp(bounds[n].0, bounds[n].1).exp();
        }
        p
    };
    let objective = |x: &[f64]| -> f64 {
        model_restitution(setup_for, to_params(x), &velocities, opts).map_or(f64::INFINITY, |m| chi2(&m, data))
    };
    let (mut best, mut chi2_min) = (grid_best, grid_min);
    if !free.is_empty() && progress(1.0) {
        let start: Vec<f64> = free.iter().map(|&p| grid_best[p].ln()).collect();
        let steps: Vec<f64> = free
            .iter()
            .map(|&p| {
                let n = grids[p].len().max(2) as f64;
                (searches[p].max.ln() - searches[p].min.ln()) / (n - 1.0) * 0.5
            })
            .collect();
        let (x, f, evaluations) = nelder_mead(&objective, &start, &steps, 120, 1e-4 * grid_min.max(1e-12));
        collisions += evaluations * data.len();
        if f < chi2_min {
            best = to_params(&x);
            chi2_min = f;
        }
    }

    // Each parameter's range: the grid points with χ² < 2 χ²_min (a projection
    // over the others), widened by a scan along the parameter from the best
    // fit (finer than the grid), each side bisected to where χ² = 2 χ²_min.
    let threshold = 2.0 * chi2_min;
    let chi2_of = |params: [f64; 3]| -> f64 {
        model_restitution(setup_for, params, &velocities, opts).map_or(f64::INFINITY, |m| chi2(&m, data))
    };
    let mut ranges = [Bounded::Below(0.0); 3];
    let under_determined = data.len() <= free.len();
    for p in 0..3 {
        if let Some(value) = searches[p].fixed {
            ranges[p] = Bounded::Fixed(value);
            continue;
        }
        if under_determined {
            ranges[p] = Bounded::Undetermined { best: best[p] };
            continue;
        }
        let mut lo = best[p];
        let mut hi = best[p];
        for (n, c) in chi2_grid.iter().enumerate() {
            if *c <= threshold {
                let idx = [n / (nt * ny), (n / ny) % nt, n % ny];
                lo = lo.min(grids[p][idx[p]]);
                hi = hi.max(grids[p][idx[p]]);
            }
        }
        let (mut open_low, mut open_high) = (false, false);
        if searches[p].fixed.is_none() {
            let (lmin, lmax) = (searches[p].min.ln(), searches[p].max.ln());
            for dir in [-1.0, 1.0] {
                let edge = if dir < 0.0 { lmin } else { lmax };
                let at = |x: f64| {
                    let mut q = best;
                    q[p] = x.exp();
                    q
                };
                let (mut inside, mut outside) = (best[p].ln(), None);
                let mut step = 0.02;
                while outside.is_none() {
                    let x = (inside + dir * step).clamp(lmin, lmax);
                    collisions += data.len();
                    if chi2_of(at(x)) > threshold {
                        outside = Some(x);
                    } else {
                        inside = x;
                        if x == edge {
                            break;
                        }
                        step *= 2.0;
                    }
                }
                if let Some(mut out) = outside {
                    for _ in 0..8 {
                        let mid = 0.5 * (inside + out);
                        collisions += data.len();
                        if chi2_of(at(mid)) > threshold { out = mid } else { inside = mid }
                    }
                } else if dir < 0.0 {
                    open_low = true;
                } else {
                    open_high = true;
                }
                if dir < 0.0 {
                    lo = lo.min(inside.exp());
                } else {
                    hi = hi.max(inside.exp());
                }
            }
            open_low |= lo <= grids[p][0] * (1.0 + 1e-9);
            open_high |= hi >= grids[p][grids[p].len() - 1] * (1.0 - 1e-9);
        }
        ranges[p] = match (open_low, open_high) {
            (false, true) => Bounded::Above(lo),
            (true, false) => Bounded::Below(hi),
            // A range of zero width (an exact fit, χ²_min = 0) is no measurement.
            _ if hi <= lo => Bounded::Undetermined { best: best[p] },
            _ => Bounded::Value { best: best[p], plus: hi - best[p], minus: best[p] - lo },
        };
    }
    Ok(Fit {
        grids,
        chi2: chi2_grid,
        grid_best,
        best,
        chi2_min,
        ranges,
        collisions,
        points: data.len(),
        free: free.len(),
    })
}

/// Minimises `f` from `start` with initial simplex steps `steps` (Nelder–Mead,
/// standard coefficients). Returns the best point, its value and the number
/// of evaluations. Written out because the problem has at most three
/// parameters and an objective that is only piecewise smooth (sticking).
pub fn nelder_mead(
    f: &dyn Fn(&[f64]) -> f64,
    start: &[f64],
    steps: &[f64],
    max_evaluations: usize,
    tolerance: f64,
) -> (Vec<f64>, f64, usize) {
    let n = start.len();
    let mut simplex: Vec<(Vec<f64>, f64)> = Vec::with_capacity(n + 1);
    simplex.push((start.to_vec(), f(start)));
    for d in 0..n {
        let mut x = start.to_vec();
        x[d] += steps[d];
        let fx = f(&x);
        simplex.push((x, fx));
    }
    let mut evaluations = n + 1;
    while evaluations < max_evaluations {
        crate::sorting::sort_by_key(&mut simplex, |a| a.1);
        if (simplex[n].1 - simplex[0].1).abs() <= tolerance {
            break;
        }
        let centroid: Vec<f64> = (0..n).map(|d| simplex[..n].iter().map(|p| p.0[d]).sum::<f64>() / n as f64).collect();
        let along =
            |t: f64| -> Vec<f64> { (0..n).map(|d| centroid[d] + t * (simplex[n].0[d] - centroid[d])).collect() };
        let xr = along(-1.0);
        let fr = f(&xr);
        evaluations += 1;
        if fr < simplex[0].1 {
            let xe = along(-2.0);
            let fe = f(&xe);
            evaluations += 1;
            simplex[n] = if fe < fr { (xe, fe) } else { (xr, fr) };
        } else if fr < simplex[n - 1].1 {
            simplex[n] = (xr, fr);
        } else {
            let xc = if fr < simplex[n].1 { along(-0.5) } else { along(0.5) };
            let fc = f(&xc);
            evaluations += 1;
            if fc < simplex[n].1.min(fr) {
                simplex[n] = (xc, fc);
            } else {
                let best = simplex[0].0.clone();
                for p in simplex.iter_mut().skip(1) {
                    let x: Vec<f64> = (0..n).map(|d| best[d] + 0.5 * (p.0[d] - best[d])).collect();
                    *p = (x.clone(), f(&x));
                    evaluations += 1;
                }
            }
        }
    }
    crate::sorting::sort_by_key(&mut simplex, |a| a.1);
    let (x, fx) = simplex.swap_remove(0);
    (x, fx, evaluations)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nelder_mead_finds_the_minimum_of_a_quadratic() {
        let f = |x: &[f64]| (x[0] - 1.0).powi(2) + 3.0 * (x[1] + 2.0).powi(2) + 0.5 * (x[2] - 0.5).powi(2);
        let (x, fx, _) = nelder_mead(&f, &[0.0, 0.0, 0.0], &[0.5, 0.5, 0.5], 2000, 1e-14);
        assert!(fx < 1e-8, "{fx}");
        assert!((x[0] - 1.0).abs() < 1e-3 && (x[1] + 2.0).abs() < 1e-3 && (x[2] - 0.5).abs() < 1e-3, "{x:?}");
    }
}
