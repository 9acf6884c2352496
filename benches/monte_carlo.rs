//! Speed against accuracy of the Monte Carlo distribution method (thesis
//! Sect. 4.3): the analytic kernels as w* grows, and the two column runs of
//! ch. 4 — perfect sticking until m_p = 10¹⁵ g and erosion at 20 m/s until
//! 10⁴ yr — with their event rates; and the cost of a new family's row of
//! pairs, at once and one pair at a time. Run with `cargo bench --bench
//! monte_carlo` (add `quick` to skip the erosion run).

use grainscope::physics::coagulation::{Run, RunConfig};
use grainscope::physics::constants::YEAR;
use grainscope::scene::Progress;
use grainscope::scene::monte_carlo::analytic_kernels::{self, Params, TestKernel};
use grainscope::scene::monte_carlo::common::ColumnCompaction;
use grainscope::scene::monte_carlo::common::ColumnParams;
use grainscope::scene::schema::Choice;
use std::time::Instant;

fn column(w: f64, v_eros: f64, compaction: &str, stop_g: f64, t_end_yr: f64) -> RunConfig {
    let p = ColumnParams {
        compaction: ColumnCompaction::from_key(compaction).unwrap_or_default(),
        newton: compaction == "full",
        v_eros,
        groups_per_decade: w,
        runs: 1,
        t_first_yr: t_end_yr,
        t_end_yr,
        snapshots: 1,
        stop_mass_g: stop_g,
        max_events_millions: 100.0,
        ..ColumnParams::default()
    };
    p.config().expect("valid")
}

fn timed(cfg: &RunConfig) -> (f64, Run) {
    let t = Instant::now();
    let r = cfg.run(1, &|_| true).expect("runs");
    (t.elapsed().as_secs_f64(), r)
}

/// Nanoseconds a pair for a row of 600 families of the erosion column, as
/// the engine computes it (`Model::pair_data_row`) and one pair at a time.
fn row_of_pairs() {
    use grainscope::physics::monte_carlo::{Body, Family, Model, OwnedRow, PairRule};
    use rand::{Rng, SeedableRng};
    let column = column(40.0, 20.0, "full", 1e21, 1e4).column;
    let m0 = column.monomer.mass();
    let mut rng = rand::rngs::StdRng::seed_from_u64(5);
    let families: Vec<_> = (0..600)
        .map(|_| {
            let mass = m0 * 10f64.powf(rng.random_range(0.0..24.0));
            let filling = (mass / m0).powf(-0.3).max(1e-4);
            Family { mass, filling, groups: 1.0, zoom: 0, props: column.props(Body { mass, filling }) }
        })
        .collect();
    let mut lanes = Default::default();
    for (i, f) in families.iter().enumerate() {
        column.set_lane(&mut lanes, i, f);
    }
    let which: Vec<usize> = (0..families.len()).collect();
    let rule = PairRule { volume: 1e15, f_m: 0.1, f_phi: 0.1 };
    let mut out = OwnedRow::new(families.len());
    let rows = 2000;
    let start = Instant::now();
    for r in 0..rows {
        column.pair_data_row(&lanes, &families[r % families.len()], &families, &which, &rule, out.row());
    }
    let at_once = start.elapsed().as_secs_f64() / (rows * families.len()) as f64 * 1e9;
    // A row without its first family is computed one pair at a time (with
    // the column's constants once), as every row was before.
    let part = &which[1..];
    let start = Instant::now();
    for r in 0..rows {
        column.pair_data_row(&lanes, &families[r % families.len()], &families, part, &rule, out.row());
    }
    let one = start.elapsed().as_secs_f64() / (rows * part.len()) as f64 * 1e9;
    println!(
        "A row of 600 pairs (erosion column): {at_once:.1} ns a pair as the engine computes it, {one:.1} one at a time"
    );
}

