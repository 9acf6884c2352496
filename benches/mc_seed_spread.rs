//! The seed spread of the erosion column (Figs. 4.9 and 4.12): for seeds
//! 1…N, the first erosion of the largest body (ζ < 1), the time from which
//! m_max stays within 3× of its steady value, the steady m_max and Ωt_s of
//! the largest body, m_p at the end and the events, with the mean and
//! standard deviation over the seeds. These are the observables the
//! reproduce rows of Figs. 4.9 and 4.12 check on one run; a change to the
//! engine should leave their distribution where it was.
//!
//! Run with `cargo bench --bench mc_seed_spread -- [w*] [seeds]` (default
//! w* = 20, the setting `reproduce --quick` checks, and 8 seeds).

use grainscope::physics::constants::YEAR;
use grainscope::scene::SceneParams;
use grainscope::scene::monte_carlo::erosion_balance::steady_state;
use rayon::prelude::*;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with('-')).collect();
    let w_star: f64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(20.0);
    let seeds: u64 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(8);
    let preset = grainscope::preset::resolve("mc-fig-4-9").expect("shipped preset");
    let SceneParams::MassDistribution(scene) = preset.scene else {
        panic!("mc-fig-4-9 is a mass distribution");
    };
    let mut column = scene.run;
    column.groups_per_decade = w_star;
    column.runs = 1;
    let config = column.config().expect("valid column");
    println!(
        "Erosion column of mc-fig-4-9 at w* = {w_star}, seeds 1 to {seeds}, {} threads",
        rayon::current_num_threads()
    );
    println!(
        "{:>5} {:>10} {:>9} {:>18} {:>12} {:>11} {:>12} {:>8}",
        "seed", "events", "time [s]", "first erosion [yr]", "settled [yr]", "m_max [kg]", "St(m_max)", "m_p [kg]"
    );
    let rows: Vec<[f64; 7]> = (1..=seeds)
        .into_par_iter()
        .map(|seed| {
            let start = Instant::now();
            let run = config.run(seed, &|_| true).expect("runs");
            let took = start.elapsed().as_secs_f64();
            let first = run.history.iter().position(|q| q.zeta < 1.0).map_or(f64::NAN, |k| {
                let (t0, t1) = (run.history[k.saturating_sub(1)].t, run.history[k].t);
                (t0 * t1).sqrt() / YEAR
            });
            let (st_steady, m_steady) = steady_state(&run);
            let settled = run
                .history
                .iter()
                .rev()
                .take_while(|q| (q.m_max / m_steady).log10().abs() <= 3f64.log10())
                .last()
                .map_or(f64::NAN, |q| q.t / YEAR);
            let m_p = run.history.last().map_or(f64::NAN, |q| q.m_p);
            [seed as f64, run.events as f64, took, first, settled, m_steady, st_steady, m_p]
        })
        .map(|r| [r[1], r[2], r[3], r[4], r[5], r[6], r[7]])
        .collect();
    for (k, r) in rows.iter().enumerate() {
        println!(
            "{:>5} {:>10.0} {:>9.1} {:>18.0} {:>12.0} {:>11.3e} {:>12.3} {:>8.3e}",
            k + 1,
            r[0],
            r[1],
            r[2],
            r[3],
            r[4],
            r[5],
            r[6]
        );
    }
    let stat = |i: usize, log: bool| {
        let v: Vec<f64> =
            rows.iter().map(|r| if log { r[i].log10() } else { r[i] }).filter(|x| x.is_finite()).collect();
        let n = v.len() as f64;
        let mean = v.iter().sum::<f64>() / n;
        let sd = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0)).sqrt();
        (mean, sd)
    };
    let (e, es) = stat(0, false);
    let (f, fs) = stat(2, false);
    let (s, ss) = stat(3, true);
    let (m, ms) = stat(4, true);
    let (st, sts) = stat(5, false);
    let (p, ps) = stat(6, true);
    println!(
        "mean ± sd: events {e:.0} ± {es:.0}; first erosion {f:.0} ± {fs:.0} yr; log10 settled [yr] {s:.3} ± {ss:.3};"
    );
    println!(
        "           log10 m_max [kg] {m:.2} ± {ms:.2}; St(m_max) {st:.3} ± {sts:.3}; log10 m_p [kg] {p:.2} ± {ps:.2}"
    );
}
