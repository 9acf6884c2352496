//! Global sensitivity (src/global_sensitivity.rs): Sobol' indices against
//! the analytic indices of the Ishigami and Sobol' G functions, Morris's
//! measures against functions whose elementary effects are known exactly,
//! and the stated rule for undefined outputs.

use grainscope::global_sensitivity::{
    Design, Factor, Method, morris, morris_design, parse_factor, sobol, sobol_design, sobol_runs_per_sample,
};
use std::f64::consts::PI;

/// Ishigami & Homma (1990) with a = 7, b = 0.1 on [−π, π]³.
fn ishigami(x: &[f64]) -> f64 {
    let (a, b) = (7.0, 0.1);
    x[0].sin() + a * x[1].sin().powi(2) + b * x[2].powi(4) * x[0].sin()
}

/// Its analytic first-order and total indices, and S13.
fn ishigami_indices() -> ([f64; 3], [f64; 3], f64) {
    let (a, b) = (7.0f64, 0.1f64);
    let v1 = 0.5 * (1.0 + b * PI.powi(4) / 5.0).powi(2);
    let v2 = a * a / 8.0;
    let v13 = b * b * PI.powi(8) * (1.0 / 18.0 - 1.0 / 50.0);
    let v = v1 + v2 + v13;
    ([v1 / v, v2 / v, 0.0], [(v1 + v13) / v, v2 / v, v13 / v], v13 / v)
}

/// The Sobol' G function on [0, 1]^d with coefficients `a`.
fn g_function(x: &[f64], a: &[f64]) -> f64 {
    x.iter().zip(a).map(|(x, a)| ((4.0 * x - 2.0).abs() + a) / (1.0 + a)).product()
}

fn unit_to(x: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    x.iter().map(|u| lo + u * (hi - lo)).collect()
}

#[test]
fn sobol_indices_of_the_ishigami_function_meet_the_analytic_values() {
    let (s1, st, s13) = ishigami_indices();
    let design = sobol_design(3, 4096, true, 1).expect("a design");
    let y: Vec<f64> = design.iter().map(|x| ishigami(&unit_to(x, -PI, PI))).collect();
    let r = sobol(&y, 3, true, 200, 7);
    assert_eq!((r.samples, r.dropped), (4096, 0));
    for i in 0..3 {
        let got = r.indices[i];
        assert!((got.first - s1[i]).abs() < 0.02, "S1[{i}] = {} vs {}", got.first, s1[i]);
        assert!((got.total - st[i]).abs() < 0.02, "ST[{i}] = {} vs {}", got.total, st[i]);
        // The intervals are of the size of the error, not far wider.
        assert!(got.first_conf > 0.0 && got.first_conf < 0.1, "{got:?}");
    }
    let (s2, _) = r.second.expect("second-order indices");
    assert!((s2[0][2] - s13).abs() < 0.04, "S13 = {} vs {s13}", s2[0][2]);
    assert!(s2[0][1].abs() < 0.04 && s2[1][2].abs() < 0.04, "{s2:?}");
}

#[test]
fn sobol_indices_of_the_g_function_meet_the_analytic_values() {
    let a = [0.0, 1.0, 4.5, 9.0, 99.0, 99.0, 99.0, 99.0];
    let v: Vec<f64> = a.iter().map(|a| 1.0 / (3.0 * (1.0 + a) * (1.0 + a))).collect();
    let total_v = v.iter().map(|v| 1.0 + v).product::<f64>() - 1.0;
    let design = sobol_design(a.len(), 8192, false, 3).expect("a design");
    let y: Vec<f64> = design.iter().map(|x| g_function(x, &a)).collect();
    let r = sobol(&y, a.len(), false, 100, 3);
    for (i, vi) in v.iter().enumerate() {
        let s1 = vi / total_v;
        let st = vi * v.iter().enumerate().filter(|(j, _)| *j != i).map(|(_, v)| 1.0 + v).product::<f64>() / total_v;
        let got = r.indices[i];
        assert!((got.first - s1).abs() < 0.02, "S1[{i}] = {} vs {s1}", got.first);
        assert!((got.total - st).abs() < 0.02, "ST[{i}] = {} vs {st}", got.total);
    }
    assert!(r.second.is_none());
}

#[test]
fn morris_measures_of_a_linear_function_are_its_coefficients() {
    // y = 3 x₀ − 2 x₁ + 0 x₂ over x₀ ∈ [0, 1], x₁ ∈ [0, 2]: an elementary
    // effect per whole range is 3, −4 and 0, exactly, at every step.
    let design = morris_design(3, 12, 4, 5).expect("a design");
    let y: Vec<f64> = design.iter().map(|u| 3.0 * u[0] - 2.0 * (2.0 * u[1]) + 0.0 * u[2]).collect();
    let m = morris(&design, &y, 3, 100, 5);
    for (i, expected) in [3.0, -4.0, 0.0].into_iter().enumerate() {
        assert!((m[i].mu - expected).abs() < 1e-12, "{i}: {:?}", m[i]);
        assert!((m[i].mu_star - f64::abs(expected)).abs() < 1e-12, "{i}: {:?}", m[i]);
        assert!(m[i].sigma < 1e-12, "{i}: {:?}", m[i]);
        assert_eq!((m[i].effects, m[i].dropped), (12, 0));
    }
}

