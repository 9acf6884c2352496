//! Smallest fragments in debris-disk collisions (thesis ch. 6).

use grainscope::physics::debris::{
    AU, TABLE_6_1, coefficient, fragment_mass_and_area, ratio_to_blowout, ratio_to_blowout_printed, smallest_fragment,
    smallest_fragment_64, smallest_fragment_erosion, smallest_fragment_unequal, split_size, splitting_limit,
};
use grainscope::scene::{self, Progress, SceneParams};

const SIL: grainscope::physics::debris::DebrisMaterial = TABLE_6_1[0];

#[test]
fn splitting_limit_follows_from_6_4() {
    // (6.4) with s_min = s_max = 2^{-1/3} s₀ gives s_min ≈ 5γ/(ηρv²) (6.6).
    for m in TABLE_6_1 {
        let (eta, v) = (1e-2, 20.0);
        let s0 = 24.0 * m.surface_energy * (2f64.cbrt() - 1.0) / (eta * m.density * v * v);
        let s_max = 2f64.powf(-1.0 / 3.0) * s0;
        let s_min = smallest_fragment_64(&m, eta, v, s0, s_max);
        assert!((s_min / s_max - 1.0).abs() < 1e-9);
        assert!((s_min / splitting_limit(&m, eta, v) - 1.0).abs() < 0.02, "{}", m.name);
        // (6.5) lies within a factor 5/3 of (6.6).
        let ratio = splitting_limit(&m, eta, v) / split_size(&m, eta, v);
        assert!((ratio - 5.0 / 3.0).abs() < 1e-12);
    }
}

#[test]
fn prefactor_of_6_8_recomputed() {
    let computed = ratio_to_blowout(0.1, 1e-2, 1e-2, 5.0 * AU, 1.0);
    assert!((computed - 1.2).abs() < 0.05, "{computed}");
    // 2.82 µm / 2.30 µm at 5 AU for ice-like density, as in the notes.
    let s_min = splitting_limit(
        &grainscope::physics::debris::DebrisMaterial { name: "", density: 1000.0, surface_energy: 0.1 },
        1e-2,
        1e-2 * (grainscope::physics::debris::G * grainscope::physics::debris::M_SUN / (5.0 * AU)).sqrt(),
    );
    assert!((s_min / 2.82e-6 - 1.0).abs() < 0.01, "{s_min}");
    assert!((ratio_to_blowout_printed(0.1, 1e-2, 1e-2, 5.0 * AU, 1.0) - 2.4).abs() < 1e-12);
    // Scalings: ∝ a L⁻¹ f⁻² η⁻¹ γ.
    let base = ratio_to_blowout(0.1, 1e-2, 1e-2, 50.0 * AU, 1.0);
    assert!((ratio_to_blowout(0.1, 1e-2, 1e-2, 100.0 * AU, 1.0) / base - 2.0).abs() < 1e-9);
    assert!((ratio_to_blowout(0.1, 1e-2, 2e-2, 50.0 * AU, 1.0) / base - 0.25).abs() < 1e-9);
    assert!((ratio_to_blowout(0.1, 1e-2, 1e-2, 50.0 * AU, 2.0) / base - 0.5).abs() < 1e-9);
}

#[test]
fn submicron_silicate_fragments_need_centimetre_colliders() {
    let p = grainscope::scene::debris::common::FragmentParams::default();
    let s0 = grainscope::scene::debris::smallest_fragment::collider_for(&p, 0, 1e-6).expect("exists");
    assert!((5e-3..=1e-1).contains(&s0), "collider radius {s0} m");
    // Smaller colliders cannot make sub-micron silicate fragments.
    let s = smallest_fragment(&SIL, 3.5, 1e-2, 20.0, 1e-3, 2f64.powf(-1.0 / 3.0) * 1e-3).expect("valid");
    assert!(s > 1e-6);
}

#[test]
fn fragment_distribution_conserves_mass() {
    for alpha in [3.2, 3.5, 3.8] {
        let s0 = 1.0;
        let s_max = 0.7;
        let c = coefficient(alpha, s0, s_max);
        let (m, _) = fragment_mass_and_area(alpha, c, SIL.density, 1e-6, s_max);
        let m0 = 4.0 / 3.0 * std::f64::consts::PI * SIL.density * s0.powi(3);
        assert!((m / (2.0 * m0) - 1.0).abs() < 1e-12, "α = {alpha}");
    }
}

#[test]
fn unequal_collisions_reduce_to_equal_and_erosion_scales_with_kappa() {
    let (eta, v, s) = (1e-2, 50.0, 0.1);
    let s_max = 2f64.powf(-1.0 / 3.0) * s;
    let equal = smallest_fragment_unequal(&SIL, eta, v, s, s, s_max);
    // The large-energy limit of (6.4).
    let asymptote = (24.0 * SIL.surface_energy / (eta * SIL.density * v * v)).powi(2) / s_max;
    assert!((equal / asymptote - 1.0).abs() < 1e-12);
    assert!(
        (smallest_fragment_erosion(&SIL, eta, v, 2.0, s_max) / smallest_fragment_erosion(&SIL, eta, v, 1.0, s_max)
            - 4.0)
            .abs()
            < 1e-12
    );
    // Near-equal masses give the smallest fragments among catastrophic collisions.
    let n = grainscope::scene::debris::unequal_colliders::normalised_catastrophic;
    assert!((n(1.0) - 1.0).abs() < 1e-12 && n(0.5) > 1.0 && n(2.0) > 1.0);
}

#[test]
fn bad_slopes_and_ranges_are_reported() {
    let mut p = SceneParams::default_for("smallest-fragment").expect("scene");
    assert!(p.set("alpha", "4.2").is_err());
    assert!(p.set("alpha", "3.0").is_err());
    p.set("s0_min", "10").expect("in range");
    p.set("s0_max", "1").expect("in range");
    assert!(scene::compute(&p, &Progress::default()).is_err());
    assert!(smallest_fragment(&SIL, 3.5, 1e-2, 20.0, 1.0, 0.0).is_err());
}

#[test]
fn debris_scenes_compute_with_defaults() {
    for id in ["smallest-fragment", "critical-energies", "debris-disks", "unequal-colliders"] {
        let out = scene::compute(&SceneParams::default_for(id).expect(id), &Progress::default()).expect(id);
        assert!(out.figures.iter().all(|f| f.series.iter().any(|s| !s.points.is_empty())), "{id}");
    }
}
