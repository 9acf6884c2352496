use grainscope::physics::monte_carlo::{Analytic, Body, Engine, Settings};
use rayon::prelude::*;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let w: f64 = args.get(1).and_then(|v| v.parse().ok()).unwrap_or(60.0);
    let seeds: u64 = args.get(2).and_then(|v| v.parse().ok()).unwrap_or(16);
    for (k, t, per) in [
        (Analytic::Constant, 1000.0, 2usize),
        (Analytic::Linear, std::env::var("TL").ok().and_then(|v| v.parse().ok()).unwrap_or(10.0), 1),
        (Analytic::Product, 0.9, 2),
    ] {
        if std::env::var("ONLY").map(|o| !format!("{k:?}").starts_with(&o)).unwrap_or(false) {
            continue;
        }
        let start = std::time::Instant::now();
        let runs: Vec<(std::collections::BTreeMap<i64, f64>, u64)> = (0..seeds)
            .into_par_iter()
            .map(|s| {
                let mut e = Engine::new(
                    k,
                    Body { mass: 1.0, filling: 1.0 },
                    1e20,
                    1e20,
                    Settings {
                        groups_per_decade: w,
                        seed: s + 1,
                        f_m: std::env::var("FM").ok().and_then(|v| v.parse().ok()).unwrap_or(0.1),
                        rezoom_every: std::env::var("RZ").ok().and_then(|v| v.parse().ok()).unwrap_or(100),
                        ..Settings::default()
                    },
                )
                .unwrap();
                e.run_until(t, 50_000_000);
                let mut b = std::collections::BTreeMap::new();
                for f in e.families() {
                    *b.entry((f.mass.log10() * per as f64).floor() as i64).or_insert(0.0) +=
                        f.mass * f.particles() / e.volume();
                }
                (b, e.events())
            })
            .collect();
        let keys: std::collections::BTreeSet<i64> = runs.iter().flat_map(|r| r.0.keys().copied()).collect();
        println!(
            "{k:?} t = {t}, w* = {w}, {seeds} seeds, {:.0} events/run, {:.2} s",
            runs.iter().map(|r| r.1 as f64).sum::<f64>() / seeds as f64,
            start.elapsed().as_secs_f64()
        );
        for b in keys {
            let v: Vec<f64> = runs.iter().map(|r| r.0.get(&b).copied().unwrap_or(0.0)).collect();
            let mean = v.iter().sum::<f64>() / v.len() as f64;
            let sd = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (v.len() - 1) as f64).sqrt()
                / (v.len() as f64).sqrt();
            let lo = 10f64.powf(b as f64 / per as f64);
            let hi = 10f64.powf((b + 1) as f64 / per as f64);
            let x = k.exact_mass_between(lo, hi, t);
            if x > 1e-3 || mean > 1e-3 {
                println!(
                    "  bin {b:>3}: mean {mean:.4} ± {sd:.4}, exact {x:.4}, error {:+.3}, {:.1} sigma",
                    mean / x - 1.0,
                    (mean - x) / sd
                );
            }
        }
    }
}