#[test]
fn morris_sees_the_ishigami_interaction_that_mu_hides() {
    // x₂ (the third factor) acts only through b x₂⁴ sin x₀: its μ is near 0
    // (sin x₀ changes sign), while μ* and σ are large.
    let design = morris_design(3, 200, 4, 11).expect("a design");
    let y: Vec<f64> = design.iter().map(|x| ishigami(&unit_to(x, -PI, PI))).collect();
    let m = morris(&design, &y, 3, 100, 11);
    assert!(m[2].mu.abs() < 0.5 * m[2].mu_star, "{:?}", m[2]);
    assert!(m[2].sigma > m[2].mu_star, "{:?}", m[2]);
    // x₁ acts through a sin² x₁ alone: on the 4-level grid (−π, −π/3, π/3,
    // π) every step of Δ = 2/3 moves sin² x₁ by ±3/4, so every effect is
    // ±(7 · 3/4)/(2/3) = ±7.875, and μ* is that, exactly.
    assert!((m[1].mu_star - 7.875).abs() < 1e-9, "{:?}", m[1]);
}

#[test]
fn undefined_outputs_are_left_out_by_the_stated_rule() {
    let d = 3;
    let design = sobol_design(d, 256, false, 2).expect("a design");
    let mut y: Vec<f64> = design.iter().map(|x| ishigami(&unit_to(x, -PI, PI))).collect();
    let per = sobol_runs_per_sample(d, false);
    // Undefined outputs in base samples 0 and 5: both are dropped whole.
    y[1] = f64::NAN;
    y[5 * per + per - 1] = f64::NAN;
    let r = sobol(&y, d, false, 50, 2);
    assert_eq!((r.samples, r.dropped), (254, 2));
    assert!(r.indices.iter().all(|i| i.first.is_finite() && i.total.is_finite()));

    let design = morris_design(d, 10, 4, 2).expect("a design");
    let mut y: Vec<f64> = design.iter().map(|u| u[0] + u[1] + u[2]).collect();
    y[0] = f64::NAN; // the first point of the first trajectory: one effect dropped
    let m = morris(&design, &y, d, 50, 2);
    assert_eq!(m.iter().map(|m| m.dropped).sum::<usize>(), 1);
    assert_eq!(m.iter().map(|m| m.effects).sum::<usize>(), 29);
    assert!(m.iter().all(|m| (m.mu - 1.0).abs() < 1e-12));
}

#[test]
fn a_design_maps_onto_its_ranges_and_reads_back_its_factors() {
    let f = parse_factor("t_vis=log:1e-13:1e-10").expect("a factor");
    assert_eq!(f, Factor { key: "t_vis".into(), log: true, from: 1e-13, to: 1e-10 });
    assert_eq!((f.value(0.0), f.value(1.0)), (1e-13, 1e-10));
    assert!((f.value(0.5) / 10f64.powf(-11.5) - 1.0).abs() < 1e-12);
    for bad in ["t_vis", "t_vis=log:0:1", "t_vis=lin:2:1", "t_vis=cubic:1:2", "t_vis=lin:1:nan", "=lin:1:2"] {
        assert!(parse_factor(bad).is_err(), "{bad}");
    }
    let design = Design {
        method: Method::Sobol { samples: 64, second_order: false },
        factors: vec![f, parse_factor("surface_energy=lin:0.1:1").expect("a factor")],
        seed: 9,
    };
    let points = design.points().expect("points");
    assert_eq!(points.len(), design.runs());
    assert_eq!(design.runs(), 64 * 4);
    assert!(points.iter().all(|p| (1e-13..=1e-10).contains(&p[0]) && (0.1..=1.0).contains(&p[1])));
    // The same design, the same points; another seed, other points.
    assert_eq!(design.points().expect("points"), points);
    assert_ne!(Design { seed: 10, ..design.clone() }.points().expect("points"), points);
    assert!(Design { method: Method::Sobol { samples: 100, second_order: false }, ..design.clone() }.points().is_err());
    assert!(Design { method: Method::Morris { trajectories: 10, levels: 3 }, ..design }.points().is_err());
}

#[test]
fn the_same_samples_give_salib_s_indices() {
    // The outputs of these designs analysed by SALib 1.5 (`sobol.analyze` with
    // calc_second_order=True; `morris.analyze` with num_levels=4): its point
    // estimates, to rounding. (The intervals are bootstraps of other draws.)
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + b.abs());
    let design = sobol_design(3, 64, true, 1).expect("a design");
    let y: Vec<f64> = design.iter().map(|x| ishigami(&unit_to(x, -PI, PI))).collect();
    let r = sobol(&y, 3, true, 10, 1);
    let s1 = [0.2685750029954696, 0.40144476130634416, -0.012803292151551791];
    let st = [0.48599901487409225, 0.46777470078768196, 0.29083645917221307];
    for i in 0..3 {
        assert!(close(r.indices[i].first, s1[i]), "S1[{i}] = {}", r.indices[i].first);
        assert!(close(r.indices[i].total, st[i]), "ST[{i}] = {}", r.indices[i].total);
    }
    let (s2, _) = r.second.expect("S2");
    for (j, k, v) in [(0, 1, 0.14883287173440513), (0, 2, 0.30182026499390324), (1, 2, 0.03230649470222313)] {
        assert!(close(s2[j][k], v), "S2[{j}][{k}] = {}", s2[j][k]);
    }
    let design = morris_design(3, 10, 4, 3).expect("a design");
    let y: Vec<f64> = design.iter().map(|x| ishigami(&unit_to(x, -PI, PI))).collect();
    let m = morris(&design, &y, 3, 10, 1);
    let (mu_star, sigma) = (
        [7.7040541115931065, 7.874999999999998, 4.999036882666495],
        [6.586809440172515, 8.300978857941995, 8.33172813777749],
    );
    for i in 0..3 {
        assert!(close(m[i].mu_star, mu_star[i]) && close(m[i].sigma, sigma[i]), "{i}: {:?}", m[i]);
    }
    assert!(close(m[0].mu, 7.7040541115931065) && m[1].mu.abs() < 1e-12 && m[2].mu.abs() < 1e-12, "{m:?}");
}
