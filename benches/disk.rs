//! Speed of the disk-and-aggregates library: the collision-speed map, one
//! growth track and the Fig. 4.13 set. Run with `cargo bench --bench disk`.

use grainscope::physics::constants::{AU, YEAR};
use grainscope::physics::growth::{GrowthModel, Porosity};
use grainscope::scene::Progress;
use grainscope::scene::disk::collision_speeds::{Params as MapParams, map};
use rayon::prelude::*;
use std::time::Instant;

fn best_of<T>(n: usize, mut f: impl FnMut() -> T) -> f64 {
    (0..n)
        .map(|_| {
            let t = Instant::now();
            std::hint::black_box(f());
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    println!("{} threads", rayon::current_num_threads());
    let p = MapParams { cells: 200, ..MapParams::default() };
    let t = best_of(5, || map(&p, &Progress::default()).expect("map"));
    println!("collision-speed map 200 x 200:            {:>8.1} ms (target 50)", t * 1e3);
    let model = GrowthModel::chapter4(Porosity::Full);
    let t = best_of(5, || model.run(5.0 * AU, 1e6 * YEAR));
    let steps = model.run(5.0 * AU, 1e6 * YEAR).points.len();
    println!("one porous track from 5 AU ({steps} steps):   {:>8.2} ms (target 5)", t * 1e3);
    let starts: Vec<f64> = (0..30).map(|i| 3.0 * 100f64.powf(i as f64 / 29.0)).collect();
    let mut models = Vec::new();
    let mut compact = GrowthModel::chapter4(Porosity::Compact);
    compact.thresholds.v_frag = 10.0;
    models.push(compact);
    for v_eros in [f64::INFINITY, 20.0, 40.0, 60.0] {
        let mut m = GrowthModel::chapter4(Porosity::Full);
        m.thresholds.v_eros = v_eros;
        models.push(m);
    }
    let t = best_of(3, || {
        models
            .iter()
            .map(|m| starts.par_iter().map(|&r| m.run(r * AU, 1e6 * YEAR).points.len()).sum::<usize>())
            .sum::<usize>()
    });
    println!("Fig. 4.13 set, 5 x 30 tracks, 1e6 yr:      {:>8.1} ms (target 100)", t * 1e3);
}
