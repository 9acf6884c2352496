//! Global sensitivity analysis over parameter ranges: Morris's elementary
//! effects (μ, μ*, σ) and Sobol' variance-based indices (first-order, total
//! and, on request, second-order, with bootstrap confidence intervals).
//!
//! Pure computation: a design of points in the unit hypercube
//! ([`morris_design`], [`sobol_design`]), mapped onto the factors' ranges
//! ([`Factor::value`]), and the analysis of the outputs computed there
//! ([`morris`], [`sobol`]). The designs and estimators are those of SALib
//! (Herman & Usher 2017), row for row, so that SALib analyses the same
//! samples to the same indices:
//!
//! - Morris (1991): `r` trajectories of `d + 1` points on a `p`-level grid,
//!   each step moving one factor by Δ = p / (2(p − 1)); μ, μ* and σ
//!   (Campolongo et al. 2007) of the elementary effects, in output units per
//!   whole range of the factor.
//! - Saltelli (2002, 2010): matrices A and B from one Owen-scrambled Sobol'
//!   sequence of 2d dimensions (Burley 2020, the `sobol_burley` crate), and
//!   for each factor A with that factor's column from B (and, for
//!   second-order indices, B with A's); first-order indices by Saltelli et
//!   al.'s (2010) estimator, total indices by Jansen's (1999), second-order
//!   by Saltelli's (2002), each over the outputs standardised to zero mean
//!   and unit variance.
//!
//! Undefined outputs (NaN, a computation that failed) are counted and left
//! out by a stated rule: an elementary effect that needs one is dropped;
//! a Sobol' base sample with one among its runs is dropped whole (its A, B
//! and mixed rows together), so the estimators stay paired.

use rand::{Rng, SeedableRng};

/// A factor varied over a range, uniform in the value or in its logarithm.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Factor {
    /// The parameter's key.
    pub key: String,
    /// Uniform in the logarithm.
    pub log: bool,
    /// Lower end, SI.
    pub from: f64,
    /// Upper end, SI.
    pub to: f64,
}

impl Factor {
    /// The value at the unit coordinate `u` (0 at `from`, 1 at `to`).
    /// The ends are exact, and no rounding leaves the range.
    pub fn value(&self, u: f64) -> f64 {
        let x = if u <= 0.0 {
            self.from
        } else if u >= 1.0 {
            self.to
        } else if self.log {
            (self.from.ln() + u * (self.to.ln() - self.from.ln())).exp()
        } else {
            self.from + u * (self.to - self.from)
        };
        x.clamp(self.from, self.to)
    }
}

/// Why a design cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DesignError {
    /// No factors.
    #[error("nothing to vary")]
    NoFactors,
    /// Too many factors for the sequence (Sobol': 2d ≤ 256).
    #[error("{0} factors: at most 128 for Sobol' indices")]
    TooManyFactors(usize),
    /// A count out of its range.
    #[error("{what} = {value}: {expected}")]
    Count {
        /// Which count.
        what: &'static str,
        /// Its value.
        value: usize,
        /// What it must be.
        expected: &'static str,
    },
}

/// Morris's step in the unit hypercube for `levels` levels: p / (2(p − 1)).
pub fn morris_delta(levels: usize) -> f64 {
    levels as f64 / (2.0 * (levels as f64 - 1.0))
}

