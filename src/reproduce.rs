//! The published numbers the project reproduces, each with the thesis value,
//! our value and the tolerance, and the figures behind them.

use crate::physics::PhysicsError;
use crate::physics::collision::{Options, Outcome, Setup, collide, sticking_velocity};
use crate::physics::contact::e_independent;
use serde::Serialize;

/// One comparison with the thesis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Check {
    /// Figure, equation or section of the thesis.
    pub figure: &'static str,
    /// What is compared.
    pub quantity: &'static str,
    /// The printed value.
    pub thesis: f64,
    /// The value computed here.
    pub ours: f64,
    /// Allowed absolute deviation.
    pub tolerance: f64,
    /// Remark (e.g. a slip in the printed text).
    pub note: &'static str,
    /// What a value outside the tolerance means.
    pub expect: Expect,
}

/// What a comparison outside its tolerance means.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Expect {
    /// The value must agree: a difference fails the table.
    Agree,
    /// A difference that comes from the thesis itself (a slip of the printed
    /// text, a printed prefactor its own equations do not give, a measurement
    /// outside its own error bar); the note says which.
    Thesis,
    /// A difference not yet explained, under investigation; the note says
    /// what is known.
    Open,
}

impl Check {
    /// A comparison that must hold (not a known difference).
    pub fn new(
        figure: &'static str,
        quantity: &'static str,
        thesis: f64,
        ours: f64,
        tolerance: f64,
        note: &'static str,
    ) -> Check {
        Check { figure, quantity, thesis, ours, tolerance, note, expect: Expect::Agree }
    }

    /// The same comparison, expected to differ for a reason inside the thesis.
    pub fn thesis(self) -> Check {
        Check { expect: Expect::Thesis, ..self }
    }

    /// The same comparison, with a difference still open.
    pub fn open(self) -> Check {
        Check { expect: Expect::Open, ..self }
    }

    /// "pass", "thesis" (differs for a reason in the thesis), "open" (differs,
    /// unexplained) or "FAIL".
    pub fn status(&self) -> &'static str {
        match (self.pass(), self.expect) {
            (true, _) => "pass",
            (false, Expect::Thesis) => "thesis",
            (false, Expect::Open) => "open",
            (false, Expect::Agree) => "FAIL",
        }
    }

    /// Whether the row fails the table: outside the tolerance and expected to agree.
    pub fn fails(&self) -> bool {
        !self.pass() && self.expect == Expect::Agree
    }

    /// Whether our value lies within the tolerance.
    pub fn pass(&self) -> bool {
        (self.ours - self.thesis).abs() <= self.tolerance
    }
}