fn main() {
    let quick = std::env::args().any(|a| a == "quick");
    println!("{} threads", rayon::current_num_threads());
    row_of_pairs();
    println!("Analytic kernels, 16 runs each from 1e20 monomers: worst error over the bins holding 90 % of the mass");
    println!("  kernel     t      w*   events/run   time/run [ms]   worst error");
    for (kernel, t) in [("constant", 1000.0), ("linear", 10.0), ("product", 0.9)] {
        for w in [20.0, 60.0, 200.0] {
            let p = Params {
                kernel: TestKernel::from_key(kernel).unwrap_or_default(),
                time: t,
                groups_per_decade: w,
                runs: 16,
                ..Params::default()
            };
            let start = Instant::now();
            let (bins, events) = analytic_kernels::run(&p, &Progress::default()).expect("runs");
            let per_run = start.elapsed().as_secs_f64() * 1e3 / 16.0 * rayon::current_num_threads() as f64;
            let worst = analytic_kernels::core_error(&bins, 0.9);
            println!("  {kernel:<9} {t:>6}  {w:>4}   {events:>10.0}   {per_run:>13.1}   {worst:>11.3}");
        }
    }
    println!("The same with no group above 1e-3 of the total mass (group_mass_cap):");
    for (kernel, t) in [("constant", 1000.0), ("linear", 10.0), ("product", 0.9)] {
        for w in [20.0, 60.0] {
            let p = Params {
                kernel: TestKernel::from_key(kernel).unwrap_or_default(),
                time: t,
                groups_per_decade: w,
                runs: 16,
                group_mass_cap: 1e-3,
                ..Params::default()
            };
            let start = Instant::now();
            let (bins, events) = analytic_kernels::run(&p, &Progress::default()).expect("runs");
            let per_run = start.elapsed().as_secs_f64() * 1e3 / 16.0 * rayon::current_num_threads() as f64;
            let worst = analytic_kernels::core_error(&bins, 0.9);
            println!("  {kernel:<9} {t:>6}  {w:>4}   {events:>10.0}   {per_run:>13.1}   {worst:>11.3}");
        }
    }

    println!("Column at 5 AU, alpha = 1e-3, 0.1 um ice, one run (one thread)");
    println!("  case                                        w*   time [s]   events    events/s   families   |dM|/M");
    let cases: Vec<(&str, f64, RunConfig)> = vec![
        ("(a) perfect sticking, collisional, to 1e15 g", 40.0, column(40.0, 1e4, "collisional", 1e15, 1e5)),
        ("(a) perfect sticking, collisional, to 1e15 g", 60.0, column(60.0, 1e4, "collisional", 1e15, 1e5)),
        ("    perfect sticking, full, to 1e15 g", 40.0, column(40.0, 1e4, "full", 1e15, 1e5)),
        ("    perfect sticking, collisional, to 1e15 g", 20.0, column(20.0, 1e4, "collisional", 1e15, 1e5)),
    ];
    let mut all = cases;
    if !quick {
        all.push(("(b) erosion at 20 m/s, full, to 1e4 yr", 40.0, column(40.0, 20.0, "full", 1e21, 1e4)));
        all.push(("(b) erosion at 20 m/s, full, to 1e4 yr", 20.0, column(20.0, 20.0, "full", 1e21, 1e4)));
    }
    for (name, w, cfg) in all {
        let (t, r) = timed(&cfg);
        let last = r.history.last().copied();
        let fam = last.map_or(0, |s| s.families);
        let dm = r.history.iter().map(|s| s.mass_error.abs()).fold(0.0, f64::max);
        println!("  {name:<43} {w:>4} {t:>10.1} {:>8} {:>11.0} {fam:>10} {dm:>9.1e}", r.events, r.events as f64 / t);
        if let Some(s) = last {
            println!(
                "      at {:.0} yr: m_p {:.2e} g, m_max {:.2e} g, Omega t_s(m_max) {:.2}, zeta {:.2} ({})",
                s.t / YEAR,
                s.m_p * 1e3,
                s.m_max * 1e3,
                s.stokes_max,
                s.zeta,
                r.ended
            );
        }
    }
    println!("  targets: (a) <= 30 s, (b) <= 120 s per run");
}
