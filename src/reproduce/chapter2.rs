//! Chapter 2: adhesive viscoelastic collisions, restitution, sticking and
//! the fits to experiments.

use super::Check;
use crate::physics::PhysicsError;
use crate::physics::collision::{Options, Outcome, Setup, collide, sticking_velocity};
use crate::physics::contact::e_independent;

/// The checks of chapter 2 (reference ice set of the thesis).
pub fn chapter2() -> Result<Vec<Check>, PhysicsError> {
    let s = Setup::reference_ice();
    let opts = Options::default();
    let p = s.pair;
    let c8 = collide(&s, 8.0, &opts)?;
    let c2 = collide(&s, 2.0, &opts)?;
    let mut quasi = s;
    quasi.t_vis = 1e-14;
    let c4q = collide(&quasi, 4.0, &opts)?;
    let e_jkr8 = p.e_jkr(8.0);
    let e_d8 = p.e_viscous(s.dissipation_time(), 8.0);
    // Fig. 2.4: the fast end of e(v) against (2.26).
    let c100 = collide(&s, 100.0, &opts)?;
    // Fig. 2.5 left: spheres of radius 200 µm (R = 100 µm) at 8 m/s.
    let mut big = s;
    big.pair.radius = 1e-4;
    big.pair.mass = crate::physics::sphere_mass(1000.0, 2e-4) / 2.0;
    let cb = collide(&big, 8.0, &opts)?;
    let e_i_big = e_independent(big.pair.e_jkr(8.0), big.pair.e_viscous(big.dissipation_time(), 8.0));
    // Fig. 2.5 right: the quasi-static sticking velocity.
    let vs_quasi = sticking_velocity(&quasi, &opts, 1e-3)?;
    // Fig. 2.10: the 2 m/s collision followed into the JKR equilibrium.
    let c2f = collide(&s, 2.0, &Options { follow_after_stick: 40.0, ..opts })?;
    let (crack, bulk) = (c2f.last.crack_dissipated, c2f.last.bulk_dissipated);
    let table = ExperimentTable::new();
    let check = Check::new;
    Ok(vec![
        check("Fig. 2.2 (Eq. 2.22)", "Hertz time t_H at 8 m/s [s]", 1.4e-8, c8.hertz_time, 0.05 * 1.4e-8, ""),
        check("Fig. 2.2", "contact time t_c at 8 m/s [s]", 1.7e-8, c8.contact_time, 0.05 * 1.7e-8, ""),
        check(
            "Fig. 2.2 (Sect. 2.3)",
            "Tabor parameter of the reference ice set (2.11)",
            14.0,
            p.tabor(s.z0),
            0.5,
            "(2.11) with the reduced radius 1 um gives 11.3; the printed 14 is (2.11) with the sphere radius 2 um",
        )
        .thesis(),
        check("Fig. 2.4 (Sect. 2.3.3)", "e_A at 8 m/s", 0.66, c8.e_adhesive, 0.02, ""),
        check(
            "Fig. 2.4 (Eq. 2.26)",
            "(e_D - e_A) at 100 m/s / (e_D - e_A) at 8 m/s (below 1/2)",
            0.0,
            (p.e_viscous(s.dissipation_time(), 100.0) - c100.e_adhesive) / (e_d8 - c8.e_adhesive),
            0.5,
            "\"Towards the higher velocities, the results appear to approach the limit described by Eq. 2.26\": the gap to e_D at least halves from 8 to 100 m/s, the top of Fig. 2.4",
        ),
        check(
            "Fig. 2.5",
            "e_I (2.27) - e_A at R = 100 um, 8 m/s",
            0.0,
            e_i_big - cb.e_adhesive,
            0.02,
            "\"the difference ... vanishes for larger spheres\"",
        ),
        check(
            "Fig. 2.5 (Eq. 2.25)",
            "v_s(T_vis = 1e-14 s) / v_c (2.25), R = 1 um",
            1.0,
            vs_quasi / p.jkr_sticking_velocity(),
            0.05,
            "\"For very small values of T_vis ... Eq. 2.25 is retrieved\"",
        ),
        check(
            "Fig. 2.4 (Eq. 2.26)",
            "1 - e_D at 8 m/s: printed (2.26) / the model's own limit gamma -> 0",
            1.0,
            (1.0 - p.e_viscous_printed(s.dissipation_time(), 8.0)) / (1.0 - e_d8),
            0.05,
            "the model's bulk force (2.19) is Brilliantov et al.'s, whose limit is 1 - 5.571 A/t_H + ... (Schwager & Poeschel 1998); the printed coefficient 1.92 is 2.90 times smaller; e_D is drawn from the model",
        )
        .thesis(),
        check(
            "Fig. 2.4 (Eq. 2.27)",
            "e_I at 8 m/s from (2.27)",
            0.92,
            e_independent(e_jkr8, e_d8),
            0.02,
            "with the model's own e_D; the printed (2.26) would give 0.96",
        ),
        check("Fig. 2.9 (App. 2.C)", "fraction dissipated at the crack", 0.37, c8.crack_fraction(), 0.02, ""),
        check("Fig. 2.9 (App. 2.C)", "fraction dissipated in the bulk", 0.19, c8.bulk_fraction(), 0.02, ""),
        check("Fig. 2.3", "2 m/s sticks (1 = yes)", 1.0, f64::from(u8::from(c2.outcome == Outcome::Stick)), 0.0, ""),
        check(
            "Fig. 2.10 (App. 2.C)",
            "crack share of the dissipated energy, 2 m/s followed to equilibrium",
            0.75,
            crack / (crack + bulk),
            0.25,
            "\"dissipated (mainly at the crack tip)\"; accepts any share above 1/2",
        ),
        check(
            "Fig. 2.10 (App. 2.C)",
            "dissipated / (U_K(0) + released surface energy), 2 m/s",
            0.75,
            (crack + bulk) / (c2f.initial_kinetic - c2f.last.surface),
            0.25,
            "\"Most of the initial kinetic energy and the released surface energy are dissipated\"",
        ),
        check("Fig. 2.5 (Eq. 2.25)", "JKR sticking velocity v_c [m/s]", 1.46, p.jkr_sticking_velocity(), 0.02, ""),
        check("Fig. 2.4 (Eq. 2.24)", "e_JKR at 4 m/s", 0.93, p.e_jkr(4.0), 0.02, ""),
        check("App. 2.A", "e at 4 m/s, T_vis = 1e-14 s", 0.93, c4q.e_adhesive, 0.02, "quasi-static hard case"),
        check(
            "Fig. 2.6 (Sect. 2.5)",
            "log10 v_y [m/s] of the Wall et al. mica fit, centred on its measured 5-120 m/s",
            table.mica_range.0.log10(),
            table.mica_range.1.log10(),
            table.mica_range.2,
            "\"only the rightmost experiment covers the plastic deformation regime\": v_y lies inside its velocities",
        ),
        check(
            "Fig. 2.7 (Sect. 2.5)",
            "share of the 17 fitted gamma within a factor 2 of gamma_L",
            0.75,
            table.gamma_within_two,
            0.25,
            "\"The majority of the derived surface energies lies within a factor of two\"; accepts any share above 1/2",
        ),
        check(
            "Fig. 2.7 (Sect. 2.5)",
            "median log10 gamma/gamma_L",
            0.0,
            table.gamma_median,
            std::f64::consts::LOG10_2,
            "\"no systematic deviation from literature values\"; tolerance the factor two of Conclusion 5",
        ),
        check(
            "Fig. 2.8 (Sect. 2.5)",
            "largest / smallest Y/E_softer (fits and lower limits)",
            20.0,
            table.yield_spread,
            6.0,
            "\"vary by about a factor of 20\"; 30 % for \"about\"",
        ),
        check(
            "Fig. 2.8 (Sect. 2.5)",
            "share of the fitted T_vis below the t_H line of panel (b)",
            1.0,
            table.t_vis_below_hertz,
            0.0,
            "\"lie well below the collision time\"; t_H (2.22) with E* = 10 GPa, rho = 2 g/cm^3, v = 10 m/s",
        ),
        check(
            "Fig. 2.11 (Sect. 2.5)",
            "share of the experiments with Tabor mu(gamma_L) > 5",
            0.75,
            table.tabor_above_five,
            0.25,
            "\"the majority of the experiments have mu >> 5\"; accepts any share above 1/2",
        ),
        check(
            "Fig. 2.11 (Sect. 2.5)",
            "experiments with Tabor mu(gamma_L) < 5",
            2.0,
            table.tabor_below_five,
            0.0,
            "\"two experiments are perhaps limiting cases\"; with gamma_L and z0 = 0.3 nm four are (Dahneke PSL 1.7, PVT 2.0, Kim & Dunn 3.5 with quartz for its glass, Wall tedlar 4.6); the thesis gives z0 = 0.2-0.4 nm without saying which, and at 0.2 nm two are (next row)",
        )
        .thesis(),
        check(
            "Fig. 2.11 (Sect. 2.5)",
            "experiments with Tabor mu(gamma_L) < 5, z0 = 0.2 nm (the low end of 2.11's range)",
            2.0,
            table.tabor_below_five_low_z0,
            0.0,
            "\"two experiments are perhaps limiting cases\": Dahneke PSL 2.6 and PVT 3.0; Kim & Dunn 5.3 and Wall tedlar 6.9 are then above 5",
        ),
    ])
}