/// `trajectories` Morris trajectories of `d + 1` points each, in the unit
/// hypercube on a `levels`-level grid (`levels` even), from seed `seed`.
/// Consecutive points of a trajectory differ in one factor by ±Δ.
pub fn morris_design(d: usize, trajectories: usize, levels: usize, seed: u64) -> Result<Vec<Vec<f64>>, DesignError> {
    if d == 0 {
        return Err(DesignError::NoFactors);
    }
    if levels < 2 || !levels.is_multiple_of(2) {
        return Err(DesignError::Count { what: "levels", value: levels, expected: "an even number, at least 2" });
    }
    if trajectories < 2 {
        return Err(DesignError::Count { what: "trajectories", value: trajectories, expected: "at least 2" });
    }
    let delta = morris_delta(levels);
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let mut rows = Vec::with_capacity(trajectories * (d + 1));
    // Starting levels from which a step of +Δ stays inside [0, 1].
    let starts = levels / 2;
    for _ in 0..trajectories {
        let base: Vec<f64> = (0..d).map(|_| rng.random_range(0..starts) as f64 / (levels as f64 - 1.0)).collect();
        let signs: Vec<f64> = (0..d).map(|_| if rng.random::<bool>() { 1.0 } else { -1.0 }).collect();
        let mut order: Vec<usize> = (0..d).collect();
        for i in (1..d).rev() {
            order.swap(i, rng.random_range(0..=i));
        }
        // B* = (x* + Δ/2 ((2B − J) D* + J)) P*: row k has its first k factors
        // of the permuted order stepped.
        for k in 0..=d {
            let mut row = vec![0.0; d];
            for (slot, &factor) in order.iter().enumerate() {
                let b = if slot < k { 1.0 } else { 0.0 };
                row[factor] = base[factor] + 0.5 * delta * ((2.0 * b - 1.0) * signs[factor] + 1.0);
            }
            rows.push(row);
        }
    }
    Ok(rows)
}

/// Morris's measures of one factor.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct MorrisIndex {
    /// Mean elementary effect μ.
    pub mu: f64,
    /// Mean absolute elementary effect μ*.
    pub mu_star: f64,
    /// Standard deviation σ of the elementary effects.
    pub sigma: f64,
    /// Half-width of μ*'s bootstrap confidence interval.
    pub mu_star_conf: f64,
    /// Elementary effects used.
    pub effects: usize,
    /// Elementary effects left out (an undefined output at either end).
    pub dropped: usize,
}

/// The standard normal quantile of a two-sided 95 % interval.
pub const Z95: f64 = 1.959_963_984_540_054;

/// Morris's measures of each of `d` factors from the outputs `y` at the
/// points of [`morris_design`] (`design`, in the unit hypercube, the same
/// order). Effects are output units per whole range of the factor. μ*'s
/// interval comes from `resamples` bootstrap resamples of the effects.
pub fn morris(design: &[Vec<f64>], y: &[f64], d: usize, resamples: usize, seed: u64) -> Vec<MorrisIndex> {
    let mut effects: Vec<Vec<f64>> = vec![Vec::new(); d];
    let mut dropped = vec![0usize; d];
    for (t, pts) in design.chunks(d + 1).enumerate() {
        for k in 0..pts.len().saturating_sub(1) {
            let (a, b) = (&pts[k], &pts[k + 1]);
            let Some(i) = (0..d).find(|&i| a[i] != b[i]) else { continue };
            let step = b[i] - a[i];
            let (ya, yb) = (y[t * (d + 1) + k], y[t * (d + 1) + k + 1]);
            if ya.is_finite() && yb.is_finite() {
                effects[i].push((yb - ya) / step);
            } else {
                dropped[i] += 1;
            }
        }
    }
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    effects
        .iter()
        .zip(dropped)
        .map(|(ee, dropped)| {
            let n = ee.len();
            let mean = |v: &mut dyn Iterator<Item = f64>| {
                let (s, c) = v.fold((0.0, 0usize), |(s, c), x| (s + x, c + 1));
                if c == 0 { f64::NAN } else { s / c as f64 }
            };
            let mu = mean(&mut ee.iter().copied());
            let mu_star = mean(&mut ee.iter().map(|x| x.abs()));
            let sigma = if n > 1 {
                (ee.iter().map(|x| (x - mu).powi(2)).sum::<f64>() / (n as f64 - 1.0)).sqrt()
            } else {
                f64::NAN
            };
            let boot: Vec<f64> = (0..resamples)
                .map(|_| {
                    if n == 0 {
                        return f64::NAN;
                    }
                    (0..n).map(|_| ee[rng.random_range(0..n)].abs()).sum::<f64>() / n as f64
                })
                .collect();
            MorrisIndex { mu, mu_star, sigma, mu_star_conf: Z95 * std_dev(&boot), effects: n, dropped }
        })
        .collect()
}