/// The checks of chapter 5 (global dust batches; 1000 batches per disk, where
/// the converted fractions agree with 2000 batches at 4× finer steps within
/// 0.01; see the batches benchmark).
pub fn chapter5() -> Result<Vec<Check>, crate::scene::SceneError> {
    use crate::physics::batches::{BatchRun, MIN_HALF_WIDTH, alpha_midplane, max_loading, surface_density};
    use crate::physics::constants::{AU, YEAR};
    use crate::physics::disk::{GasDisk, Profile};
    use crate::scene::Progress;
    use crate::scene::batches::common::BatchParams;
    use rayon::prelude::*;
    let check = Check::new;
    let progress = Progress::default();
    let base = BatchParams { batches: 1000, ..BatchParams::default() };
    let with = |mass: f64, z: f64, r_c: f64, cold: bool| {
        let mut b = base.clone();
        b.disk.disk_mass = mass;
        b.disk.metallicity = z;
        b.disk.r_c = r_c;
        b.disk.cold = cold;
        b
    };
    let mut compact = with(0.01, 0.01, 30.0, false);
    compact.growth = "compact".into();
    compact.disk.icy = false;
    compact.v_frag = 5.0;
    let mut eroding = with(0.01, 0.02, 30.0, false);
    eroding.v_eros = 20.0;
    let mut runs = vec![compact, with(0.01, 0.02, 30.0, false), eroding, with(0.2, 0.05, 30.0, false)];
    runs.push(with(0.01, 0.02, 100.0, false));
    runs.push(with(0.01, 0.02, 100.0, true));
    // The Fig. 5.8 (top) grid.
    for m in [0.01, 0.045, 0.2] {
        for z in [0.01, 0.02, 0.05] {
            runs.push(with(m, z, 30.0, false));
        }
    }
    // Fig. 5.12: compact silicates at v_frag = 1 m/s (done[15]); Fig. 5.14:
    // α = 10⁻⁵, Z0 = 0.05, erosion at 20 m/s (done[16]).
    let mut compact_slow = with(0.01, 0.01, 30.0, false);
    compact_slow.growth = "compact".into();
    compact_slow.disk.icy = false;
    compact_slow.v_frag = 1.0;
    let mut weak = with(0.01, 0.05, 30.0, false);
    weak.disk.alpha = 1e-5;
    weak.v_eros = 20.0;
    runs.push(compact_slow);
    runs.push(weak);
    let done: Vec<_> = runs.par_iter().map(|b| b.run(&progress)).collect::<Result<_, _>>()?;
    let dust_left = done[0].frames.last().map_or(f64::NAN, |f| (f.budget[0] + f.budget[1]) / done[0].total_mass);
    let grid = &done[6..15];
    let least = grid.iter().map(|r| r.converted_fraction()).fold(f64::INFINITY, f64::min);
    let eta = base.disk.disk().eta(AU);
    // Fig. 5.1: the initial Σ_d against Z0 Σ_g between 5 and 150 AU.
    let points: Vec<(f64, f64)> = done[0].initial_radii.iter().copied().zip(done[0].masses.iter().copied()).collect();
    let sigma = surface_density(&points, 2, MIN_HALF_WIDTH);
    let disk0 = runs[0].disk.disk();
    let worst_sigma = points
        .iter()
        .zip(&sigma)
        .filter(|((r, _), _)| (5.0 * AU..=150.0 * AU).contains(r))
        .map(|((r, _), s)| (s / disk0.dust_surface_density(*r) - 1.0).abs())
        .fold(0.0, f64::max);
    // Fig. 5.4: when batches reach Ωt_s = 10⁻³.
    let nearest = |run: &BatchRun, r0: f64| {
        (0..run.initial_radii.len())
            .min_by(|&a, &b| (run.initial_radii[a] / r0).ln().abs().total_cmp(&(run.initial_radii[b] / r0).ln().abs()))
            .unwrap_or(0)
    };
    let reach = |run: &BatchRun, b: usize, st: f64| {
        run.frames
            .iter()
            .find(|f| f.batches.get(b).is_some_and(|q| q.stokes >= st))
            .map_or(f64::NAN, |f| (f.t / YEAR).log10())
    };
    let dust = |run: &BatchRun| {
        run.frames.iter().flat_map(|f| f.batches.iter().filter(|q| q.dust)).copied().collect::<Vec<_>>()
    };
    // Fig. 5.7: planetesimal masses on the grid.
    let planetesimals = |run: &BatchRun| run.frames.last().map_or(f64::NAN, |f| f.budget[1]);
    let by_1e5 =
        done[1].frames.iter().rfind(|f| f.t <= 1e5 * YEAR).map_or(f64::NAN, |f| f.budget[1]) / planetesimals(&done[1]);
    // Fig. 5.14: the streaming-instability region of the weakly turbulent disk.
    let si_first = done[16]
        .frames
        .iter()
        .find(|f| f.batches.iter().any(|q| q.dust && q.si))
        .map_or(f64::NAN, |f| (f.t / YEAR).log10());
    let si_edge = done[16].frames.iter().rfind(|f| f.t <= 1e5 * YEAR).map_or(f64::NAN, |f| {
        f.batches.iter().filter(|q| q.dust && q.si).map(|q| q.r / AU).fold(0.0, f64::max).log10()
    });
    // Fig. 5.15: the three disks of the midplane-loading scene.
    let panel = |r_c: f64, slope: f64, cold: bool| GasDisk {
        profile: Profile::TruncatedPowerLaw { mass: 0.01, r_c, slope },
        cold,
        alpha: 1e-3,
        metallicity: 0.01,
    };
    let edge = |g: &GasDisk, z: f64| {
        crate::scene::logspace(1.0, 200.0, 2001)
            .into_iter()
            .filter(|&r| max_loading(g.eta(r * AU), z) >= 1.0)
            .fold(0.0, f64::max)
            .log10()
    };
    let (mmsn_like, extended, cold) = (panel(30.0, 1.5, false), panel(100.0, 1.0, false), panel(100.0, 1.0, true));
    let c_s = base.disk.disk().sound_speed(5.0 * AU);
    Ok(vec![
        check(
            "Fig. 5.1",
            "largest |Sigma_d/(Z0 Sigma_g) - 1| at t = 0, 5-150 AU",
            0.0,
            worst_sigma,
            0.05,
            "\"The initial metallicity equals Z0 = 0.01 throughout the entire disk\"",
        ),
        check(
            "Fig. 5.4",
            "log10 t [yr] when the innermost (3 AU) compact batch reaches Omega t_s = 1e-3",
            3.0,
            reach(&done[0], 0, 1e-3),
            0.5,
            "\"particles reach Omega t_s = 1e-3 already after 1e3 yr\"",
        ),
        check(
            "Fig. 5.4",
            "log10 t [yr] when the compact batch from ~100 AU reaches Omega t_s = 1e-3",
            6.0,
            reach(&done[0], nearest(&done[0], 100.0 * AU), 1e-3),
            0.5,
            "\"growth towards similar Stokes numbers takes almost 1e6 yr\"",
        ),
        check(
            "Fig. 5.7",
            "log10 planetesimal mass, (0.2 M_sun, Z0 = 0.05) / (0.01 M_sun, Z0 = 0.01)",
            2.0,
            (planetesimals(&done[14]) / planetesimals(&done[6])).log10(),
            0.5,
            "\"between 10 and ~1e3 M_earth of planetesimals can form\"",
        ),
        check(
            "Fig. 5.7",
            "share of the planetesimal mass formed by 1e5 yr (0.01 M_sun, Z0 = 0.02)",
            0.75,
            by_1e5,
            0.25,
            "\"Most planetesimals form in the first 1e5 yrs\"; accepts any share above 1/2",
        ),
        check(
            "Fig. 5.12",
            "log10 largest Omega t_s of the dust, compact, v_frag = 1 m/s",
            -2.5,
            dust(&done[15]).iter().map(|q| q.stokes).fold(0.0, f64::max).log10(),
            0.5,
            "\"do not reach Omega t_s > 1e-2\" while \"a large region\" has Omega t_s > 1e-3; ours stays below 1e-2 inside 50 AU but reaches 0.017 at 68 AU (batches from ~94 AU, 5e5 yr)",
        )
        .open(),
        check(
            "Fig. 5.12 (Eq. 5.14)",
            "log10 (Omega t_s)_max = (v_frag/c_s)^2/alpha at 5 AU, v_frag = 1 m/s",
            -3.0,
            ((1.0 / c_s).powi(2) / 1e-3).log10(),
            0.5,
            "\"(Omega t_s)_max ~ 1e-3 for v_frag = 1 m/s and alpha = 1e-3\"",
        ),
        check(
            "Fig. 5.13",
            "log10 largest midplane rho*_d/rho_g, erosion at 20 m/s, alpha = 1e-3",
            -1.0,
            dust(&done[2]).iter().map(|q| q.loading).fold(0.0, f64::max).log10(),
            0.5,
            "\"at most results in a midplane dust-to-gas ratio of ~0.1\"",
        ),
        check(
            "Fig. 5.14",
            "log10 t [yr] when SI conditions are first met, alpha = 1e-5, Z0 = 0.05",
            3.5,
            si_first,
            0.5,
            "\"first met ... after a few 1e3 yr\"",
        ),
        check(
            "Fig. 5.14",
            "log10 outermost radius [AU] meeting SI conditions at 1e5 yr",
            19.2f64.log10(),
            si_edge,
            0.15,
            "\"reaching the current location of Uranus after 1e5 yr\" (19.2 AU); ours meets SI first at 2-3 AU after ~4e3 yr and moves out as printed to ~6 AU at 1e4 yr, but from 1.6e4 yr scattered batches (2-21 of 1000) meet it out to 100-190 AU",
        )
        .open(),
        check(
            "Fig. 5.15",
            "log10 outer edge [AU] of rho*_d/rho_g >= 1, MMSN-like, Z* = 0.03",
            1.0,
            edge(&mmsn_like, 0.03),
            0.15,
            "\"Z* = 0.03 in the inner ~10 AU\"",
        ),
        check(
            "Fig. 5.15",
            "log10 outer edge [AU], MMSN-like, Z* = 0.05",
            80f64.log10(),
            edge(&mmsn_like, 0.05),
            0.15,
            "\"Z* = 0.05 in the region out to 80 AU\"",
        ),
        check(
            "Fig. 5.15",
            "log10 outer edge [AU], extended, Z* = 0.03",
            20f64.log10(),
            edge(&extended, 0.03),
            0.15,
            "\"in the inner ~20 and 90 AU\" (printed with <= 1 for >= 1)",
        ),
        check("Fig. 5.15", "log10 outer edge [AU], extended, Z* = 0.05", 90f64.log10(), edge(&extended, 0.05), 0.15, ""),
        check(
            "Fig. 5.15",
            "log10 outer edge [AU], extended cold, Z* = 0.02",
            1.0,
            edge(&cold, 0.02),
            0.15,
            "\"Z* = 0.02 could be enough ... in the inner 10 AU\"",
        ),
        check(
            "Fig. 5.15",
            "log10 outer edge [AU], extended cold, Z* = 0.03",
            50f64.log10(),
            edge(&cold, 0.03),
            0.15,
            "\"Z* = 0.03 suffices out to 50 AU\"",
        ),
        check(
            "Fig. 5.3",
            "dust left after 1e6 yr, compact silicates, v_frag = 5 m/s (fraction)",
            0.0,
            dust_left,
            0.01,
            "",
        ),
        check(
            "Fig. 5.6",
            "outermost planetesimal formation, porous, 0.01 M_sun, Z0 = 0.02 [AU]",
            5.0,
            done[1].outermost_planetesimals() / AU,
            1.0,
            "\"~5 AU\"",
        ),
        check(
            "Fig. 5.8",
            "converted fraction after 1e6 yr, 0.2 M_sun, Z0 = 0.05",
            0.9,
            done[14].converted_fraction(),
            0.1,
            "\"~90%\"",
        ),
        check(
            "Fig. 5.8",
            "smallest converted fraction after 1e6 yr on the top grid (0.01-0.2 M_sun, Z0 = 0.01-0.05)",
            0.8,
            least,
            0.1,
            "\"over 70 %\" for every disk of the top grid",
        ),
        check(
            "Fig. 5.9",
            "outer edge of the zone, 0.2 M_sun, Z0 = 0.05, R_c = 30 AU [AU]",
            20.0,
            done[3].outermost_planetesimals() / AU,
            4.0,
            "\"~20 AU\"",
        ),
        check(
            "Fig. 5.10",
            "zone edge, cold / warm disk (0.01 M_sun, Z0 = 0.02, R_c = 100 AU)",
            2.0,
            done[5].outermost_planetesimals() / done[4].outermost_planetesimals(),
            0.3,
            "\"nearly doubles\"",
        ),
        check(
            "Fig. 5.11",
            "outermost planetesimal formation with erosion at 20 m/s [AU]",
            0.0,
            done[2].outermost_planetesimals() / AU,
            0.0,
            "none",
        ),
        check(
            "Fig. 5.15 (Eq. 5.16)",
            "log10 alpha_mp at 1 AU, Omega t_s = 1e-2, Z = 0.01",
            -6.0,
            alpha_midplane(eta, 0.01, 1e-2).log10(),
            0.5,
            "\"~1e-6\"",
        ),
        check(
            "Fig. 5.15 (Eq. 5.16)",
            "log10 alpha_mp at 1 AU, Omega t_s = 1, Z = 0.01",
            -4.0,
            alpha_midplane(eta, 0.01, 1.0).log10(),
            0.5,
            "\"~1e-4\"",
        ),
    ])
}

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
            "Fig. 2.4 (Sect. 2.3.3)",
            "e_JKR² + e_D² − 1 at 8 m/s",
            0.92,
            e_jkr8 * e_jkr8 + e_d8 * e_d8 - 1.0,
            0.02,
            "the printed e_I = 0.92 equals the radicand of (2.27)",
        ),
        check(
            "Fig. 2.4 (Eq. 2.27)",
            "e_I at 8 m/s from (2.27)",
            0.92,
            e_independent(e_jkr8, e_d8),
            0.02,
            "slip: (2.27) gives 0.96; the printed 0.92 is its square",
        )
        .thesis(),
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
            "\"two experiments are perhaps limiting cases\"; with gamma_L and z0 = 0.3 nm four are: Dahneke PSL, PVT, Kim & Dunn (quartz stands in for its glass) and Wall tedlar",
        )
        .open(),
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
        let tabor = |e: &Experiment| {
            e.best_fit_setup().map_or(f64::NAN, |st| {
                Pair { surface_energy: e.literature_surface_energy().unwrap_or(f64::NAN), ..st.pair }.tabor(st.z0)
            })
        };
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
        }
    }
}

