//! Grids of parameter values that scenes and controls share. Imports nothing
//! of the crate, so both [`super::controls`] and [`super::core`] can use it.

/// Evenly spaced values in log space, `n ≥ 2` points from `lo` to `hi`.
pub fn logspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let n = n.max(2);
    let (a, b) = (lo.ln(), hi.ln());
    (0..n).map(|i| (a + (b - a) * i as f64 / (n - 1) as f64).exp()).collect()
}