/// Runs of a Saltelli design per base sample: A, AB_1…AB_d, (BA_1…BA_d,) B.
pub fn sobol_runs_per_sample(d: usize, second_order: bool) -> usize {
    if second_order { 2 * d + 2 } else { d + 2 }
}

/// A Saltelli design of `samples` base samples (a power of two, at most
/// 2¹⁶) for `d` factors from an Owen-scrambled Sobol' sequence of 2d
/// dimensions (`seed` picks the scramble), in the unit hypercube. Each base
/// sample gives [`sobol_runs_per_sample`] consecutive rows: A, then A with
/// factor i from B for each i, then (for second order) B with factor i from
/// A for each i, then B.
pub fn sobol_design(d: usize, samples: usize, second_order: bool, seed: u32) -> Result<Vec<Vec<f64>>, DesignError> {
    if d == 0 {
        return Err(DesignError::NoFactors);
    }
    if 2 * d > 256 {
        return Err(DesignError::TooManyFactors(d));
    }
    if !samples.is_power_of_two() || !(2..=1 << 16).contains(&samples) {
        return Err(DesignError::Count { what: "samples", value: samples, expected: "a power of two, 2 to 65536" });
    }
    let mut rows = Vec::with_capacity(samples * sobol_runs_per_sample(d, second_order));
    for s in 0..samples {
        let point: Vec<f64> =
            (0..2 * d).map(|dim| f64::from(sobol_burley::sample(s as u32, dim as u32, seed))).collect();
        let (a, b) = point.split_at(d);
        rows.push(a.to_vec());
        for i in 0..d {
            let mut ab = a.to_vec();
            ab[i] = b[i];
            rows.push(ab);
        }
        if second_order {
            for i in 0..d {
                let mut ba = b.to_vec();
                ba[i] = a[i];
                rows.push(ba);
            }
        }
        rows.push(b.to_vec());
    }
    Ok(rows)
}

/// Sobol' indices of one factor, each with the half-width of its bootstrap
/// confidence interval.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SobolIndex {
    /// First-order index S1.
    pub first: f64,
    /// Half-width of S1's interval.
    pub first_conf: f64,
    /// Total index ST.
    pub total: f64,
    /// Half-width of ST's interval.
    pub total_conf: f64,
}

/// The Sobol' analysis of a design.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SobolResult {
    /// Per factor.
    pub indices: Vec<SobolIndex>,
    /// Second-order indices S2[j][k] (j < k) with their interval half-widths,
    /// when asked for; NaN on and below the diagonal.
    pub second: Option<(Matrix, Matrix)>,
    /// Base samples used.
    pub samples: usize,
    /// Base samples left out (an undefined output among their runs).
    pub dropped: usize,
}

/// A square table of indices by factor pair.
pub type Matrix = Vec<Vec<f64>>;

/// The outputs of one base sample, split by role.
struct Sample<'a> {
    a: f64,
    b: f64,
    ab: &'a [f64],
    ba: &'a [f64],
}