/// The checks of chapter 3 (rolling friction).
pub fn chapter3() -> Vec<Check> {
    use crate::physics::rolling::{
        HalfDiscs, critical_displacement, rolling_force, rolling_torque, small_asymmetry_torque,
    };
    use crate::scene::rolling::common::RollingParams;
    let check = Check::new;
    // Peri & Cetinkaya: 21.4 µm PSL on aluminium, γ = 0.1 J/m².
    let peri = RollingParams::of("PSL", "aluminium alloy", true, 10.7e-6, 0.1);
    let pair = peri.pair(10.7e-6);
    let a_eq = pair.jkr_equilibrium_radius();
    let f0 = crate::physics::rolling::rocking_frequency(&pair, peri.inertia(10.7e-6));
    let silica = RollingParams::of("silicate", "silicate", false, 0.95e-6, 0.05);
    let force = |d: f64| {
        let p = silica.pair(d / 2.0);
        rolling_force(&p, rolling_torque(&p, 0.5))
    };
    let ding = RollingParams::of("PSL", "silicon", true, 12e-6, 0.1);
    let ding_h = 0.5 * (73e-9 + 94e-9) / critical_displacement(&ding.pair(0.25 * (22.5e-6 + 26.8e-6)), 1.0);
    // Figs. 3.1-3.2: a 5 µm PSL sphere on PSL (the rolling-contact-psl preset) at ξ/a = 0.1.
    let psl = RollingParams::default();
    let pp = psl.pair(psl.radius);
    let a_eq_psl = pp.jkr_equilibrium_radius();
    let xi = 0.1 * a_eq_psl;
    let tilted = HalfDiscs::displaced(&pp, xi);
    let level = HalfDiscs::displaced(&pp, 0.0);
    // Fig. 3.3: PSL on glass (the Table 3.1 silicate), Δγ/γ = 3.
    let glass = RollingParams::of("PSL", "silicate", true, 5e-6, 0.05);
    let xi_3 = |r: f64| critical_displacement(&glass.pair(r), 3.0) / 3e-10;
    vec![
        check(
            "Fig. 3.1",
            "F_E (3.12) / F_c at xi = 0 (panel A)",
            0.0,
            level.elastic_force(&pp) / pp.pull_off_force(),
            1e-9,
            "(A): a1 = a2 = a_eq, no torque",
        ),
        check(
            "Fig. 3.1",
            "under a torque the trailing half > a_eq > leading half (1 = yes)",
            1.0,
            f64::from(u8::from(tilted.a2 > a_eq_psl && a_eq_psl > tilted.a1)),
            0.0,
            "(B): a1 > a_eq > a2 with 1 the trailing half; the code names the trailing (x < 0) half a2",
        ),
        check(
            "Fig. 3.2 (Eq. 3.14)",
            "M (3.10) / 6 pi gamma R xi at xi/a = 0.1, 5 um PSL on PSL",
            1.0,
            tilted.torque(&pp).abs() / small_asymmetry_torque(&pp, xi),
            0.02,
            "(3.14) holds for small asymmetry; its correction (3/2)(xi/a)^2 is 1.5 % here",
        ),
        check(
            "Fig. 3.2 (Eq. 3.11)",
            "M (3.10) / M (3.11) at xi/a = 0.1",
            1.0,
            tilted.torque(&pp) / tilted.torque_from_release_rates(&pp),
            1e-9,
            "the torque from the pressure map equals the torque from the release rates",
        ),
        check(
            "Fig. 3.3 (Sect. 3.3.1)",
            "log10 xi(dgamma/gamma = 3) / z0, 5 um PSL on glass",
            2.0,
            xi_3(5e-6).log10(),
            0.5,
            "\"approximately two orders of magnitude larger than z_0\"",
        ),
        check(
            "Fig. 3.3 (Sect. 3.3.1)",
            "log10 xi(dgamma/gamma = 3) / z0, 15 um PSL on glass",
            2.0,
            xi_3(15e-6).log10(),
            0.5,
            "",
        ),
        check(
            "Sect. 3.3.1",
            "a_eq, PSL on aluminium [m]",
            3.8e-7,
            a_eq,
            3e-8,
            "thesis used Peri & Cetinkaya's elastic constants; Table 2.2's give 354 nm",
        ),
        check("Eq. 3.20", "rocking frequency f0 [Hz]", 1.5e5, f0, 7.5e3, ""),
        check("Sect. 3.3.1", "torque at xi = 30 nm [N m]", 6e-13, small_asymmetry_torque(&pair, 30e-9), 3e-14, ""),
        check("Eq. 3.16", "dgamma/gamma for xi = 0.08 a_eq (lower limit)", 0.95, 0.08 * 12.0, 0.02, ""),
        check("Eq. 3.25", "Q from damping in ~10 periods", 30.0, std::f64::consts::PI * 10.0, 2.0, ""),
        check(
            "Fig. 3.5",
            "F_roll, d = 1.9 um, dgamma/gamma = 0.5 vs Heim et al. [N]",
            8.5e-10,
            force(1.9e-6),
            1.6e-10,
            "error bar 0.3 + 1.3 (stat. + syst.)",
        ),
        check(
            "Fig. 3.5",
            "F_roll, d = 1.9 um, dgamma/gamma = 0.5 vs Blum & Wurm [N]",
            5.0e-10,
            force(1.9e-6),
            2.5e-10,
            "",
        ),
        check(
            "Fig. 3.5",
            "F_roll, d = 1.5 um, dgamma/gamma = 0.5 vs Gundlach et al. [N]",
            12.1e-10,
            force(1.5e-6),
            3.6e-10,
            "outside the error bar; the thesis attributes the spread to differing procedures",
        )
        .thesis(),
        check("Fig. 3.4", "dgamma/gamma from Ding et al.'s xi_crit (gamma = 0.1)", 2.5, ding_h, 0.25, ""),
    ]
}

