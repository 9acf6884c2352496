//! Speed of the restitution fit: a 40 × 40 × 40 grid over a 30-point data
//! set, as in thesis Sect. 2.4.1. Run with `cargo bench --bench fitting`.

use grainscope::physics::collision::{Options, Setup, collide};
use grainscope::physics::experiments::experiment;
use grainscope::physics::fit::{Measurement, Search, fit, model_restitution};
use std::time::Instant;

fn main() {
    let e = experiment("wall-mica").expect("experiment");
    let setup_for = |g: f64, t: f64, y: Option<f64>| -> Option<Setup> { e.setup(g, t, y) };
    let truth = [0.13, 9.79e-11, 1.92e8];
    let velocities: Vec<f64> = (0..30).map(|i| e.v_min * (e.v_max / e.v_min).powf(i as f64 / 29.0)).collect();
    let exact = model_restitution(&setup_for, truth, &velocities, &Options { rtol: 1e-8, ..Options::default() })
        .expect("model");
    let data: Vec<Measurement> = velocities
        .iter()
        .zip(&exact)
        .map(|(&velocity, &restitution)| Measurement { velocity, restitution, uncertainty: None })
        .collect();
    println!("data: Wall et al. mica best fit at 30 velocities, {} threads", rayon::current_num_threads());
    println!(
        "{:>6} {:>7} {:>11} {:>13} {:>12} {:>10} {:>10} {:>10}",
        "rtol", "grid", "time [s]", "collisions", "µs/collision", "γ", "T_vis", "Y"
    );
    for (rtol, n) in [(1e-4, 20), (1e-4, 40), (1e-5, 40)] {
        let searches = [
            Search { min: 0.02, max: 1.0, points: n, fixed: None },
            Search { min: 1e-12, max: 1e-9, points: n, fixed: None },
            Search { min: 3e7, max: 3e10, points: n, fixed: None },
        ];
        let opts = Options { rtol, ..Options::default() };
        let start = Instant::now();
        let f = fit(&setup_for, &data, searches, &opts, &|_| true).expect("fit");
        let t = start.elapsed().as_secs_f64();
        println!(
            "{rtol:>6.0e} {:>7} {t:>11.2} {:>13} {:>12.1} {:>10.4} {:>10.3e} {:>10.3e}",
            format!("{n}³"),
            f.collisions,
            t / f.collisions as f64 * 1e6 * rayon::current_num_threads() as f64,
            f.best[0],
            f.best[1],
            f.best[2]
        );
    }
    // One model evaluation (one collision) on a single thread, for reference.
    let s = e.setup(truth[0], truth[1], None).expect("setup");
    let opts = Options { rtol: 1e-4, ..Options::default() };
    let start = Instant::now();
    let mut n = 0;
    for &v in velocities.iter().cycle().take(3000) {
        n += usize::from(collide(&s, v, &opts).expect("collide").e_adhesive > 0.0);
    }
    println!(
        "single-thread collision at rtol 1e-4: {:.1} µs ({n} bounces)",
        start.elapsed().as_secs_f64() / 3000.0 * 1e6
    );
}
