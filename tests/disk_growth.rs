//! Porous aggregates in a disk (thesis ch. 4.2, 4.5, App. 5.A–5.C).

use grainscope::physics::aggregate::{
    Aggregate, DragRegime, Monomer, Particle, TurbulenceModel, relative_velocity, stopping_time,
};
use grainscope::physics::constants::{AU, YEAR};
use grainscope::physics::disk::GasDisk;
use grainscope::physics::growth::{GrowthModel, Porosity, Stop};
use grainscope::scene::{self, Progress, SceneParams};

fn env5() -> grainscope::physics::disk::Local {
    GasDisk::mmsn(1e-3, 1e-2).local(5.0 * AU)
}

#[test]
fn figure_4_1_drag_transitions() {
    let env = env5();
    let mono = Monomer::ice();
    let m0 = mono.mass();
    let st = |n: f64, phi: f64| {
        let s = stopping_time(&env, &mono, &Aggregate { mass: n * m0, filling: phi }, true);
        (s.time * env.omega, s.regime)
    };
    // Compact grains reach Ωt_s = 1 while still in Epstein drag.
    let n1 = (0..400).map(|i| 10f64.powf(i as f64 / 10.0)).find(|&n| st(n, 1.0).0 >= 1.0).expect("reaches 1");
    assert_eq!(st(n1, 1.0).1, DragRegime::Epstein);
    // D_f = 2.5 aggregates: Stokes drag near Ωt_s ~ 1e-3, Re_p > 1 near 1e21 m₀, C_D = 0.44 beyond ~1e26 m₀.
    let fractal = |n: f64| n.powf(1.0 - 3.0 / 2.5);
    let first = |regime: DragRegime| {
        (0..330).map(|i| 10f64.powf(i as f64 / 10.0)).find(|&n| st(n, fractal(n)).1 == regime).expect("regime reached")
    };
    let stokes = first(DragRegime::Stokes);
    let st_at = st(stokes, fractal(stokes)).0;
    assert!((1e-4..=1e-2).contains(&st_at), "Epstein→Stokes at Ωt_s = {st_at}");
    let re1 = first(DragRegime::Intermediate);
    assert!((1e20..=1e22).contains(&re1), "Re_p > 1 at m/m₀ = {re1:e}");
    assert!(st(re1, fractal(re1)).0 < 1.0, "the Newton transition comes before Ωt_s = 1");
    let newton = first(DragRegime::Newton);
    assert!((1e25..=1e27).contains(&newton), "C_D = 0.44 from m/m₀ = {newton:e}");
}

#[test]
fn stopping_times_and_velocities_are_finite_over_the_documented_ranges() {
    let mono = Monomer::ice();
    let m0 = mono.mass();
    let mut worst = 0;
    for r_au in [1.0, 5.0, 30.0, 100.0, 300.0] {
        let env = GasDisk::mmsn(1e-3, 1e-2).local(r_au * AU);
        let mono_p = Particle {
            mass: m0,
            stokes: stopping_time(&env, &mono, &Aggregate { mass: m0, filling: 1.0 }, true).time * env.omega,
        };
        for i in 0..=60 {
            let n = 10f64.powf(i as f64 / 2.0);
            for phi in [1e-6, 1e-4, 1e-2, 1.0] {
                let s = stopping_time(&env, &mono, &Aggregate { mass: n * m0, filling: phi }, true);
                assert!(s.time.is_finite() && s.time > 0.0, "R = {r_au}, N = {n:e}, φ = {phi}: {s:?}");
                worst = worst.max(s.iterations);
                let p = Particle { mass: n * m0, stokes: s.time * env.omega };
                for model in [TurbulenceModel::Thesis, TurbulenceModel::OrmelCuzzi] {
                    let v = relative_velocity(&env, &p, &mono_p, model, 0.1).total();
                    assert!(v.is_finite() && v > 0.0, "R = {r_au}, N = {n:e}, φ = {phi}: v = {v}");
                }
            }
        }
    }
    assert!(worst <= 60, "Newton iteration took {worst} steps");
}