/// The checks of chapter 4 (disk, aggregates, semi-analytical growth).
pub fn chapter4() -> Vec<Check> {
    use crate::physics::aggregate::Monomer;
    use crate::physics::constants::{AU, YEAR};
    use crate::physics::disk::GasDisk;
    use crate::physics::growth::{GrowthModel, Porosity};
    let check = Check::new;
    let d = GasDisk::mmsn(1e-3, 1e-2);
    let r = 5.0 * AU;
    let mono = Monomer::ice();
    let mut model = GrowthModel::chapter4(Porosity::Collisional);
    model.drift = false;
    let coll = model.run(r, 1e8 * YEAR);
    model.porosity = Porosity::Full;
    let full = model.run(r, 1e8 * YEAR);
    let log = |x: Option<[f64; 2]>, i: usize| x.map_or(f64::NAN, |v| v[i].log10());
    let preset = |name: &str| {
        crate::preset::resolve(name)
            .ok()
            .and_then(|p| crate::scene::compute(&p.scene, &crate::scene::Progress::default()).ok())
    };
    let scalar = |out: &Option<crate::scene::SceneOutput>, key: &str| {
        out.as_ref().and_then(|o| o.scalar(key)).unwrap_or(f64::NAN)
    };
    // Fig. 4.13: where the porous tracks from 3-300 AU reach 10¹⁶ g.
    let formation = scalar(&preset("disk-fig-4-13"), "outermost_planetesimal_formation");
    // Fig. 4.1: the three families at 5 AU.
    let drag = preset("disk-fig-4-1");
    let series = |name: &str| {
        drag.as_ref()
            .and_then(|o| o.figures.first())
            .and_then(|f| f.series.iter().find(|s| s.name.starts_with(name)))
            .map(|s| s.points.clone())
            .unwrap_or_default()
    };
    let fractal = series("fractal");
    let onset = scalar(&drag, "fractal_stokes_onset");
    let stokes_switch = fractal.iter().find(|q| q[0] >= onset).map_or(f64::NAN, |q| q[1]);
    let m0 = mono.mass();
    let compact_alpha = series("compact").iter().find(|q| q[1] >= 1e-3).map_or(f64::NAN, |q| (q[0] * m0 * 1e3).log10());
    let env = d.local(r);
    let compact_one = scalar(&drag, "compact_st1");
    let epstein_at_one = crate::physics::aggregate::stopping_time(
        &env,
        &mono,
        &crate::physics::aggregate::Aggregate { mass: compact_one * m0, filling: 1.0 },
        true,
    )
    .regime
        == crate::physics::aggregate::DragRegime::Epstein;
    // Fig. 4.2: the two speed maps.
    let compact_map = preset("disk-fig-4-2-compact");
    let porous_map = preset("disk-fig-4-2-porous");
    vec![
        check(
            "Fig. 4.1",
            "log10 Omega t_s where D_f = 2.5 aggregates enter Stokes drag",
            -3.0,
            stokes_switch.log10(),
            0.5,
            "\"switch to the Stokes regime around Omega t_s = 1e-3\"",
        ),
        check(
            "Fig. 4.1",
            "log10 m/m0 where Re_p exceeds 1, D_f = 2.5",
            21.0,
            scalar(&drag, "fractal_re_one").log10(),
            0.5,
            "\"at a mass of m/m0 ~ 1e21\"; with the projected area pi a^2 used here Re_p reaches 1 at 10^21.75 (Okuzumi et al.'s smaller area for fractals would move it down)",
        )
        .open(),
        check(
            "Fig. 4.1",
            "1e26 / (m/m0 where C_D = 0.44), D_f = 2.5 (below 1)",
            0.0,
            1e26 / scalar(&drag, "fractal_newton"),
            1.0,
            "\"m/m0 > 1e26 are in the regime where C_D = 0.44\"",
        ),
        check(
            "Fig. 4.1 (Sect. 4.4.1)",
            "log10 m [g] of compact grains at Omega t_s = alpha",
            -3.0,
            compact_alpha,
            0.5,
            "\"m ~ 1e-3 g for compact particles (see Figure 4.1)\"",
        ),
        check(
            "Fig. 4.1",
            "compact grains reach Omega t_s = 1 in Epstein drag (1 = yes)",
            1.0,
            f64::from(u8::from(epstein_at_one)),
            0.0,
            "\"Compact particles ... reach Omega t_s = 1 while still in the Epstein drag regime\"",
        ),
        check(
            "Fig. 4.2",
            "share of the compact map where settling dominates",
            0.0,
            scalar(&compact_map, "share_settling"),
            0.0,
            "\"no combination of particle masses whose relative velocity is dominated by differential settling\"",
        ),
        check("Fig. 4.2", "share of the porous (phi = 1e-4) map where settling dominates", 0.0, scalar(&porous_map, "share_settling"), 0.0, ""),
        check(
            "Fig. 4.2 (Sect. 4.7)",
            "log10 largest Delta v / eta v_K, compact map",
            0.0,
            (scalar(&compact_map, "max_dv") / env.eta_vk).log10(),
            0.3,
            "Conclusion 2: drifting bodies against small ones collide at \"~eta v_K\"",
        ),
        check(
            "Fig. 4.14 (Sect. 5.2.5)",
            "log10 radius [km] at the planetesimal mass, porous track at 5 AU",
            0.5,
            full.points.last().map_or(f64::NAN, |q| (q.radius / 1e3).log10()),
            0.5,
            "\"kilometer-size planetesimals\": 1-10 km",
        ),
        check("Eq. 4.3", "sound speed at 5 AU [m/s]", 670.0, d.sound_speed(r), 15.0, ""),
        check("Eq. 4.4", "Omega at 5 AU [1/s]", 1.8e-8, d.omega(r), 5e-10, ""),
        check("Sect. 4.2.1", "h_g/R at 5 AU", 0.05, d.scale_height(r) / r, 0.002, ""),
        check("Sect. 4.2.2", "midplane mean free path at 5 AU [m]", 1.2, d.mean_free_path(r), 0.06, ""),
        check("Eq. 4.33", "eta at 5 AU", 4e-3, d.eta(r), 4e-4, ""),
        check("Sect. 4.2.4", "E_roll, 0.1 um ice [J]", 4e-16, mono.rolling_energy(), 2e-17, ""),
        check("Eq. 4.12", "v_frag, 0.1 um ice [m/s]", 80.0, mono.fragmentation_velocity(), 1e-9, ""),
        check(
            "Fig. 4.8",
            "log10 phi at the end of hit-and-stick (collisional only)",
            -5.0,
            log(coll.markers.collisional, 1),
            1.0,
            "order of magnitude",
        ),
        check(
            "Fig. 4.8 (Sect. 4.4.1)",
            "log10 mass [g] at Omega t_s = 1, porous ice",
            9.5,
            log(full.markers.stokes_one, 0) + 3.0,
            0.5,
            "",
        ),
        check(
            "Fig. 4.13",
            "outermost radius where a porous track reaches 1e16 g (perfect sticking) [AU]",
            10.0,
            formation,
            3.0,
            "\"the inner ~10 AU\" (ch. 4 conclusion 1); tracks from up to 60 AU drift in and form inside it",
        ),
        check(
            "Fig. 5.5 (Sect. 5.3.2)",
            "log10 filling factor at 1e16 g (self-gravity compaction, 4.15-4.16)",
            -1.0,
            full.points.last().map_or(f64::NAN, |q| q.filling.log10()),
            0.5,
            "\"increases to ~1e-1\"; (4.15)-(4.16) with E_roll = 3.9e-9 erg give 0.030 at 1e16 g: the wording is an order of magnitude",
        )
        .thesis(),
        check(
            "Fig. 4.8 (Sect. 4.4.1)",
            "log10 mass [g] of first self-gravity compaction",
            11.0,
            log(full.markers.gravity, 0) + 3.0,
            1.0,
            "1e10-1e12 g",
        ),
    ]
}

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

