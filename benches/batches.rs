//! Speed against accuracy of the global dust-batch model (thesis ch. 5): one
//! porous run as the batch count and the synchronisation rate grow, and the
//! Fig. 5.9 grid of 30 disks. Run with `cargo bench --bench batches`.

use grainscope::physics::batches::{BatchConfig, BatchRun, run};
use grainscope::physics::constants::AU;
use grainscope::preset;
use grainscope::scene::{self, Progress};
use std::time::Instant;

fn timed(cfg: &BatchConfig) -> (f64, BatchRun) {
    let t = Instant::now();
    let r = run(cfg, &|_| false).expect("valid configuration");
    (t.elapsed().as_secs_f64(), r)
}

fn main() {
    println!("{} threads", rayon::current_num_threads());
    println!("Fig. 5.6 disk (porous, perfect sticking, 1e6 yr); reference: 2000 batches, 1280 syncs/decade");
    let reference = timed(&BatchConfig { syncs_per_decade: 1280, ..BatchConfig::figure_5_6(2000) }).1;
    let (e_ref, f_ref) = (reference.outermost_planetesimals() / AU, reference.converted_fraction());
    println!("  reference: zone edge {e_ref:.3} AU, converted {f_ref:.4}");
    println!("  batches  syncs/dec   time [s]   edge [AU]  d(edge)   converted  d(converted)");
    for (batches, syncs) in
        [(125, 160), (250, 40), (250, 160), (250, 640), (500, 160), (1000, 40), (1000, 160), (1000, 640)]
    {
        let (t, r) = timed(&BatchConfig { syncs_per_decade: syncs, ..BatchConfig::figure_5_6(batches) });
        let (e, f) = (r.outermost_planetesimals() / AU, r.converted_fraction());
        println!(
            "  {batches:>7}  {syncs:>9}  {t:>9.3}  {e:>10.3}  {:>+7.1}%  {f:>10.4}  {:>+11.4}",
            (e / e_ref - 1.0) * 100.0,
            f - f_ref
        );
    }
    println!("  target: 1000 batches over 1e6 yr in <= 1 s");

    let grid = preset::resolve("batch-fig-5-9").expect("shipped preset");
    let t = Instant::now();
    let out = scene::compute(&grid.scene, &Progress::default()).expect("Fig. 5.9 grid");
    let disks = out.scalars.iter().find(|s| s.key == "disks").map_or(0.0, |s| s.value);
    println!("Fig. 5.9 grid, {disks} disks x 120 batches: {:.2} s (target 20 s)", t.elapsed().as_secs_f64());
}