fn first_order(rows: &[Sample<'_>], pick: &[usize], i: usize, var: f64) -> f64 {
    let n = pick.len() as f64;
    pick.iter().map(|&r| rows[r].b * (rows[r].ab[i] - rows[r].a)).sum::<f64>() / n / var
}

fn total_order(rows: &[Sample<'_>], pick: &[usize], i: usize, var: f64) -> f64 {
    let n = pick.len() as f64;
    0.5 * pick.iter().map(|&r| (rows[r].a - rows[r].ab[i]).powi(2)).sum::<f64>() / n / var
}

fn second_order(rows: &[Sample<'_>], pick: &[usize], j: usize, k: usize, var: f64) -> f64 {
    let n = pick.len() as f64;
    let v = pick.iter().map(|&r| rows[r].ba[j] * rows[r].ab[k] - rows[r].a * rows[r].b).sum::<f64>() / n / var;
    v - first_order(rows, pick, j, var) - first_order(rows, pick, k, var)
}

/// The variance (ddof 0) of the A and B outputs of the picked samples.
fn variance(rows: &[Sample<'_>], pick: &[usize]) -> f64 {
    let n = 2.0 * pick.len() as f64;
    let mean = pick.iter().map(|&r| rows[r].a + rows[r].b).sum::<f64>() / n;
    pick.iter().map(|&r| (rows[r].a - mean).powi(2) + (rows[r].b - mean).powi(2)).sum::<f64>() / n
}

fn std_dev(v: &[f64]) -> f64 {
    let n = v.len();
    if n < 2 {
        return f64::NAN;
    }
    let mean = v.iter().sum::<f64>() / n as f64;
    (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n as f64 - 1.0)).sqrt()
}

/// Sobol' indices of `d` factors from the outputs `y` at the points of
/// [`sobol_design`] (the same order and `second_order`). The outputs of the
/// kept samples are standardised (zero mean, unit variance) first; the
/// intervals come from `resamples` bootstrap resamples of the base samples
/// (95 %, normal approximation).
pub fn sobol(y: &[f64], d: usize, second_order_too: bool, resamples: usize, seed: u64) -> SobolResult {
    let per = sobol_runs_per_sample(d, second_order_too);
    let total_samples = y.len() / per;
    let kept: Vec<&[f64]> = y.chunks_exact(per).filter(|c| c.iter().all(|v| v.is_finite())).collect();
    let dropped = total_samples - kept.len();
    let all: Vec<f64> = kept.iter().flat_map(|c| c.iter().copied()).collect();
    let n_all = all.len().max(1) as f64;
    let mean = all.iter().sum::<f64>() / n_all;
    let sd = (all.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n_all).sqrt();
    let scale = if sd > 0.0 { 1.0 / sd } else { 1.0 };
    let standardised: Vec<Vec<f64>> = kept.iter().map(|c| c.iter().map(|v| (v - mean) * scale).collect()).collect();
    let rows: Vec<Sample<'_>> = standardised
        .iter()
        .map(|c| Sample {
            a: c[0],
            b: c[per - 1],
            ab: &c[1..=d],
            ba: if second_order_too { &c[d + 1..=2 * d] } else { &[] },
        })
        .collect();
    let n = rows.len();
    let every: Vec<usize> = (0..n).collect();
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let picks: Vec<Vec<usize>> =
        (0..resamples).map(|_| (0..n).map(|_| if n > 0 { rng.random_range(0..n) } else { 0 }).collect()).collect();
    let var = variance(&rows, &every);
    let boot = |f: &dyn Fn(&[usize], f64) -> f64| -> f64 {
        if n == 0 {
            return f64::NAN;
        }
        let values: Vec<f64> = picks.iter().map(|p| f(p, variance(&rows, p))).collect();
        Z95 * std_dev(&values)
    };
    let indices = (0..d)
        .map(|i| SobolIndex {
            first: if n > 0 { first_order(&rows, &every, i, var) } else { f64::NAN },
            first_conf: boot(&|p, v| first_order(&rows, p, i, v)),
            total: if n > 0 { total_order(&rows, &every, i, var) } else { f64::NAN },
            total_conf: boot(&|p, v| total_order(&rows, p, i, v)),
        })
        .collect();
    let second = second_order_too.then(|| {
        let mut s2 = vec![vec![f64::NAN; d]; d];
        let mut conf = vec![vec![f64::NAN; d]; d];
        for j in 0..d {
            for k in j + 1..d {
                s2[j][k] = if n > 0 { second_order(&rows, &every, j, k, var) } else { f64::NAN };
                conf[j][k] = boot(&|p, v| second_order(&rows, p, j, k, v));
            }
        }
        (s2, conf)
    });
    SobolResult { indices, second, samples: n, dropped }
}

/// The method of a design and its size.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Method {
    /// Morris's elementary effects: `trajectories` of d + 1 points on a
    /// `levels`-level grid.
    Morris {
        /// Trajectories r.
        trajectories: usize,
        /// Grid levels p (even).
        levels: usize,
    },
    /// Points given as they are (`sweep --points`), SI, a row per point in
    /// the order of the factors: run, not analysed.
    Given {
        /// The points.
        points: Vec<Vec<f64>>,
    },
    /// Sobol' indices from a Saltelli design of `samples` base samples.
    Sobol {
        /// Base samples N (a power of two).
        samples: usize,
        /// Second-order indices too (N(2d + 2) runs instead of N(d + 2)).
        second_order: bool,
    },
}

/// A sample design as recorded with its runs (`sweep.ron`): the method,
/// the factors and the seed rebuild every point exactly.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Design {
    /// Method and size.
    pub method: Method,
    /// The factors, in the order of the design's columns.
    pub factors: Vec<Factor>,
    /// Seed of the Morris trajectories or of the Sobol' scramble.
    pub seed: u64,
}

impl Design {
    /// The points in the unit hypercube.
    pub fn unit_points(&self) -> Result<Vec<Vec<f64>>, DesignError> {
        let d = self.factors.len();
        match self.method {
            Method::Morris { trajectories, levels } => morris_design(d, trajectories, levels, self.seed),
            Method::Sobol { samples, second_order } => {
                // The scramble's seed is 32 bits: both halves of the seed fold into it.
                sobol_design(d, samples, second_order, (self.seed ^ (self.seed >> 32)) as u32)
            }
            Method::Given { ref points } => Ok(points
                .iter()
                .map(|row| {
                    row.iter()
                        .zip(&self.factors)
                        .map(|(x, f)| if f.to > f.from { (x - f.from) / (f.to - f.from) } else { 0.0 })
                        .collect()
                })
                .collect()),
        }
    }

    /// The points in the factors' own values (SI).
    pub fn points(&self) -> Result<Vec<Vec<f64>>, DesignError> {
        if let Method::Given { points } = &self.method {
            return Ok(points.clone());
        }
        Ok(self
            .unit_points()?
            .into_iter()
            .map(|u| u.iter().zip(&self.factors).map(|(&u, f)| f.value(u)).collect())
            .collect())
    }

    /// The number of runs.
    pub fn runs(&self) -> usize {
        let d = self.factors.len();
        match self.method {
            Method::Morris { trajectories, .. } => trajectories * (d + 1),
            Method::Sobol { samples, second_order } => samples * sobol_runs_per_sample(d, second_order),
            Method::Given { ref points } => points.len(),
        }
    }

    /// A design of the points of a table: a header of parameter keys (a
    /// unit in brackets after a key is allowed and ignored: values are SI),
    /// then a row of numbers per point. The factors' ranges are the
    /// columns' smallest and largest values.
    pub fn given(text: &str) -> Result<Design, String> {
        let mut reader =
            csv::ReaderBuilder::new().trim(csv::Trim::All).comment(Some(b'#')).from_reader(text.as_bytes());
        let keys: Vec<String> = reader
            .headers()
            .map_err(|e| format!("no header: {e}"))?
            .iter()
            .map(|h| h.split(" [").next().unwrap_or(h).trim().to_string())
            .collect();
        if keys.is_empty() || keys.iter().any(String::is_empty) {
            return Err("the header must name a parameter in every column".into());
        }
        let mut points = Vec::new();
        for (n, record) in reader.records().enumerate() {
            let record = record.map_err(|e| format!("row {}: {e}", n + 1))?;
            let row = record
                .iter()
                .map(|v| v.parse::<f64>().ok().filter(|x| x.is_finite()))
                .collect::<Option<Vec<f64>>>()
                .filter(|r| r.len() == keys.len())
                .ok_or_else(|| format!("row {}: expected {} numbers", n + 1, keys.len()))?;
            points.push(row);
        }
        if points.is_empty() {
            return Err("no points".into());
        }
        let factors = keys
            .iter()
            .enumerate()
            .map(|(k, key)| {
                let (lo, hi) =
                    points.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| (lo.min(r[k]), hi.max(r[k])));
                Factor { key: key.clone(), log: false, from: lo, to: hi }
            })
            .collect();
        Ok(Design { method: Method::Given { points }, factors, seed: 0 })
    }

    /// The factors as the varied parameters of a sweep (their ranges).
    pub fn vary(&self) -> Vec<crate::sweep::Vary> {
        use crate::sweep::{Spacing, Vary};
        self.factors
            .iter()
            .map(|f| Vary::range(&f.key, if f.log { Spacing::Log } else { Spacing::Lin }, f.from, f.to, 2))
            .collect()
    }
}

