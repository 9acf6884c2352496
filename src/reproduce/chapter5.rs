//! Chapter 5: the global dust-batch model and planetesimal maps.

use super::Check;
use crate::scene::batches::common::Growth;

/// The checks of chapter 5 (global dust batches; 1000 batches per disk at
/// Δln m = 0.05 with the kernel estimate of Σ_d, where the zone edge of
/// Fig. 5.9's disk is within 0.5 % of its converged value; see
/// `tests/batches.rs`).
pub fn chapter5() -> Result<Vec<Check>, crate::scene::SceneError> {
    use crate::physics::batches::{BatchRun, alpha_midplane, max_loading, surface_density};
    use crate::physics::constants::{AU, YEAR};
    use crate::physics::disk::{GasDisk, Profile};
    use crate::scene::Progress;
    use crate::scene::batches::common::BatchParams;
    use rayon::prelude::*;
    let check = Check::new;
    let progress = Progress::default();
    let base = BatchParams { batches: 1000, dlnm: 0.05, ..BatchParams::default() };
    let with = |mass: f64, z: f64, r_c: f64, cold: bool| {
        let mut b = base.clone();
        b.disk.disk_mass = mass;
        b.disk.metallicity = z;
        b.disk.r_c = r_c;
        b.disk.cold = cold;
        b
    };
    let mut compact = with(0.01, 0.01, 30.0, false);
    compact.growth = Growth::Compact;
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
    compact_slow.growth = Growth::Compact;
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
    // The same grid at the thesis's own step, Δt ≤ min(0.5 t_grow, 0.05 t_drift)
    // with the rates at the start of the step (Sect. 5.2.5).
    let thesis_step: Vec<f64> = runs[6..15]
        .par_iter()
        .map(|b| {
            let mut cfg = b.config();
            cfg.model.dlnm = 0.5;
            cfg.model.drift_step = 0.05;
            cfg.model.midpoint = false;
            crate::physics::batches::run(&cfg, &|_| false).map(|r| r.converted_fraction())
        })
        .collect::<Result<_, _>>()?;
    let least_thesis_step = thesis_step.iter().copied().fold(f64::INFINITY, f64::min);
    let eta = base.disk.disk().eta(AU);
    // Fig. 5.1: the initial Σ_d against Z0 Σ_g between 5 and 150 AU.
    let points: Vec<(f64, f64)> = done[0].initial_radii.iter().copied().zip(done[0].masses.iter().copied()).collect();
    let sigma = surface_density(&points, runs[0].config().density_smoothing());
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
    // The SI front: from the innermost batch inside R_c meeting the SI
    // conditions outward, the outermost such batch up to which at least half
    // of the dust batches meet them. It leaves out the tail beyond ~5 R_c,
    // where the thin gas gives Omega t_s ~ 0.07 early and the conditions hold
    // far out.
    let r_c = runs[16].disk.r_c;
    let front = |f: &crate::physics::batches::Frame| {
        let mut dust: Vec<(f64, bool)> = f.batches.iter().filter(|q| q.dust).map(|q| (q.r / AU, q.si)).collect();
        dust.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (mut seen, mut meeting, mut edge) = (0usize, 0usize, 0.0f64);
        for (r, si) in dust.iter().skip_while(|q| !(q.1 && q.0 < r_c)) {
            seen += 1;
            if *si {
                meeting += 1;
                if 2 * meeting >= seen {
                    edge = *r;
                }
            }
        }
        edge
    };
    let uranus = 19.2;
    let si_reach = done[16].frames.iter().find(|f| front(f) >= uranus).map_or(f64::NAN, |f| (f.t / YEAR).log10());
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
            "\"growth towards similar Stokes numbers takes almost 1e6 yr\"; ours 4.0e5 yr with the midplane velocities of App. 5.B (3.0e5 yr when differential settling is counted, as ch. 4 does)",
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
            "\"do not reach Omega t_s > 1e-2\"; the largest values are the 0.1 um monomers of the outermost batches (188-200 AU) from t = 0: in the thesis's own disk (5.1) their Epstein Omega t_s = pi rho_0 a_0/(2 Sigma_g) is 0.0136 at 200 AU. Grown dust stays below 1e-2 (next row)",
        )
        .thesis(),
        check(
            "Fig. 5.12",
            "log10 largest Omega t_s of grown dust (m >= 2 m0), compact, v_frag = 1 m/s",
            -2.5,
            dust(&done[15])
                .iter()
                .filter(|q| q.mass >= 2.0 * runs[15].disk.monomer().mass())
                .map(|q| q.stokes)
                .fold(0.0, f64::max)
                .log10(),
            0.5,
            "\"Compact particles do not reach Omega t_s > 1e-2\" while \"a large region\" has Omega t_s > 1e-3",
        ),
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
            "log10 t [yr] when the SI front (outer edge of the region where most dust batches meet SI) reaches 19.2 AU",
            5.0,
            si_reach,
            0.5,
            "\"this region moves outward, reaching the current location of Uranus after 1e5 yr\"; ours (App. 5.B's midplane velocities) first meets the conditions at 7e3 yr, moves past 10 AU at 3.5e4 yr and reaches 19.2 AU at 5.3e4 yr; the dust is gone by 8.9e4 yr (with settling counted as in ch. 4: 3.0e4 yr, about 3x sooner). Beyond ~5 R_c the thin gas gives Omega t_s ~ 0.07 from 7e3 yr, so the conditions also hold at 150-190 AU, a region the thesis does not describe",
        ),
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
            "\"~5 AU\"; the thesis does not give the radial scale over which (5.7) differentiates the cumulative mass, and the edge follows it: ours 6.14 AU with the kernel of half-width 0.1 (1000 batches, Delta ln m = 0.05; 6.19 AU with 2000 batches), 5.65 AU at half-width 0.07; the neighbour annuli of earlier versions gave 4.03 AU here without converging (4.31 AU at Delta ln m = 0.025, 3.87 AU with 2000 batches at 0.025)",
        )
        .thesis(),
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
            "\"over 70 %\" for every disk of the top grid; the poorest disk (0.01 M_sun, Z0 = 0.01) converts where drifting batches pile up enough to outgrow drift. With the neighbour annuli of earlier versions it gave 0.695 at this setting and kept falling with the resolution (0.58 with 2000 batches at Delta ln m = 0.025); with the kernel estimate it does not depend on the step (next row)",
        ),
        check(
            "Fig. 5.8 (Sect. 5.2.5)",
            "smallest converted fraction on the top grid at the thesis's step (Delta t <= min(0.5 t_grow, 0.05 t_drift), rates at the step's start)",
            0.8,
            least_thesis_step,
            0.1,
            "\"over 70 %\"; each batch takes its own step at the thesis's bound, where the thesis used one global step set by the fastest batch, which in the pile-up that decides the fraction is one of those batches",
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