/// What the thesis says of Tables 2.1-2.3 as a whole (Figs. 2.6-2.8, 2.11).
struct ExperimentTable {
    /// log10 of the centre of the Wall et al. mica velocities, log10 of the
    /// fit's yield velocity, and half the log width of the velocities.
    mica_range: (f64, f64, f64),
    /// Share of fitted γ within a factor 2 of γ_L.
    gamma_within_two: f64,
    /// Median log10 γ/γ_L.
    gamma_median: f64,
    /// Largest over smallest Y/E of the softer material.
    yield_spread: f64,
    /// Share of the fitted T_vis below the Hertz time of Fig. 2.8b's line.
    t_vis_below_hertz: f64,
    /// Share of experiments with μ(γ_L) > 5.
    tabor_above_five: f64,
    /// Number of experiments with μ(γ_L) < 5.
    tabor_below_five: f64,
    /// The same count with z₀ = 0.2 nm.
    tabor_below_five_low_z0: f64,
}

impl ExperimentTable {
    fn new() -> ExperimentTable {
        use crate::physics::contact::Pair;
        use crate::physics::experiments::{Experiment, experiment, experiments};
        let all = experiments();
        let n = all.len() as f64;
        let ratio = |e: &Experiment| e.gamma.representative() / e.literature_surface_energy().unwrap_or(f64::NAN);
        let share = |keep: &dyn Fn(&Experiment) -> bool| all.iter().filter(|e| keep(e)).count() as f64 / n;
        let mut logs: Vec<f64> = all.iter().map(|e| ratio(e).log10()).collect();
        logs.sort_by(f64::total_cmp);
        let yield_ratios: Vec<f64> =
            all.iter().filter_map(|e| Some(e.yield_strength.representative() / e.softer_modulus()?)).collect();
        // The grey line of Fig. 2.8b: t_H of equal spheres, E* = 10 GPa, ρ = 2 g/cm³, v = 10 m/s.
        let hertz = |r: f64| {
            Pair {
                modulus: 1e10,
                radius: r,
                mass: crate::physics::sphere_mass(2000.0, 2.0 * r) / 2.0,
                surface_energy: 0.0,
            }
            .hertz_time(10.0)
        };
        let tabor_at = |e: &Experiment, z0: Option<f64>| {
            e.best_fit_setup().map_or(f64::NAN, |st| {
                Pair { surface_energy: e.literature_surface_energy().unwrap_or(f64::NAN), ..st.pair }
                    .tabor(z0.unwrap_or(st.z0))
            })
        };
        let tabor = |e: &Experiment| tabor_at(e, None);
        let mica = experiment("wall-mica").map_or((f64::NAN, f64::NAN, f64::NAN), |e| {
            let v_y = e.best_fit_setup().map_or(f64::NAN, |st| st.yield_velocity());
            ((e.v_min * e.v_max).sqrt(), v_y, 0.5 * (e.v_max / e.v_min).log10())
        });
        ExperimentTable {
            mica_range: mica,
            gamma_within_two: share(&|e| (0.5..=2.0).contains(&ratio(e))),
            gamma_median: logs.get(logs.len() / 2).copied().unwrap_or(f64::NAN),
            yield_spread: yield_ratios.iter().copied().fold(0.0, f64::max)
                / yield_ratios.iter().copied().fold(f64::INFINITY, f64::min),
            t_vis_below_hertz: share(&|e| e.t_vis.representative() < hertz(e.reduced_radius())),
            tabor_above_five: share(&|e| tabor(e) > 5.0),
            tabor_below_five: all.iter().filter(|e| tabor(e) < 5.0).count() as f64,
            tabor_below_five_low_z0: all.iter().filter(|e| tabor_at(e, Some(0.2e-9)) < 5.0).count() as f64,
        }
    }
}