/// Reads a factor, `NAME=lin|log:FROM:TO` (SI units).
pub fn parse_factor(text: &str) -> Result<Factor, String> {
    let bad = || format!("'{text}' is not NAME=lin|log:FROM:TO (e.g. surface_energy=log:0.1:1)");
    let (key, rest) = text.split_once('=').ok_or_else(bad)?;
    let parts: Vec<&str> = rest.split(':').collect();
    let [spacing, from, to] = parts[..] else { return Err(bad()) };
    let number = |s: &str| s.trim().parse::<f64>().ok().filter(|v| v.is_finite());
    let (Some(from), Some(to)) = (number(from), number(to)) else { return Err(bad()) };
    let log = match spacing.trim() {
        "lin" => false,
        "log" => true,
        _ => return Err(bad()),
    };
    let key = key.trim();
    if key.is_empty() || from >= to {
        return Err(format!("{text}: needs a key and FROM below TO"));
    }
    if log && from <= 0.0 {
        return Err(format!("{text}: a log range needs positive ends"));
    }
    Ok(Factor { key: key.to_string(), log, from, to })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn morris_trajectories_step_one_factor_by_delta() {
        let d = 5;
        let design = morris_design(d, 10, 4, 7).expect("a design");
        assert_eq!(design.len(), 10 * (d + 1));
        let delta = morris_delta(4);
        for t in design.chunks(d + 1) {
            let mut moved = vec![false; d];
            for w in t.windows(2) {
                let changed: Vec<usize> = (0..d).filter(|&i| w[0][i] != w[1][i]).collect();
                assert_eq!(changed.len(), 1, "{w:?}");
                assert!(((w[1][changed[0]] - w[0][changed[0]]).abs() - delta).abs() < 1e-12);
                moved[changed[0]] = true;
            }
            assert!(moved.iter().all(|&m| m), "every factor moves once");
            assert!(t.iter().flatten().all(|&x| (0.0..=1.0).contains(&x)));
        }
    }

    #[test]
    fn saltelli_rows_mix_a_and_b_column_by_column() {
        let d = 3;
        let design = sobol_design(d, 8, true, 0).expect("a design");
        assert_eq!(design.len(), 8 * (2 * d + 2));
        for c in design.chunks(2 * d + 2) {
            let (a, b) = (&c[0], &c[2 * d + 1]);
            for i in 0..d {
                for k in 0..d {
                    assert_eq!(c[1 + i][k], if k == i { b[k] } else { a[k] });
                    assert_eq!(c[1 + d + i][k], if k == i { a[k] } else { b[k] });
                }
            }
        }
    }
}