/// A number as printed: plain in a readable range, otherwise scientific.
fn plain(v: f64) -> String {
    let short = format!("{v}");
    if v == 0.0 || ((1e-3..1e4).contains(&v.abs()) && short.len() <= 7) {
        short
    } else if (1e-3..1e4).contains(&v.abs()) {
        // Four significant digits, trailing zeros dropped.
        let digits = (3 - v.abs().log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.digits$}");
        if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
    } else {
        format!("{v:e}")
    }
}

/// The figure a row's reference starts with ("Fig. 4.13" of "Fig. 4.13 (Sect. 4.6)").
pub fn figure_of(reference: &str) -> Option<&str> {
    let rest = reference.strip_prefix("Fig. ")?;
    let end = rest.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(rest.len());
    let number = rest[..end].trim_end_matches('.');
    (!number.is_empty()).then(|| &reference[..5 + number.len()])
}

/// The checks as a Markdown table.
pub fn markdown(checks: &[Check]) -> String {
    let mut s = String::from(
        "| figure | quantity | thesis | ours | tolerance | result | note |\n|---|---|---|---|---|---|---|\n",
    );
    for c in checks {
        s.push_str(&format!(
            "| {} | {} | {} | {:.4e} | ±{} | {} | {} |\n",
            c.figure,
            c.quantity,
            plain(c.thesis),
            c.ours,
            plain(c.tolerance),
            c.status(),
            c.note
        ));
    }
    let passed = checks.iter().filter(|c| c.pass()).count();
    let count = |status: &str| checks.iter().filter(|c| c.status() == status).count();
    let figures: std::collections::BTreeSet<&str> = checks.iter().filter_map(|c| figure_of(c.figure)).collect();
    s.push_str(&format!(
        "\n{passed} of {} within tolerance; {} differ for a reason inside the thesis, {} open, {} FAIL; {} figures checked.\n",
        checks.len(),
        count("thesis"),
        count("open"),
        count("FAIL"),
        figures.len()
    ));
    s
}

