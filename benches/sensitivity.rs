//! Speed of the sensitivity tools: a 50-point curve of an analytic scene,
//! the restitution scene's "what matters" (through the quick path to v_s,
//! and through whole computations), a 24 × 24 map, each from a cold cache and
//! again from a warm one, and the formation zone's ranking (coarse, then
//! full: about two minutes). Run with `cargo bench --bench sensitivity`.

use grainscope::scene::{Progress, SceneParams};
use grainscope::sensitivity::{curve, map, what_matters};
use std::time::Instant;

/// Runs `f` twice (cold cache, then warm) and prints both times.
fn time<T>(what: &str, f: impl Fn() -> T) -> T {
    let start = Instant::now();
    f();
    let cold = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let out = f();
    let warm = start.elapsed().as_secs_f64();
    println!("{what:<58} {:>9.1} {:>9.1}", cold * 1e3, warm * 1e3);
    out
}

fn main() {
    let progress = Progress::default();
    let scene = |id: &str| SceneParams::default_for(id).expect("scene");
    println!("{} threads", rayon::current_num_threads());
    println!("{:<58} {:>9} {:>9}", "", "cold [ms]", "warm [ms]");
    let hysteresis = scene("hysteresis");
    time("curve: JKR v_c over γ, 50 points (hysteresis)", || {
        curve(&hysteresis, "v_c", "surface_energy", 50, &progress).expect("curve")
    });
    let restitution = scene("restitution");
    let m = time("what matters: v_stick, 15 parameters (restitution)", || {
        what_matters(&restitution, "v_stick", 2.0, &progress).expect("matters")
    });
    let gamma = m.rows.iter().find(|r| r.key == "surface_energy").expect("γ");
    println!("  elasticity of v_stick in γ: {:+.4}", gamma.elasticity.unwrap_or(f64::NAN));
    time("what matters: e_max, the e(v) panel alone (restitution)", || {
        what_matters(&restitution, "e_max", 2.0, &progress).expect("matters")
    });
    time("curve: v_stick over γ, 50 points (restitution)", || {
        curve(&restitution, "v_stick", "surface_energy", 50, &progress).expect("curve")
    });
    time("map: v_stick over γ and T_vis, 24 × 24 (restitution)", || {
        map(&restitution, "v_stick", "surface_energy", "t_vis", 24, &progress).expect("map")
    });
    // The formation zone of Fig. 5.10: the window's coarse first answer, then the full one.
    let zone = grainscope::preset::resolve("batch-fig-5-10").expect("shipped").scene;
    let coarse = zone.coarse().expect("a coarse preview");
    time("what matters: widest_zone, coarse first answer (Fig. 5.10)", || {
        what_matters(&coarse, "widest_zone", 2.0, &progress).expect("matters")
    });
    time("what matters: widest_zone, full (Fig. 5.10)", || {
        what_matters(&zone, "widest_zone", 2.0, &progress).expect("matters")
    });
    let kernels = scene("kernel-tests");
    time("what matters: events, seed by seed (kernel tests)", || {
        what_matters(&kernels, "events", 2.0, &progress).expect("matters")
    });
}