/// One run's output for an analysis: the value (None where it is undefined
/// or the run failed) and whether it is a bound entered at the bound.
pub type RunValue = (Option<f64>, bool);

/// Computes runs `from..to` of `design` (in design order) over the
/// parameters `base`: scalar `output` in unit `unit`, in parallel, through
/// the scene's quick path where it has one. The same values as the runs of
/// `grainscope sensitivity` (the same plan).
pub fn run_values(
    base: &crate::scene::SceneParams,
    design: &Design,
    output: &str,
    unit: &str,
    range: std::ops::Range<usize>,
    progress: &crate::scene::Progress,
) -> Result<Vec<RunValue>, String> {
    use crate::sweep::{Columns, Plan};
    let points = design.points().map_err(|e| e.to_string())?;
    let plan = Plan::of_points(base.clone(), design.vary(), points).map_err(|e| e.to_string())?;
    let columns = Columns::new(vec![output.to_string()], vec![unit.to_string()], &plan.base);
    let indices: Vec<usize> = range.filter(|&i| i < plan.len()).collect();
    let rows = crate::sweep::run(&plan, &columns, &indices, progress, &|_| {}).map_err(|e| e.to_string())?;
    Ok(rows
        .iter()
        .map(|r| match (&r.error, r.scalars.first().copied().flatten()) {
            (None, Some(v)) if v.is_finite() => (Some(v), r.status.first().is_some_and(|s| s.starts_with("above"))),
            _ => (None, false),
        })
        .collect())
}