/// The checks as CSV.
pub fn csv(checks: &[Check]) -> Result<Vec<u8>, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(["figure", "quantity", "thesis", "ours", "tolerance", "pass", "status", "note"])?;
    for c in checks {
        w.write_record([
            c.figure,
            c.quantity,
            &c.thesis.to_string(),
            &format!("{:e}", c.ours),
            &c.tolerance.to_string(),
            if c.pass() { "true" } else { "false" },
            c.status(),
            c.note,
        ])?;
    }
    w.into_inner().map_err(|e| csv::Error::from(e.into_error()))
}

/// The Monte Carlo figures of ch. 4 with their checks.
#[derive(Debug)]
pub struct MonteCarlo {
    /// Comparisons with the published outcomes.
    pub checks: Vec<Check>,
    /// Figures, by preset name.
    pub figures: Vec<(String, crate::scene::SceneOutput)>,
}

/// The column parameters of a Monte Carlo scene.
fn column_of(scene: &mut crate::scene::SceneParams) -> Option<&mut crate::scene::monte_carlo::common::ColumnParams> {
    use crate::scene::SceneParams;
    match scene {
        SceneParams::MassDistribution(p) => Some(&mut p.run),
        SceneParams::Families(p) => Some(&mut p.run),
        SceneParams::ErosionBalance(p) => Some(&mut p.run),
        _ => None,
    }
}