#[test]
fn published_track_numbers_at_5_au() {
    let mut model = GrowthModel::chapter4(Porosity::Collisional);
    model.drift = false;
    let coll = model.run(5.0 * AU, 1e8 * YEAR);
    // φ ~ 1e-5 at the end of hit-and-stick growth (collisional compaction only).
    let [_, phi_c] = coll.markers.collisional.expect("collisional compaction starts");
    assert!((1e-6..=1e-4).contains(&phi_c), "φ at the end of hit-and-stick: {phi_c:e}");
    model.porosity = Porosity::Full;
    let full = model.run(5.0 * AU, 1e8 * YEAR);
    assert_eq!(full.stop, Stop::Planetesimal);
    // Ωt_s = 1 near 1e9–1e10 g.
    let [m1, _] = full.markers.stokes_one.expect("reaches Ωt_s = 1");
    assert!((1e5..=1e8).contains(&m1), "Ωt_s = 1 at {} g", m1 * 1e3);
    // Self-gravity compaction above ~1e10–1e12 g, and φ rises towards 1e-1.
    let [mg, _] = full.markers.gravity.expect("self-gravity compaction");
    assert!((1e7..=1e9).contains(&mg), "self-gravity from {} g", mg * 1e3);
    let last = full.points.last().expect("points");
    assert!(last.filling > 1e-2, "final φ {}", last.filling);
    // Gas compaction sets in before the first collisional compaction (Sect. 4.4.1).
    assert!(full.markers.gas.expect("gas compaction")[0] < full.markers.collisional.expect("collisional")[0]);
    // Perfect sticking outgrows drift: t_grow ≪ t_drift throughout.
    let worst = full.points.iter().filter(|q| q.t_grow.is_finite()).map(|q| q.t_grow / q.t_drift).fold(0.0, f64::max);
    assert!(worst < 0.1, "t_grow/t_drift up to {worst}");
}

#[test]
fn erosion_stalls_growth_near_stokes_one_and_perfect_sticking_outgrows_drift() {
    let mut model = GrowthModel::chapter4(Porosity::Full);
    let free = model.run(5.0 * AU, 1e6 * YEAR);
    assert_eq!(free.stop, Stop::Planetesimal);
    assert!(free.points.last().expect("points").r > 4.0 * AU, "drifted too far before forming");
    model.thresholds.v_eros = 40.0;
    let eroded = model.run(5.0 * AU, 1e6 * YEAR);
    assert_eq!(eroded.halted_by, Some("erosion"));
    let st_max = eroded.points.iter().map(|q| q.stokes).fold(0.0, f64::max);
    assert!((0.1..=3.0).contains(&st_max), "stalls at Ωt_s = {st_max}");
    assert_ne!(eroded.stop, Stop::Planetesimal);
}

#[test]
fn compact_growth_is_limited_by_fragmentation_in_the_inner_disk() {
    let mut model = GrowthModel::chapter4(Porosity::Compact);
    model.thresholds.v_frag = 10.0;
    let t = model.run(5.0 * AU, 1e6 * YEAR);
    assert_eq!(t.halted_by, Some("fragmentation"));
    // Same-size turbulent velocities 1.55 δv_g (Ωt_s)^{1/2} reach 10 m/s near Ωt_s ≈ 0.09.
    let first = t.points.iter().find(|q| q.halted).expect("halted");
    assert!(
        first.v_rel >= 10.0 && (0.05..=0.2).contains(&first.stokes),
        "halted at v = {}, Ωt_s = {}",
        first.v_rel,
        first.stokes
    );
    let a_max = t.points.iter().map(|q| q.radius).fold(0.0, f64::max);
    assert!(a_max < 1.0, "compact grains stay below a metre: {a_max} m");
}

#[test]
fn disk_scenes_compute_with_defaults() {
    for id in ["stokes-number", "collision-speeds", "porosity-track", "timescales", "growth-tracks"] {
        let out = scene::compute(&SceneParams::default_for(id).expect(id), &Progress::default()).expect(id);
        assert!(!out.figures.is_empty(), "{id}");
    }
}