/// The indices of a design from the runs done so far.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Answer {
    /// Morris's measures per factor (a Morris design).
    pub morris: Option<Vec<MorrisIndex>>,
    /// Sobol' indices (a Sobol' design).
    pub sobol: Option<SobolResult>,
    /// Runs analysed: the complete trajectories or base samples among those done.
    pub runs: usize,
    /// Runs of the whole design.
    pub total: usize,
    /// Runs analysed whose output is undefined (left out by the stated rule).
    pub undefined: usize,
    /// Runs analysed whose output is a bound (entered at the bound).
    pub bounded: usize,
}

/// Bootstrap resamples of the confidence intervals (as SALib's default).
pub const RESAMPLES: usize = 1000;

/// The indices from `values`, the first runs of `design` in design order:
/// a prefix of whole Morris trajectories or Sobol' base samples is a design
/// of its own, so the indices fill in as runs finish and equal those of the
/// whole design once every run is done. `log_output` analyses ln X (a
/// non-positive X counts as undefined). None until two trajectories or base
/// samples are complete.
pub fn answer(design: &Design, values: &[RunValue], log_output: bool) -> Result<Option<Answer>, DesignError> {
    let d = design.factors.len();
    let block = match design.method {
        Method::Morris { .. } => d + 1,
        Method::Sobol { second_order, .. } => sobol_runs_per_sample(d, second_order),
        Method::Given { .. } => return Ok(None),
    };
    let whole = values.len() / block.max(1);
    if whole < 2 {
        return Ok(None);
    }
    let used = &values[..whole * block];
    let (mut undefined, mut bounded) = (0, 0);
    let y: Vec<f64> = used
        .iter()
        .map(|&(v, bound)| match v {
            Some(v) if v > 0.0 || !log_output => {
                bounded += usize::from(bound);
                if log_output { v.ln() } else { v }
            }
            _ => {
                undefined += 1;
                f64::NAN
            }
        })
        .collect();
    let (morris, sobol) = match design.method {
        Method::Morris { .. } => {
            let unit = design.unit_points()?;
            (Some(morris(&unit[..used.len()], &y, d, RESAMPLES, design.seed)), None)
        }
        _ => {
            let second = matches!(design.method, Method::Sobol { second_order: true, .. });
            (None, Some(sobol(&y, d, second, RESAMPLES, design.seed)))
        }
    };
    Ok(Some(Answer { morris, sobol, runs: used.len(), total: design.runs(), undefined, bounded }))
}

#[cfg(test)]
mod answer_tests {
    use super::*;

    /// The indices of a prefix of whole trajectories are those of that many
    /// trajectories; fewer than two give none, a partial one is left out.
    #[test]
    fn a_prefix_of_whole_trajectories_is_analysed() {
        let factor = |key: &str| Factor { key: key.into(), log: false, from: 0.0, to: 1.0 };
        let design = Design {
            method: Method::Morris { trajectories: 8, levels: 4 },
            factors: vec![factor("a"), factor("b")],
            seed: 3,
        };
        let unit = design.unit_points().expect("a design");
        // y = 3a + b: μ* = 3 and 1 on every trajectory.
        let values: Vec<RunValue> = unit.iter().map(|u| (Some(3.0 * u[0] + u[1]), false)).collect();
        assert_eq!(answer(&design, &values[..5], false).expect("a design"), None);
        let part = answer(&design, &values[..3 * 3 + 2], false).expect("a design").expect("three trajectories");
        assert_eq!((part.runs, part.total), (9, 24));
        let m = part.morris.expect("Morris");
        assert!((m[0].mu_star - 3.0).abs() < 1e-12 && (m[1].mu_star - 1.0).abs() < 1e-12);
        assert_eq!(m[0].effects, 3);
        let whole = answer(&design, &values, false).expect("a design").expect("all");
        assert_eq!(
            whole.morris.expect("Morris"),
            morris(&unit, &values.iter().map(|v| v.0.unwrap_or(f64::NAN)).collect::<Vec<_>>(), 2, RESAMPLES, 3)
        );
    }
}