/// log10 of m(Ωt_s = `st_2`)/m(Ωt_s = `st_1`) along the porous growth track at
/// 5 AU (MMSN, α = 10⁻³, 0.1 µm ice), and the local slope d log Ωt_s / d log m
/// around `st_2`.
pub fn implied_mass_ratio(st_1: f64, st_2: f64) -> (f64, f64) {
    use crate::physics::constants::{AU, YEAR};
    use crate::physics::growth::{GrowthModel, Porosity};
    let mut model = GrowthModel::chapter4(Porosity::Full);
    model.drift = false;
    let track = model.run(5.0 * AU, 1e8 * YEAR);
    let log_mass_at = |st: f64| {
        track.points.windows(2).find(|w| w[0].stokes < st && w[1].stokes >= st).map_or(f64::NAN, |w| {
            let x = (st / w[0].stokes).ln() / (w[1].stokes / w[0].stokes).ln();
            (w[0].mass.ln() + x * (w[1].mass / w[0].mass).ln()) / std::f64::consts::LN_10
        })
    };
    let slope = 1.0 / (log_mass_at(st_2 * 10f64.sqrt()) - log_mass_at(st_2 / 10f64.sqrt()));
    (log_mass_at(st_2) - log_mass_at(st_1), slope)
}

/// Runs the Monte Carlo presets (Figs. 4.4–4.12, 5.2) and checks the
/// published outcomes at 5 AU. `quick`: w* = 20 and one run per set, so that
/// CI can afford it; the checks keep their tolerances.
pub fn monte_carlo(quick: bool) -> Result<MonteCarlo, crate::scene::SceneError> {
    use crate::physics::PhysicsError;
    use crate::physics::constants::YEAR;
    use crate::scene::{Caches, Progress, SceneParams, compute_cached};
    let progress = Progress::default();
    let mut caches = Caches::default();
    let mut figures = Vec::new();
    let mut params = std::collections::BTreeMap::new();
    for name in [
        "mc-fig-4-4",
        "mc-fig-4-6",
        "mc-fig-4-9",
        "mc-fig-4-10-4-11",
        "mc-fig-4-12",
        "mc-fig-5-2-porosity",
        "mc-kernel-constant",
        "mc-kernel-linear",
        "mc-kernel-product",
    ] {
        let mut scene = crate::preset::resolve(name).map_err(|e| PhysicsError::Invalid(e.to_string()))?.scene;
        if quick {
            if let Some(run) = column_of(&mut scene) {
                run.groups_per_decade = 20.0;
                run.runs = 1;
            }
            if let SceneParams::KernelTests(k) = &mut scene {
                k.runs = 4;
            }
        }
        let out = compute_cached(&scene, &progress, &mut caches)?;
        params.insert(name, scene);
        figures.push((name.to_string(), out));
    }
    let column = |name: &str| {
        let mut scene = params.get(name).cloned().ok_or_else(|| PhysicsError::Invalid(format!("no preset {name}")))?;
        column_of(&mut scene).cloned().ok_or_else(|| PhysicsError::Invalid(format!("{name} is no column")))
    };
    let sticking =
        caches.get::<crate::scene::monte_carlo::common::RunCache>().get(&column("mc-fig-4-4")?, &progress)?;
    let porosity =
        caches.get::<crate::scene::monte_carlo::common::RunCache>().get(&column("mc-fig-5-2-porosity")?, &progress)?;
    let base = column("mc-fig-4-10-4-11")?;
    let SceneParams::ErosionBalance(balance) = &params["mc-fig-4-10-4-11"] else {
        return Err(PhysicsError::Invalid("mc-fig-4-10-4-11 is no erosion balance".into()).into());
    };
    let thresholds = [balance.v_eros_1, balance.v_eros_2, balance.v_eros_3];
    let mut eroded = Vec::new();
    for v in thresholds {
        let p = crate::scene::monte_carlo::common::ColumnParams { v_eros: v, ..base.clone() };
        eroded.push(caches.get::<crate::scene::monte_carlo::common::RunCache>().get(&p, &progress)?);
    }
    let first = |runs: &std::sync::Arc<Vec<crate::physics::coagulation::Run>>| runs.first().cloned();
    let mut checks = Vec::new();
    // log10 m_p [g] where Ωt_s(m_p) reaches 1, interpolated in log between the samples around it.
    let at_one = |r: &crate::physics::coagulation::Run| {
        r.history.windows(2).find(|w| w[0].stokes_p < 1.0 && w[1].stokes_p >= 1.0).map_or(f64::NAN, |w| {
            let x = -w[0].stokes_p.ln() / (w[1].stokes_p / w[0].stokes_p).ln();
            ((w[0].m_p.ln() + x * (w[1].m_p / w[0].m_p).ln()).exp() * 1e3).log10()
        })
    };
    if let Some(r) = first(&sticking) {
        checks.push(Check::new(
            "Fig. 4.4",
            "log10 m_p [g] where Omega t_s(m_p) reaches 1 (MC)",
            10.0,
            at_one(&r),
            1.0,
            "",
        ));
        let worst = crate::scene::monte_carlo::mass_distribution::growth_times(&r.history)
            .iter()
            .map(|g| g.1 / g.2)
            .fold(0.0, f64::max);
        checks.push(Check::new(
            "Fig. 4.5",
            "largest t_grow/t_drift of the peak mass (MC; below 1/30)",
            0.0,
            worst,
            1.0 / 30.0,
            "",
        ));
    }
    if let Some(r) = first(&porosity) {
        let p = params.get("mc-fig-5-2-porosity").cloned();
        let track = match p {
            Some(SceneParams::Families(f)) => crate::scene::monte_carlo::families::semi_analytical(&f.run),
            _ => Vec::new(),
        };
        let phi = |m: f64| {
            let k = track.partition_point(|q| q[0] < m).clamp(1, track.len().max(2) - 1);
            let (a, b) = (track.get(k - 1).copied().unwrap_or([1.0, 1.0]), track.get(k).copied().unwrap_or([2.0, 1.0]));
            let x = (m / a[0]).ln() / (b[0] / a[0]).ln();
            (a[1].ln() + x * (b[1] / a[1]).ln()).exp()
        };
        let worst = r
            .history
            .iter()
            .filter(|s| s.m_p > 1e-15 && s.m_p < track.last().map_or(0.0, |q| q[0]))
            .map(|s| (s.phi_p / phi(s.m_p)).log10().abs())
            .fold(0.0, f64::max);
        checks.push(Check::new(
            "Fig. 5.2",
            "largest |log10 phi_p(MC)/phi(track)| (within a factor 3)",
            0.0,
            worst,
            3f64.log10(),
            "",
        ));
    }
    let full = caches.get::<crate::scene::monte_carlo::common::RunCache>().get(&column("mc-fig-4-6")?, &progress)?;
    if let Some(r) = first(&full) {
        checks.push(Check::new(
            "Fig. 4.6 (Sect. 5.3.2)",
            "log10 m_p [g] where Omega t_s(m_p) reaches 1 (MC, full compaction)",
            9.0,
            at_one(&r),
            1.0,
            "\"In the inner disk, Omega t_s = 1 corresponds to m ~ 1e9 g\"",
        ));
        let worst = crate::scene::monte_carlo::mass_distribution::growth_times(&r.history)
            .iter()
            .map(|g| g.1 / g.2)
            .fold(0.0, f64::max);
        checks.push(Check::new(
            "Fig. 4.7",
            "largest t_grow/t_drift of the peak mass (MC, full compaction; below 1)",
            0.0,
            worst,
            1.0,
            "\"the growth is still fast enough to prevent particles from drifting significant distances\"",
        ));
    }
    let e1 = caches.get::<crate::scene::monte_carlo::common::RunCache>().get(&column("mc-fig-4-9")?, &progress)?;
    if let Some(r) = first(&e1) {
        let (_, m_steady) = crate::scene::monte_carlo::erosion_balance::steady_state(&r);
        let band = 3f64.log10();
        let settled = r
            .history
            .iter()
            .rev()
            .take_while(|q| (q.m_max / m_steady).log10().abs() <= band)
            .last()
            .map_or(f64::NAN, |q| q.t / YEAR);
        checks.push(Check::new(
            "Fig. 4.9",
            "log10 t [yr] from which m_max stays within 3x of its steady value, v_eros = 20 m/s",
            4000f64.log10(),
            settled.log10(),
            0.15,
            "\"after ~4000 yr a steady-state is reached\"; ours reaches the erosion barrier about 2x later (next row), while the steady state itself agrees (Fig. 4.11 rows)",
        )
        .open());
        if let Some(k) = r.history.iter().position(|q| q.zeta < 1.0) {
            let (t0, t1) = (r.history[k.saturating_sub(1)].t / YEAR, r.history[k].t / YEAR);
            checks.push(Check::new(
                "Fig. 4.12",
                "first erosion of the largest body (zeta < 1), v_eros = 20 m/s [yr]",
                3200.0,
                (t0 * t1).sqrt(),
                200.0 + 0.5 * (t1 - t0),
                "spread small \"during the first 3000 years\", first erosive collisions \"after 3400 years\"; plus half our sampling gap. Ours grows to the erosion barrier in about twice that time although the masses at Omega t_s = 1 agree (Figs. 4.4, 4.6)",
            )
            .open());
        }
    }
    if let Some(snap) = eroded.first().and_then(first).and_then(|r| r.snapshots.last().cloned()) {
        let largest_eroding = snap.projectiles.iter().filter(|q| q.1 < 0.0).map(|q| q.0).fold(0.0, f64::max);
        checks.push(Check::new(
            "Fig. 4.10",
            "log10 largest eroding projectile / m_max at the last snapshot (1e4 yr)",
            -2.0,
            (largest_eroding / snap.sample.m_max).log10(),
            0.5,
            "\"lose mass by colliding with particles that have a mass below 1e-2 m_t\"",
        ));
    }
    let steady: Vec<(f64, f64, f64)> = eroded
        .iter()
        .filter_map(first)
        .map(|r| {
            let (st, m) = crate::scene::monte_carlo::erosion_balance::steady_state(&r);
            (st, m, r.history.iter().map(|s| s.zeta).fold(1.0, f64::min))
        })
        .collect();
    if let [e20, e40, e60] = steady[..] {
        checks.push(Check::new(
            "Fig. 4.11",
            "log10 steady Omega t_s(m_max), v_eros = 20 m/s (0.6)",
            0.6f64.log10(),
            e20.0.log10(),
            0.5,
            "",
        ));
        checks.push(Check::new("Fig. 4.11", "lowest zeta, v_eros = 20 m/s (negative)", -0.5, e20.2, 0.5, ""));
        checks.push(Check::new(
            "Fig. 4.11",
            "log10 steady Omega t_s(m_max), v_eros = 40 m/s (~10)",
            1.0,
            e40.0.log10(),
            0.5,
            "",
        ));
        // The thesis's steady Stokes numbers, 0.6 (20 m/s) and ~10 (40 m/s),
        // carried to masses along the porous track at 5 AU.
        let (implied, slope) = implied_mass_ratio(0.6, 10.0);
        checks.push(Check::new(
            "Fig. 4.11 (Sect. 4.4.2)",
            "log10 m_max(40 m/s)/m_max(20 m/s), implied by the steady Omega t_s 0.6 and ~10",
            implied,
            (e40.1 / e20.1).log10(),
            0.5 / slope,
            "the porous track at 5 AU turns Omega t_s 0.6 -> 10 into this mass ratio; the tolerance carries the Stokes rows' 0.5 dex through Omega t_s ~ m^slope near 10",
        ));
        checks.push(
            Check::new(
                "Fig. 4.11 (Sect. 4.4.2)",
                "log10 m_max(40 m/s)/m_max(20 m/s) as worded (\"about a factor of 10\")",
                1.0,
                (e40.1 / e20.1).log10(),
                0.5,
                "the wording conflicts with the thesis's own Stokes numbers, which imply ~10^2.5 (row above)",
            )
            .thesis(),
        );
        checks.push(Check::new("Fig. 4.11", "lowest zeta, v_eros = 60 m/s (never below 0)", 0.5, e60.2, 0.5, ""));
    }
    Ok(MonteCarlo { checks, figures })
}
