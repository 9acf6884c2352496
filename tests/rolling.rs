//! Rolling friction (thesis ch. 3): the published checks of physics notes §2.

use grainscope::physics::rolling::{
    Rocking, bulk_torque, critical_displacement, rocking_frequency, rolling_force, rolling_torque,
    small_asymmetry_torque,
};
use grainscope::scene::rolling::common::RollingParams;
use grainscope::scene::rolling::rocking::measured_frequency;
use grainscope::scene::{self, Progress, SceneParams};

fn peri() -> RollingParams {
    // Peri & Cetinkaya: 21.4 µm PSL sphere on aluminium, γ = 0.1 J/m².
    RollingParams::of("PSL", "aluminium alloy", true, 10.7e-6, 0.1)
}

#[test]
fn psl_on_aluminium_contact_and_rocking_frequency() {
    let p = peri();
    let pair = p.pair(10.7e-6);
    let a_eq = pair.jkr_equilibrium_radius();
    assert!((350e-9..=400e-9).contains(&a_eq), "a_eq = {a_eq}");
    let f0 = rocking_frequency(&pair, p.inertia(10.7e-6));
    assert!((f0 / 150e3 - 1.0).abs() < 0.02, "f0 = {f0}");
    // (3.20)'s second form depends only on γ, ρ and R.
    let closed = 3.0 / (4.0 * std::f64::consts::PI) * (5.0 * 0.1 / (1026.0 * 10.7e-6f64.powi(3))).sqrt();
    assert!((f0 / closed - 1.0).abs() < 1e-12);
    // 0.16° of rocking ↔ ξ = 30 nm = 0.08 a_eq, M ≈ 6e-13 N m, so Δγ/γ > 0.95.
    let xi = 30e-9;
    assert!(((xi / 10.7e-6f64).to_degrees() - 0.16).abs() < 0.01);
    assert!((xi / a_eq - 0.08).abs() < 0.006, "{}", xi / a_eq);
    let m = small_asymmetry_torque(&pair, xi);
    assert!((m / 6e-13 - 1.0).abs() < 0.05, "M = {m}");
    let h_min = 0.08 * 12.0;
    assert!((critical_displacement(&pair, h_min) / a_eq - 0.08).abs() < 1e-12);
    assert!((0.95..=0.97).contains(&h_min));
}

#[test]
fn silica_rolling_forces_for_half_hysteresis() {
    let silica = RollingParams::of("silicate", "silicate", false, 0.95e-6, 0.05);
    let force = |d: f64| {
        let pair = silica.pair(d / 2.0);
        rolling_force(&pair, rolling_torque(&pair, 0.5))
    };
    // The feel given in the notes: ~7e-10 N for 1.9 µm spheres.
    assert!((force(1.9e-6) / 7e-10 - 1.0).abs() < 0.05, "{}", force(1.9e-6));
    // Inside the error bars of Heim et al. and Blum & Wurm; outside Gundlach et al.'s.
    assert!((force(1.9e-6) - 8.5e-10).abs() <= 1.6e-10);
    assert!((force(1.9e-6) - 5.0e-10).abs() <= 2.5e-10);
    assert!((force(1.5e-6) - 12.1e-10).abs() > 3.6e-10);
    // F ∝ R^{2/3} at fixed Δγ/γ.
    assert!((force(3.8e-6) / force(1.9e-6) - 2f64.powf(2.0 / 3.0)).abs() < 1e-9);
}

#[test]
fn ding_critical_displacements_for_hysteresis_two_and_a_half() {
    let ding = RollingParams::of("PSL", "silicon", true, 12e-6, 0.1);
    for d in [22.5e-6, 24.0e-6, 26.8e-6] {
        let xi = critical_displacement(&ding.pair(d / 2.0), 2.5);
        assert!((73e-9..=94e-9).contains(&xi), "d = {d}: ξ_crit = {xi}");
    }
}

