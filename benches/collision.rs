//! Speed against error of the collision solver and the collision scenes.
//!
//! Run with `cargo bench --bench collision`. For each tolerance it prints the
//! time per collision (median of repeated runs) and |e − e_ref|, where e_ref
//! comes from a run at rtol = 1e-11; then the time of whole scenes.
//! `cargo bench --bench collision -- solver` prints the solver's tables alone;
//! `-- sweep` prints, for four families of collisions over a range of
//! speeds each, the mean time and steps per collision and the worst and the
//! median |e − e_ref|.

use grainscope::physics::collision::{Options, Setup, collide, sticking_search};
use grainscope::physics::crack::CrackLaw;
use grainscope::scene::grid::logspace;
use grainscope::scene::{self, Caches, Progress, SceneParams};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Median wall time of `f` over enough repetitions to fill ~0.3 s.
fn time<T>(mut f: impl FnMut() -> T) -> Duration {
    let start = Instant::now();
    black_box(f());
    let once = start.elapsed().max(Duration::from_nanos(100));
    let reps = ((0.3 / once.as_secs_f64()) as usize).clamp(3, 2000);
    let mut samples: Vec<Duration> = (0..reps)
        .map(|_| {
            let t = Instant::now();
            black_box(f());
            t.elapsed()
        })
        .collect();
    samples.sort();
    samples[samples.len() / 2]
}

fn solver_table(name: &str, setup: &Setup, v: f64) {
    let e_ref = collide(setup, v, &Options { rtol: 1e-11, ..Options::default() }).expect("reference").e_adhesive;
    println!("\n{name}: v = {v} m/s, T_vis = {:e} s, e_ref = {e_ref:.10}", setup.t_vis);
    println!("{:>8} {:>12} {:>8} {:>12}", "rtol", "time [µs]", "steps", "|e - e_ref|");
    for rtol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9] {
        let opts = Options { rtol, ..Options::default() };
        let c = collide(setup, v, &opts).expect("collision");
        let t = time(|| collide(setup, v, &opts).expect("collision").e_adhesive);
        println!(
            "{rtol:>8.0e} {:>12.1} {:>8} {:>12.2e}",
            t.as_secs_f64() * 1e6,
            c.stats.accepted,
            (c.e_adhesive - e_ref).abs()
        );
    }
}

/// Speed against error over ranges of speeds: reference ice at 3–25 m/s, the
/// quasi-static hard cases T_vis = 10⁻¹⁴ and 10⁻¹⁵ s at 1.5–20 m/s and a
/// viscous case T_vis = 10⁻¹⁰ s at 30–200 m/s, 40 speeds each (sticking
/// collisions among them), e_ref at rtol 10⁻¹¹. Per tolerance: the mean time,
/// accepted and rejected steps of a collision and the worst |e − e_ref| with
/// the speed where it occurs.
fn sweeps() {
    let ice = Setup::reference_ice();
    let with_t_vis = |t_vis| Setup { t_vis, ..ice };
    let cases = [
        ("reference ice, 3-25 m/s", ice, logspace(3.0, 25.0, 40)),
        ("T_vis = 1e-14 s, 1.5-20 m/s", with_t_vis(1e-14), logspace(1.5, 20.0, 40)),
        ("T_vis = 1e-15 s, 1.5-20 m/s", with_t_vis(1e-15), logspace(1.5, 20.0, 40)),
        ("T_vis = 1e-10 s, 30-200 m/s", with_t_vis(1e-10), logspace(30.0, 200.0, 40)),
    ];
    println!(
        "{:<30} {:>6} {:>10} {:>8} {:>8} {:>12} {:>8} {:>12}",
        "case", "rtol", "time [µs]", "steps", "rejected", "worst |Δe|", "at v", "median |Δe|"
    );
    for (name, setup, vs) in &cases {
        let reference: Vec<f64> = vs
            .iter()
            .map(|&v| collide(setup, v, &Options { rtol: 1e-11, ..Options::default() }).expect("reference").e_adhesive)
            .collect();
        for rtol in [1e-5, 3e-6, 1e-6] {
            let opts = Options { rtol, ..Options::default() };
            let (mut steps, mut rejected, mut worst, mut at) = (0, 0, 0.0_f64, 0.0);
            let mut errors = Vec::new();
            for (&v, &e_ref) in vs.iter().zip(&reference) {
                let c = collide(setup, v, &opts).expect("collision");
                steps += c.stats.accepted;
                rejected += c.stats.rejected;
                let err = (c.e_adhesive - e_ref).abs();
                errors.push(err);
                if err > worst {
                    (worst, at) = (err, v);
                }
            }
            errors.sort_by(f64::total_cmp);
            let median = errors[errors.len() / 2];
            let t = time(|| vs.iter().map(|&v| collide(setup, v, &opts).expect("collision").e_adhesive).sum::<f64>());
            let n = vs.len() as f64;
            println!(
                "{name:<30} {rtol:>6.0e} {:>10.1} {:>8.1} {:>8.1} {worst:>12.2e} {at:>8.2} {median:>12.2e}",
                t.as_secs_f64() * 1e6 / n,
                steps as f64 / n,
                rejected as f64 / n
            );
        }
    }
}

