//! Speed against accuracy of the global dust-batch model (thesis ch. 5): one
//! porous run as the batch count and the time resolution grow, and the
//! Fig. 5.9 grid of 30 disks. Run with `cargo bench --bench batches`.
//!
//! The zone's edge follows the pile-up of drifting batches around 4–5 AU,
//! which shifts with where the batches happen to sit: each setting runs with
//! four offsets of the initial grid and prints the mean and the spread.

use grainscope::physics::batches::{BatchConfig, BatchRun, run};
use grainscope::physics::constants::AU;
use grainscope::preset;
use grainscope::scene::{self, Progress};
use std::time::Instant;

const OFFSETS: [f64; 4] = [0.0, 0.25, 0.5, 0.75];

/// The Fig. 5.6 disk with `batches` batches and steps `finer` times smaller
/// than the default (Δln m = 0.2, 5 % of the drift time).
fn figure_5_6(batches: usize, finer: f64, offset: f64) -> BatchConfig {
    let mut cfg = BatchConfig::figure_5_6(batches);
    cfg.model.dlnm /= finer;
    cfg.model.drift_step /= finer;
    cfg.offset = offset;
    cfg
}

/// Mean and standard deviation.
fn spread(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    (mean, (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0)).sqrt())
}

/// Time per run (s) and, over the offsets: edge, 90 % radius and converted fraction.
fn ensemble(batches: usize, finer: f64) -> (f64, [(f64, f64); 3]) {
    let mut time = 0.0;
    let mut runs: Vec<BatchRun> = Vec::new();
    for u in OFFSETS {
        let t = Instant::now();
        runs.push(run(&figure_5_6(batches, finer, u), &|_| false).expect("valid configuration"));
        time += t.elapsed().as_secs_f64();
    }
    let of = |f: &dyn Fn(&BatchRun) -> f64| spread(&runs.iter().map(f).collect::<Vec<_>>());
    (
        time / OFFSETS.len() as f64,
        [
            of(&|r| r.outermost_planetesimals() / AU),
            of(&|r| r.formation_radius_quantile(0.9) / AU),
            of(&|r| r.converted_fraction()),
        ],
    )
}

fn main() {
    println!("{} threads", rayon::current_num_threads());
    println!("Fig. 5.6 disk (porous, perfect sticking, 1e6 yr), each over {} grid offsets (mean ± sd)", OFFSETS.len());
    let (t_ref, [e_ref, q_ref, f_ref]) = ensemble(4000, 2.0);
    println!(
        "  reference, 4000 batches, steps x2 finer ({t_ref:.2} s per run): edge {:.2} ± {:.2} AU, \
         90 % of the mass inside {:.2} ± {:.2} AU, converted {:.4} ± {:.4}",
        e_ref.0, e_ref.1, q_ref.0, q_ref.1, f_ref.0, f_ref.1
    );
    println!(
        "  batches  steps  time/run [s]   edge [AU]       d(edge)   r_90 [AU]      d(r_90)   converted         d(conv)"
    );
    for (batches, finer) in
        [(125, 1.0), (250, 1.0), (500, 1.0), (500, 2.0), (1000, 1.0), (1000, 4.0), (2000, 1.0), (2000, 2.0)]
    {
        let (t, [e, q, f]) = ensemble(batches, finer);
        println!(
            "  {batches:>7}  {:>5}  {t:>12.3}   {:.2} ± {:.2}   {:>+6.1}%   {:.2} ± {:.2}   {:>+6.1}%   {:.4} ± {:.4}   {:>+.4}",
            format!("x{finer}"),
            e.0,
            e.1,
            (e.0 / e_ref.0 - 1.0) * 100.0,
            q.0,
            q.1,
            (q.0 / q_ref.0 - 1.0) * 100.0,
            f.0,
            f.1,
            f.0 - f_ref.0
        );
    }
    println!("  targets: at the default (500 batches, x1) edge within 5 %, converted within 0.02;");
    println!("           within 2 % in <= 1 s");

    let grid = preset::resolve("batch-fig-5-9").expect("shipped preset");
    let t = Instant::now();
    let out = scene::compute(&grid.scene, &Progress::default()).expect("Fig. 5.9 grid");
    let disks = out.scalars.iter().find(|s| s.key == "disks").map_or(0.0, |s| s.value);
    println!(
        "Fig. 5.9 grid, {disks} disks x 500 batches, each also with 250: {:.2} s (target 20 s)",
        t.elapsed().as_secs_f64()
    );
}