#[test]
fn dominik_tielens_limit_and_bulk_torque() {
    let p = peri();
    let pair = p.pair(10.7e-6);
    // ξ = 0.3 nm: M = 6πγRξ.
    let m = small_asymmetry_torque(&pair, 3e-10);
    assert!((m - 6.0 * std::f64::consts::PI * 0.1 * 10.7e-6 * 3e-10).abs() < 1e-25);
    // The bulk torque for Q = 100 is far below the crack torque of Δγ/γ = 1 (3.23).
    assert!(bulk_torque(&pair, 100.0) < 0.1 * rolling_torque(&pair, 1.0));
}

#[test]
fn undamped_rocking_conserves_energy_at_f0() {
    let p = peri();
    let pair = p.pair(10.7e-6);
    let inertia = p.inertia(10.7e-6);
    let a = pair.jkr_equilibrium_radius();
    let kick = Rocking::kick_for_amplitude(&pair, inertia, 0.01 * a);
    let r = Rocking { pair, inertia, hysteresis: 10.0, q: f64::INFINITY, kick };
    let s = r.run(50.0, 400);
    let e0 = s[0].energy;
    let drift = s.iter().map(|x| (x.energy / e0 - 1.0).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-8, "energy drift {drift}");
    let f = measured_frequency(&s).expect("oscillates");
    assert!((f / r.frequency() - 1.0).abs() < 0.005, "{f} vs {}", r.frequency());
    let amp = s.iter().map(|x| x.xi.abs()).fold(0.0, f64::max);
    assert!((amp / (0.01 * a) - 1.0).abs() < 1e-3, "amplitude {amp}");
    assert!(s.iter().all(|x| !x.rolling));
}

#[test]
fn quality_factor_thirty_damps_in_about_ten_periods() {
    let out = scene::compute(
        &grainscope::preset::resolve("rolling-psl-aluminium-rocking").expect("preset").scene,
        &Progress::default(),
    )
    .expect("rocking");
    let n = out.scalar("efold_periods").expect("e-folds");
    assert!((n / (30.0 / std::f64::consts::PI) - 1.0).abs() < 0.05, "{n} periods");
    let f = out.scalar("f_measured").expect("frequency");
    assert!((f / out.scalar("f0").expect("f0") - 1.0).abs() < 0.005);
    assert_eq!(out.scalar("rolled"), Some(0.0));
}

#[test]
fn a_kick_past_the_critical_displacement_rolls_then_pins_again() {
    let mut p = SceneParams::default_for("rocking").expect("scene");
    p.set("hysteresis", "0.3").expect("valid");
    p.set("kick_amplitude", "0.1").expect("valid");
    p.set("q", "1e12").expect("valid");
    let SceneParams::Rocking(params) = &p else { panic!("rocking") };
    let s = params.model().run(20.0, 400);
    let rolled = s.last().expect("samples").rolled;
    assert!(rolled > 0.0, "did not roll");
    assert!(s.iter().any(|x| x.rolling));
    assert!(!s.last().expect("samples").rolling, "ends pinned");
    // Energy only decreases once rolling dissipates it.
    assert!(s.windows(2).all(|w| w[1].energy <= w[0].energy * (1.0 + 1e-9)));
}

#[test]
fn rolling_scenes_recompute_with_defaults() {
    for id in ["contact-torque", "rolling-force", "critical-displacement", "rocking"] {
        let p = SceneParams::default_for(id).expect(id);
        let out = scene::compute(&p, &Progress::default()).expect(id);
        assert!(!out.figures.is_empty());
    }
    // The contact-torque scene: (3.10) against (3.14) at ξ/a = 0.1.
    let out = scene::compute(&SceneParams::default_for("contact-torque").expect("scene"), &Progress::default())
        .expect("scene");
    let ratio = out.scalar("torque").expect("M") / out.scalar("torque_small").expect("M14");
    assert!((ratio - 1.015).abs() < 1e-3, "{ratio}");
}
