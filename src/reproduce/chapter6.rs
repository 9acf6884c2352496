//! Chapter 6: the smallest debris fragments.

use super::Check;
use crate::physics::PhysicsError;

/// The checks of chapter 6 (smallest fragments).
pub fn chapter6() -> Result<Vec<Check>, PhysicsError> {
    use crate::physics::debris::{AU, TABLE_6_1, ratio_to_blowout, smallest_fragment_64, split_size, splitting_limit};
    use crate::scene::debris::unequal_colliders::{normalised_catastrophic, normalised_erosion};
    let check = Check::new;
    let sil = TABLE_6_1[0];
    let (eta, v) = (1e-2, 20.0);
    // (6.4) at s_min = s_max = 2^{-1/3} s₀: solve 2^{-1/3}(ηρs₀v² + 24γ) = 24γ for s₀.
    let s0 = 24.0 * sil.surface_energy * (2f64.cbrt() - 1.0) / (eta * sil.density * v * v);
    let s_limit = 2f64.powf(-1.0 / 3.0) * s0;
    let coefficient = s_limit * eta * sil.density * v * v / sil.surface_energy;
    let consistent = smallest_fragment_64(&sil, eta, v, s0, s_limit) / s_limit;
    let p = crate::scene::debris::common::FragmentParams::default();
    let collider = crate::scene::debris::smallest_fragment::collider_for(&p, 0, 1e-6).unwrap_or(f64::NAN);
    // Fig. 6.2: the slopes of (6.8) in f (the arrow) and in a (the diagonal lines).
    let at = |f: f64, a_au: f64| ratio_to_blowout(0.1, 1e-2, f, a_au * AU, 1.0);
    let slope_f = (at(1e-1, 5.0) / at(1e-2, 5.0)).log10();
    let slope_a = (at(1e-2, 50.0) / at(1e-2, 5.0)).log10();
    // Fig. 6.3: the mass ratio of the smallest catastrophic fragment.
    let best = crate::scene::logspace(1e-3, 1e2, 2001)
        .into_iter()
        .map(|q| (q, normalised_catastrophic(q.cbrt())))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map_or(f64::NAN, |(q, _)| q);
    Ok(vec![
        check("Fig. 6.2 (Eq. 6.8)", "d log(s_min/s_blow) / d log f (the f arrow)", -2.0, slope_f, 1e-9, "(6.8): (f/1e-2)^-2"),
        check("Fig. 6.2 (Eq. 6.8)", "d log(s_min/s_blow) / d log a (the diagonal lines)", 1.0, slope_a, 1e-9, "(6.8): (a/5 AU)"),
        check(
            "Fig. 6.3",
            "log10 mass ratio of the smallest catastrophic s_min",
            0.0,
            best.log10(),
            0.5,
            "\"collisions with a mass ratio close to unity are the most effective at creating small fragments\"",
        ),
        check(
            "Fig. 6.3 (App. 6.B)",
            "s_min(erosive, kappa = 1) / s_min(equal masses)",
            1.0,
            normalised_erosion(1.0),
            0.0,
            "(6.11)/(6.10) = (kappa/4)^2: erosion with kappa ~ 1 makes 16x smaller fragments; \"mass ratio close to unity\" holds among catastrophic collisions only",
        )
        .thesis(),
        check("Fig. 6.1 (Eq. 6.6)", "coefficient of gamma/(eta rho v^2) from (6.4) at s_min = s_max", 5.0, coefficient, 0.1, ""),
        check("Fig. 6.1 (Eq. 6.4)", "(6.4) at that s0 returns s_min = s_max (ratio)", 1.0, consistent, 1e-9, ""),
        check(
            "Eqs. 6.5/6.6",
            "s_split / s_min(6.6)",
            0.6,
            split_size(&sil, eta, v) / splitting_limit(&sil, eta, v),
            1e-12,
            "(6.5) is 3/5 of (6.6)",
        ),
        check(
            "Fig. 6.1",
            "collider radius for 1 um silicate fragments at 20 m/s [m] (\"a few cm\")",
            0.03,
            collider,
            0.025,
            "",
        ),
        check(
            "Fig. 6.2 (Eq. 6.8)",
            "s_min/s_blow prefactor (5 AU, f = eta = 1e-2, gamma = 0.1, L = M = 1)",
            2.4,
            ratio_to_blowout(0.1, 1e-2, 1e-2, 5.0 * AU, 1.0),
            0.1,
            "recomputed from (6.6) and the beta = 1/2 blow-out size; the printed 2.4 matches beta = 1",
        )
        .thesis(),
    ])
}
