//! The Monte Carlo distribution method against the analytic Smoluchowski
//! kernels, mass conservation and seed reproducibility.

use grainscope::physics::monte_carlo::{Analytic, Engine, Settings};

const PARTICLES: f64 = 1e20;

fn engine(kernel: Analytic, seed: u64) -> Engine<Analytic> {
    let f_m: f64 = std::env::var("FM").ok().and_then(|v| v.parse().ok()).unwrap_or(0.1);
    let w: f64 = std::env::var("WSTAR").ok().and_then(|v| v.parse().ok()).unwrap_or(60.0);
    // N₀ = 1: the volume equals the particle count.
    Engine::new(kernel, 1.0, PARTICLES, PARTICLES, Settings { seed, f_m, groups_per_decade: w, ..Settings::default() }).expect("valid")
}

/// Mass fraction per bin of the run and of the exact solution, for bins of
/// `per_decade`, over the bins that together hold `core` of the exact mass.
fn compare(kernel: Analytic, t: f64, seeds: u64, per_decade: usize, core: f64) -> (f64, usize, f64) {
    let mut sum: std::collections::BTreeMap<i64, f64> = Default::default();
    let mut events = 0;
    for seed in 0..seeds {
        let mut e = engine(kernel, seed + 1);
        e.run_until(t, 5_000_000);
        assert!(e.time >= t, "stopped at t = {} after {} events", e.time, e.events);
        events += e.events;
        let rel = (e.mass() - e.initial_mass()).abs() / e.initial_mass();
        assert!(rel < 1e-12, "mass drift {rel:e}");
        let n = per_decade as f64;
        for f in &e.families {
            *sum.entry((f.mass.log10() * n).floor() as i64).or_default() += f.mass * f.particles() / e.volume / seeds as f64;
        }
    }
    let n = per_decade as f64;
    let mut rows: Vec<(i64, f64, f64)> = sum
        .iter()
        .map(|(&b, &m)| {
            let lo = 10f64.powf(b as f64 / n);
            let hi = 10f64.powf((b + 1) as f64 / n);
            (b, m, kernel.exact_mass_between(lo, hi, t))
        })
        .collect();
    let total_exact: f64 = rows.iter().map(|r| r.2).sum();
    rows.sort_by(|a, b| b.2.total_cmp(&a.2));
    let mut held = 0.0;
    let mut worst: f64 = 0.0;
    let mut used = 0;
    for (b, m, x) in &rows {
        if held >= core * total_exact {
            break;
        }
        held += x;
        used += 1;
        let err = (m / x - 1.0).abs();
        eprintln!("{kernel:?} bin {b}: run {m:.4e}, exact {x:.4e}, error {err:.3}");
        worst = worst.max(err);
    }
    (worst, used, events as f64 / seeds as f64)
}

#[test]
fn constant_kernel_matches_the_exact_solution() {
    let (worst, bins, events) = compare(Analytic::Constant, 1000.0, 4, 2, 0.9);
    eprintln!("constant: worst {worst:.3} over {bins} bins, {events} events per run");
    assert!(worst < 0.1, "{worst}");
}

#[test]
fn linear_kernel_matches_the_exact_solution() {
    let (worst, bins, events) = compare(Analytic::Linear, 10.0, 4, 1, 0.9);
    eprintln!("linear: worst {worst:.3} over {bins} bins, {events} events per run");
    assert!(worst < 0.1, "{worst}");
}

#[test]
fn product_kernel_matches_the_exact_solution_before_gelation() {
    let (worst, bins, events) = compare(Analytic::Product, 0.9, 4, 2, 0.9);
    eprintln!("product: worst {worst:.3} over {bins} bins, {events} events per run");
    assert!(worst < 0.1, "{worst}");
}