fn main() {
    if std::env::args().skip(1).any(|a| a == "sweep") {
        sweeps();
        return;
    }
    let ice = Setup::reference_ice();
    solver_table("reference ice collision", &ice, 8.0);
    solver_table("reference ice, the thesis's crack law", &ice.with_crack(CrackLaw::thesis(0.02)), 8.0);
    let mut hard = ice;
    hard.t_vis = 1e-14;
    solver_table("quasi-static hard case", &hard, 4.0);
    solver_table("quasi-static hard case, the thesis's crack law", &hard.with_crack(CrackLaw::thesis(0.02)), 4.0);
    let mut harder = ice;
    harder.t_vis = 1e-15;
    solver_table("quasi-static, T_vis = 1e-15 s", &harder, 4.0);
    let mut viscous = ice;
    viscous.t_vis = 1e-10;
    solver_table("viscous, T_vis = 1e-10 s", &viscous, 100.0);

    if std::env::args().skip(1).any(|a| a == "solver") {
        return;
    }
    println!("\nscenes (default parameters, {} threads):", rayon::current_num_threads());
    let hysteresis = SceneParams::default_for("hysteresis").expect("scene");
    let t = time(|| scene::compute(&hysteresis, &Progress::default()).expect("scene"));
    println!("  hysteresis (one recorded collision):            {:>8.2} ms", t.as_secs_f64() * 1e3);
    let restitution = SceneParams::default_for("restitution").expect("scene");
    let t = time(|| scene::compute(&restitution, &Progress::default()).expect("scene"));
    println!("  restitution, all three panels:                  {:>8.2} ms", t.as_secs_f64() * 1e3);
    let t = recompute_time(&restitution, "v_min", ["0.5", "0.50001"]);
    println!("  restitution, e(v) at 200 velocities + v_stick:   {:>8.2} ms", t.as_secs_f64() * 1e3);
    let t = recompute_time(&restitution, "t_vis", ["1e-11", "1.1e-11"]);
    println!("  restitution, a change of T_vis (e(v) and e(R)):  {:>8.2} ms", t.as_secs_f64() * 1e3);
    restitution_accuracy();
    println!("  every scene with its default parameters:");
    for info in scene::SCENES {
        let p = SceneParams::default_for(info.id).expect("scene");
        let t = time(|| scene::compute(&p, &Progress::default()).expect("scene"));
        println!("    {:<24} {:>9.3} ms{}", info.id, t.as_secs_f64() * 1e3, if info.heavy { "  (worker)" } else { "" });
    }
}

/// Time of a cached recomputation of scene `p` when `key` alternates
/// between two values: what that parameter's change costs in the window.
fn recompute_time(p: &SceneParams, key: &str, values: [&str; 2]) -> Duration {
    let mut caches = Caches::default();
    scene::compute_cached(p, &Progress::default(), &mut caches).expect("scene");
    let mut flip = false;
    time(|| {
        flip = !flip;
        let mut q = p.clone();
        q.set(key, values[usize::from(flip)]).expect("valid");
        scene::compute_cached(&q, &Progress::default(), &mut caches).expect("scene")
    })
}

/// The e(v) panel of the restitution scene against a dense reference: the
/// model computed at every one of its 200 velocities at rtol = 1e-10, for the
/// reference ice set, a quasi-static (T_vis = 1e-14 s) and a viscous
/// (T_vis = 1e-10 s) case, with the collisions the sticking-velocity search
/// took.
fn restitution_accuracy() {
    println!("\n  e(v) panel against every velocity computed at rtol 1e-10:");
    println!("  {:<28} {:>9} {:>12} {:>10} {:>10}", "case", "time [ms]", "max |Δe|", "v_s [m/s]", "v_s evals");
    for (name, t_vis) in [("reference ice", None), ("T_vis = 1e-14 s", Some(1e-14)), ("T_vis = 1e-10 s", Some(1e-10))] {
        let mut p = SceneParams::default_for("restitution").expect("scene");
        if let Some(t) = t_vis {
            p.set("t_vis", &t.to_string()).expect("valid");
        }
        let t = recompute_time(&p, "v_min", ["0.5", "0.50001"]);
        let out = scene::compute(&p, &Progress::default()).expect("scene");
        let curve = &out.figures[0].series.iter().find(|s| s.name == "e (model)").expect("e(v)").points;
        let mut setup = Setup::reference_ice();
        if let Some(t) = t_vis {
            setup.t_vis = t;
        }
        let tight = Options { rtol: 1e-10, ..Options::default() };
        let worst = curve
            .iter()
            .map(|&[v, e]| (collide(&setup, v, &tight).expect("collision").e_adhesive - e).abs())
            .fold(0.0, f64::max);
        let search = sticking_search(&setup, &Options::default(), 1e-4).expect("v_s");
        println!(
            "  {name:<28} {:>9.2} {worst:>12.2e} {:>10.4} {:>10}",
            t.as_secs_f64() * 1e3,
            search.velocity,
            search.evaluations
        );
    }
}
