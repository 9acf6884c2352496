//! The global dust-batch model of thesis ch. 5: conservation, the published
//! checks, convergence with the batch count and parameter errors.

use grainscope::physics::batches::{BatchConfig, BatchRun, Fate, alpha_midplane, run, surface_density};
use grainscope::physics::constants::AU;
use grainscope::scene::batches::common::{BatchParams, Growth};
use grainscope::scene::{self, Progress, SceneParams};

fn go(cfg: &BatchConfig) -> BatchRun {
    run(cfg, &|_| false).expect("valid configuration")
}

fn params_run(p: &BatchParams) -> BatchRun {
    p.run(&Progress::default()).expect("valid parameters")
}

fn assert_conserved(r: &BatchRun) {
    assert!(r.total_mass > 0.0);
    for f in &r.frames {
        let sum: f64 = f.budget.iter().sum();
        assert!(
            ((sum - r.total_mass) / r.total_mass).abs() <= 1e-12,
            "t = {:e} s: budget {:?} sums to {sum:e}, total {:e}",
            f.t,
            f.budget,
            r.total_mass
        );
        assert!(f.budget.iter().all(|m| *m >= 0.0));
    }
}

#[test]
fn initial_batches_reproduce_the_dust_surface_density() {
    // (5.6)-(5.7): the batch positions and masses give back Z₀ Σ_g.
    let cfg = BatchConfig::figure_5_6(500);
    let r = go(&BatchConfig { t_end: 1e-6 * cfg.t_end, ..cfg.clone() });
    let points: Vec<(f64, f64)> = r.initial_radii.iter().copied().zip(r.masses.iter().copied()).collect();
    let sigma = surface_density(&points, cfg.density_smoothing());
    for (i, (radius, _)) in points.iter().enumerate() {
        if *radius > 5.0 * AU && *radius < 150.0 * AU {
            let expected = cfg.model.disk.dust_surface_density(*radius);
            assert!(
                (sigma[i] / expected - 1.0).abs() < 0.02,
                "R = {:.1} AU: {:e} against {expected:e}",
                radius / AU,
                sigma[i]
            );
        }
    }
}

#[test]
fn mass_is_conserved_to_1e_12_in_every_frame() {
    assert_conserved(&go(&BatchConfig::figure_5_6(300)));
    let mut compact = BatchParams { growth: Growth::Compact, v_frag: 5.0, ..BatchParams::default() };
    compact.disk.icy = false;
    assert_conserved(&params_run(&compact));
    assert_conserved(&params_run(&BatchParams { coagulation: false, duration_yr: 1e7, ..BatchParams::default() }));
}

#[test]
fn figure_5_3_compact_silicates_empty_the_disk_within_a_million_years() {
    let mut p = BatchParams { growth: Growth::Compact, v_frag: 5.0, ..BatchParams::default() };
    p.disk.icy = false;
    p.disk.metallicity = 0.01;
    let r = params_run(&p);
    let end = r.frames.last().expect("frames");
    assert!(end.budget[0] / r.total_mass < 0.01, "dust left {:.3}", end.budget[0] / r.total_mass);
    assert_eq!(end.budget[1], 0.0, "fragmentation-limited compact growth forms no planetesimals");
}

#[test]
fn figure_5_6_planetesimals_form_out_to_about_5_au_and_converge_as_the_batch_count_doubles() {
    // "~5 AU" in the thesis; 6.19 AU with the default kernel, whose width the
    // thesis does not give (5.65 AU at a half-width of 0.07; README).
    let r = go(&BatchConfig::figure_5_6(2000));
    let edge = r.outermost_planetesimals() / AU;
    assert!((4.0..6.5).contains(&edge), "edge {edge:.2} AU");
    // Inside-out: batches that start further in turn into planetesimals earlier.
    let formed: Vec<(f64, f64)> = r
        .fates
        .iter()
        .zip(&r.initial_radii)
        .filter_map(|(f, r0)| if let Fate::Planetesimals { t, .. } = f { Some((*r0, *t)) } else { None })
        .collect();
    assert!(formed.len() > 10);
    assert!(formed.first().expect("some").1 < formed.last().expect("some").1);
    assert!(r.converted_fraction() > 0.3);
    let half = go(&BatchConfig::figure_5_6(1000)).outermost_planetesimals() / AU;
    assert!((half / edge - 1.0).abs() < 0.1, "1000 batches: {half:.2} AU, 2000: {edge:.2} AU");
}

/// The outer edge of planetesimal formation in Fig. 5.9's disk (0.2 M☉,
/// Z₀ = 0.05, R_c = 30 AU), AU, converged in the batch count and the step:
/// 21.68 / 21.67 AU with 2000 batches at Δln m = 0.05 / 0.025, 21.72 AU with
/// 4000 at 0.1 (the ignored test below); 500 batches at 0.2 give 21.45 AU.
const FIG_5_9_EDGE_AU: f64 = 21.7;

/// Fig. 5.9's disk with `batches` batches and growth step `dlnm`.
fn fig_5_9(batches: usize, dlnm: f64) -> BatchParams {
    let mut p = BatchParams { batches, dlnm, ..BatchParams::default() };
    p.disk.disk_mass = 0.2;
    p.disk.metallicity = 0.05;
    p.disk.r_c = 30.0;
    p
}

#[test]
fn zone_edge_is_within_2_percent_of_the_converged_reference_from_500_batches() {
    for (batches, dlnm) in [(500, 0.2), (1000, 0.1)] {
        let edge = params_run(&fig_5_9(batches, dlnm)).outermost_planetesimals() / AU;
        assert!(
            (edge / FIG_5_9_EDGE_AU - 1.0).abs() < 0.02,
            "{batches} batches at {dlnm}: {edge:.3} AU against {FIG_5_9_EDGE_AU} AU"
        );
    }
}

/// The reference itself (about two minutes on two cores; `.ci/run` runs it).
#[test]
#[ignore]
fn zone_edge_reference_is_converged_in_batches_and_step() {
    let base = params_run(&fig_5_9(2000, 0.05)).outermost_planetesimals() / AU;
    let finer = params_run(&fig_5_9(2000, 0.025)).outermost_planetesimals() / AU;
    let more = params_run(&fig_5_9(4000, 0.1)).outermost_planetesimals() / AU;
    for (what, edge) in [("2000 batches, 0.05", base), ("2000 batches, 0.025", finer), ("4000 batches, 0.1", more)] {
        assert!((edge / FIG_5_9_EDGE_AU - 1.0).abs() < 0.01, "{what}: {edge:.3} AU against {FIG_5_9_EDGE_AU} AU");
    }
}

/// The formation-zone scene of a single disk (M_D in M☉, Z₀, R_c in AU) at
/// its default resolution, batches out to 300 AU.
fn one_disk_zone(mass: f64, z: f64, r_c: f64) -> SceneParams {
    use grainscope::scene::batches::formation_zone::Params;
    SceneParams::FormationZone(Params {
        mass_min: mass,
        mass_max: mass,
        n_mass: 1,
        z_min: z,
        z_max: z,
        n_z: 1,
        r_c_1: r_c,
        r_c_2: r_c,
        run: BatchParams { r_out_au: 300.0, ..BatchParams::default() },
        ..Params::default()
    })
}

/// A single disk of the formation-zone scene at its default resolution:
/// (edge, reported error), AU.
fn zone_of(mass: f64, z: f64, r_c: f64) -> (f64, f64) {
    let out = scene::compute(&one_disk_zone(mass, z, r_c), &Progress::default()).expect("valid disk");
    (out.scalar("widest_zone").expect("edge"), out.scalar("widest_zone_error").expect("error"))
}

/// A run that keeps only its end state (no frames per decade: the
/// formation zone's runs, which need only the fates) ends as the run with
/// every frame does, to the last bit: the frames are an output the dynamics
/// never read.
#[test]
fn a_run_without_frames_ends_as_the_run_with_them() {
    let cfg = BatchConfig::figure_5_6(200);
    let with = go(&cfg);
    let without = go(&BatchConfig { frames_per_decade: 0, ..cfg });
    assert!(with.frames.len() > 200, "{} frames", with.frames.len());
    assert_eq!(without.frames.len(), 1);
    assert_eq!(with.fates, without.fates);
    assert_eq!(with.frames.last(), without.frames.last());
    assert!(with.fates.iter().any(|f| matches!(f, Fate::Planetesimals { .. })), "nothing to compare");
}

/// The outputs a computation of `p` offers before its result, and the result.
fn offered_and_final(p: &SceneParams) -> (Vec<scene::SceneOutput>, scene::SceneOutput) {
    use std::sync::{Arc, Mutex};
    let offered: Arc<Mutex<Vec<scene::SceneOutput>>> = Arc::default();
    let keep = Arc::clone(&offered);
    let watcher = scene::Watcher(Arc::new(move |r: scene::Report<'_>| {
        if let scene::Report::Partial(out) = r {
            keep.lock().expect("not poisoned").push(out.clone());
        }
    }));
    let out = scene::compute(p, &Progress::watched(watcher)).expect("valid grid");
    let offered = offered.lock().expect("not poisoned").clone();
    (offered, out)
}

/// The formation zone's first picture (what the window shows while the
/// grid computes) is the final result's own runs at every other disk mass,
/// the first and last always: the same edges to the last bit, where the
/// 12-batch preview of earlier versions put Fig. 5.9's edges at 2–3 times
/// the full run's. The window takes no separate preview for this scene.
#[test]
fn the_formation_zone_shows_its_own_runs_at_every_other_mass_first() {
    use grainscope::scene::batches::formation_zone::Params;
    let grid = SceneParams::FormationZone(Params {
        n_mass: 5,
        n_z: 1,
        run: BatchParams { batches: 40, r_out_au: 300.0, ..BatchParams::default() },
        ..Params::default()
    });
    assert!(grid.preview().is_none(), "the window computes a separate preview");
    assert!(grid.coarse().is_some(), "sweeps and the coarse audit keep their cheaper setting");
    let (offered, out) = offered_and_final(&grid);
    assert_eq!(offered.len(), 1, "one first picture");
    let first = &offered[0];
    assert!(
        first.notes[0].starts_with("first picture: every other disk mass (3 of 5) at 40 batches, 6 disks"),
        "{:?}",
        first.notes
    );
    let (shown, all) = (&first.figures[0].series, &out.figures[0].series);
    assert_eq!(shown.len(), 2);
    assert_eq!(shown.len(), all.len());
    for (s, f) in shown.iter().zip(all) {
        assert_eq!(s.name, f.name);
        assert_eq!(f.points.len(), 5);
        let every_other: Vec<[f64; 2]> = [0, 2, 4].iter().map(|&i| f.points[i]).collect();
        assert_eq!(s.points, every_other, "{}: not the final runs", s.name);
    }
    // Its resolution check is still to come: undefined, not zero.
    assert!(first.scalar("edge_error").is_some_and(f64::is_nan));
    assert!(out.scalar("edge_error").is_some_and(f64::is_finite));
}

/// A grid of one or two disk masses shows every disk with half the batches
/// first: the final result's own resolution check, so the first picture's
/// widest edge differs from the final one by exactly the reported
/// `widest_zone_error`. Below 20 batches there is no such run, and nothing
/// comes first.
#[test]
fn a_single_disk_shows_its_run_with_half_the_batches_first() {
    let SceneParams::FormationZone(mut disk) = one_disk_zone(0.2, 0.05, 30.0) else { unreachable!() };
    disk.run.batches = 40;
    let (offered, out) = offered_and_final(&SceneParams::FormationZone(disk.clone()));
    assert_eq!(offered.len(), 1, "one first picture");
    assert!(
        offered[0].notes[0].starts_with("first picture: every disk at 20 batches, 2 disks"),
        "{:?}",
        offered[0].notes
    );
    let (first, last) = (offered[0].scalar("widest_zone").expect("edge"), out.scalar("widest_zone").expect("edge"));
    assert_eq!((first - last).abs(), out.scalar("widest_zone_error").expect("error"));
    assert!(first > 0.0 && first != last, "the check cannot tell: {first} and {last} AU");
    disk.run.batches = 16;
    let (offered, _) = offered_and_final(&SceneParams::FormationZone(disk));
    assert!(offered.is_empty(), "a first picture without runs with half the batches");
}

/// The formation zone's coarse setting of a single disk (`Scene::coarse`,
/// 120 batches: a sweep's preview, the coarse audit) against the full edge
/// (500 batches): Fig. 5.9's disk 22.42
/// against 21.41 AU (+4.7 %), two disks not in the thesis 9.06 against 7.98
/// (+13.5 %) and 10.64 against 10.24 AU (+3.9 %). At 40 batches (the preview
/// of earlier versions) they came out at 29.85, 17.13 and 19.82 AU
/// (+39 to +115 %). The edge follows one batch, so a preview is not within
/// 10 % of it everywhere (0.05 M☉, Z₀ = 0.02, R_c = 100 AU: +43 %).
#[test]
fn a_single_disk_preview_of_the_formation_zone_is_near_its_edge() {
    for (mass, z, r_c) in [(0.2, 0.05, 30.0), (0.1, 0.01, 30.0), (0.03, 0.03, 50.0)] {
        let p = one_disk_zone(mass, z, r_c);
        let preview = p.coarse().expect("the formation zone has a preview");
        let SceneParams::FormationZone(coarse) = &preview else { panic!("the preview of another scene") };
        assert_eq!(coarse.run.batches, 120, "a single disk's preview");
        let widest = |q: &SceneParams| {
            scene::compute(q, &Progress::default()).expect("valid disk").scalar("widest_zone").expect("edge")
        };
        let (rough, full) = (widest(&preview), widest(&p));
        let within = if mass == 0.2 { 0.05 } else { 0.15 };
        assert!(
            (rough / full - 1.0).abs() < within,
            "{mass} M☉, Z₀ = {z}, R_c = {r_c} AU: preview {rough:.2} AU, full {full:.2} AU"
        );
    }
}

#[test]
fn zone_edge_at_the_default_resolution_on_a_disk_not_in_the_thesis() {
    // 0.1 M☉, Z₀ = 0.01, R_c = 30 AU: converged 8.33 AU (4000 batches at
    // Δln m = 0.1; 8.30 AU with 2000), where the annuli of earlier versions
    // gave 9.75 / 7.90 / 7.38 / 8.08 / 6.10 AU with 120 to 2000 batches.
    let (edge, change) = zone_of(0.1, 0.01, 30.0);
    assert!((edge / 8.33 - 1.0).abs() < 0.05, "{edge:.2} AU against 8.33 AU");
    assert!(change.is_finite() && change >= 0.0, "change with half the batches {change}");
}

/// A second disk not in the thesis (0.03 M☉, Z₀ = 0.03, R_c = 50 AU):
/// 10.24 AU at the default 500 batches, 10.39 AU with 4000 (`.ci/run` runs
/// it, about a minute).
#[test]
#[ignore]
fn zone_edge_of_a_second_disk_not_in_the_thesis_is_converged_at_2000_batches() {
    let disk = |batches: usize| {
        let mut p = BatchParams { batches, dlnm: 0.1, r_out_au: 300.0, ..BatchParams::default() };
        p.disk.disk_mass = 0.03;
        p.disk.metallicity = 0.03;
        p.disk.r_c = 50.0;
        params_run(&p).outermost_planetesimals() / AU
    };
    let (a, b) = (disk(2000), disk(4000));
    let default = params_run(&BatchParams {
        batches: 500,
        dlnm: 0.2,
        r_out_au: 300.0,
        disk: grainscope::scene::disk::common::DiskParams {
            disk_mass: 0.03,
            metallicity: 0.03,
            r_c: 50.0,
            ..BatchParams::default().disk
        },
        ..BatchParams::default()
    })
    .outermost_planetesimals()
        / AU;
    assert!((a / b - 1.0).abs() < 0.01, "2000: {a:.3} AU, 4000: {b:.3} AU");
    assert!((default / b - 1.0).abs() < 0.05, "500 batches at 0.2: {default:.3} AU, 4000: {b:.3} AU");
}

#[test]
fn erosion_at_20_m_s_prevents_direct_planetesimal_formation() {
    let r = params_run(&BatchParams { v_eros: 20.0, ..BatchParams::default() });
    assert_eq!(r.outermost_planetesimals(), 0.0);
    assert!(r.fates.iter().all(|f| !matches!(f, Fate::Planetesimals { .. })));
    assert_conserved(&r);
}

#[test]
fn without_coagulation_micron_grains_barely_drift() {
    // Fig. 5.1: compact 1 µm silicates have Ωt_s ~ 1e-6 and drift little in 1e7 yr.
    let mut p = BatchParams { coagulation: false, growth: Growth::Compact, duration_yr: 1e7, ..BatchParams::default() };
    p.disk.monomer_radius = 1e-6;
    p.disk.icy = false;
    let r = params_run(&p);
    let end = r.frames.last().expect("frames");
    assert_eq!(end.budget[1], 0.0);
    for (s, r0) in end.batches.iter().zip(&r.initial_radii) {
        assert!(s.r <= *r0 * (1.0 + 1e-12), "a batch moved outward");
        assert_eq!(s.mass, end.batches[0].mass, "no growth without coagulation");
    }
    assert!(end.budget[0] / r.total_mass > 0.9);
}

#[test]
fn cold_disk_widens_the_zone_and_richer_disks_reach_further() {
    // The warm and cold disks of Fig. 5.10 (0.01 M☉, Z₀ = 0.02, R_c = 100 AU).
    let mut base = BatchParams::default();
    base.disk.r_c = 100.0;
    let warm = params_run(&base).outermost_planetesimals();
    let mut c = base.clone();
    c.disk.cold = true;
    let cold = params_run(&c).outermost_planetesimals();
    assert!(cold / warm > 1.5 && cold / warm < 2.5, "cold/warm {:.2}", cold / warm);
    let mut rich = base.clone();
    rich.disk.r_c = 30.0;
    rich.disk.disk_mass = 0.2;
    rich.disk.metallicity = 0.05;
    let rich_edge = params_run(&rich).outermost_planetesimals() / AU;
    assert!((16.0..24.0).contains(&rich_edge), "0.2 M_sun, Z0 = 0.05: {rich_edge:.1} AU");
}

#[test]
fn midplane_turbulence_matches_the_quoted_magnitudes() {
    let eta = BatchParams::default().disk.disk().eta(AU);
    let low = alpha_midplane(eta, 0.01, 1e-2);
    let high = alpha_midplane(eta, 0.01, 1.0);
    assert!((low.log10() + 6.0).abs() < 0.5, "{low:e}");
    assert!((high.log10() + 4.0).abs() < 0.5, "{high:e}");
    assert!((high / low - 100.0).abs() < 1e-9, "alpha_mp scales with the Stokes number");
}

#[test]
fn runs_stay_finite_and_conservative_over_the_documented_ranges() {
    for mass in [1e-4, 0.5] {
        for alpha in [1e-6, 1e-1] {
            for z in [1e-4, 0.1] {
                let mut p = BatchParams { batches: 40, ..BatchParams::default() };
                p.disk.disk_mass = mass;
                p.disk.alpha = alpha;
                p.disk.metallicity = z;
                let r = params_run(&p);
                assert_conserved(&r);
                for f in &r.frames {
                    for b in f.batches.iter().filter(|b| b.dust) {
                        assert!(
                            b.r.is_finite() && b.mass.is_finite() && b.stokes.is_finite() && b.filling > 0.0,
                            "M = {mass}, alpha = {alpha}, Z = {z}: {b:?}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn bad_parameters_are_refused_with_a_clear_message() {
    let p = BatchParams { r_in_au: 50.0, r_out_au: 20.0, ..BatchParams::default() };
    let e = p.run(&Progress::default()).expect_err("r_in > r_out").to_string();
    assert!(e.contains("r_in"), "{e}");

    let mut p = BatchParams::default();
    p.disk.disk_mass = -0.01;
    let e = p.run(&Progress::default()).expect_err("negative mass").to_string();
    assert!(e.contains("mass"), "{e}");

    let p = BatchParams { dlnm: 0.0, ..BatchParams::default() };
    let e = p.run(&Progress::default()).expect_err("zero step").to_string();
    assert!(e.contains("dlnm"), "{e}");

    let mut s = SceneParams::default_for("planetesimal-yield").expect("scene");
    let e = s.set("n_mass", "0").expect_err("empty sweep").to_string();
    assert!(e.contains("n_mass"), "{e}");
    let e = s.set("disk_mass", "-1").expect_err("negative mass").to_string();
    assert!(e.contains("disk_mass"), "{e}");
    let e = s.set("r_in_au", "NaN").expect_err("non-finite").to_string();
    assert!(e.contains("r_in_au"), "{e}");

    let mut z = SceneParams::default_for("formation-zone").expect("scene");
    let e = z.set("contrast", "hotter").expect_err("unknown choice").to_string();
    assert!(e.contains("contrast"), "{e}");
}

#[test]
fn cancelling_stops_a_run() {
    let progress = Progress::default();
    progress.cancel();
    let s = SceneParams::default_for("disk-map").expect("scene");
    assert!(matches!(scene::compute(&s, &progress), Err(scene::SceneError::Cancelled)));
}

#[test]
fn sweeps_report_progress_by_finished_disks() {
    let mut s = SceneParams::default_for("planetesimal-yield").expect("scene");
    for (k, v) in [("n_mass", "2"), ("n_z", "2"), ("batches", "40")] {
        s.set(k, v).expect("in range");
    }
    let progress = Progress::default();
    let out = scene::compute(&s, &progress).expect("sweep");
    assert_eq!(out.scalars.iter().find(|x| x.key == "runs").map(|x| x.value), Some(4.0));
    assert!((progress.fraction() - 1.0).abs() < 1e-9, "{}", progress.fraction());
}

#[test]
fn display_changes_reuse_the_cached_run() {
    use grainscope::scene::batches::common::RunCache;
    let mut cache = RunCache::default();
    let p = BatchParams { batches: 30, ..BatchParams::default() };
    let progress = Progress::default();
    let first = cache.get(&p, &progress).expect("run");
    let again = cache.get(&p, &progress).expect("run");
    assert!(std::sync::Arc::ptr_eq(&first, &again), "same run parameters must not rerun the model");
    let other = cache.get(&BatchParams { v_eros: 20.0, ..p.clone() }, &progress).expect("run");
    assert!(!std::sync::Arc::ptr_eq(&first, &other), "a changed run parameter must rerun the model");
    // The cached result equals a fresh run.
    let fresh = cache.get(&p, &progress).expect("run");
    assert_eq!(fresh.frames, params_run(&p).frames);

    // Scenes: changing only the thinning or colouring keeps the output of the same run.
    let mut caches = scene::Caches::default();
    let mut s = SceneParams::default_for("batch-lifelines").expect("scene");
    s.set("batches", "30").expect("in range");
    let a = scene::compute_cached(&s, &progress, &mut caches).expect("scene");
    s.set("colour_by_filling", "true").expect("toggle");
    let b = scene::compute_cached(&s, &progress, &mut caches).expect("scene");
    assert_eq!(a.scalars, b.scalars);
}

/// The batch parameters of a shipped disk-map preset.
fn disk_map_of(name: &str) -> BatchParams {
    match grainscope::preset::resolve(name).expect(name).scene {
        SceneParams::DiskMap(p) => p.run,
        other => panic!("{name} is not a disk map: {other:?}"),
    }
}

/// The loading a tenth of the dust reaches settles with the batch count where
/// the largest loading does not. Measured (500 / 1000 / 2000 / 4000 batches):
/// Fig. 5.13's disk 0.1236 / 0.1194 / 0.1242 / 0.1165, a disk not in the
/// thesis 0.0179 / 0.0176 / 0.0173 / 0.0173: within 7 % of the 4000-batch
/// value at the default 500, and within 7 % of each other from 2000 on
/// (the largest loading of `batch-fig-5-4` at R_c = 205 AU moves by a factor
/// of four over such counts). `.ci/run` runs it, about half a minute.
#[test]
#[ignore]
fn the_loading_a_tenth_of_the_dust_reaches_is_converged_at_the_default_batch_count() {
    let other = {
        let mut p = disk_map_of("batch-fig-5-6");
        p.disk.disk_mass = 0.03;
        p.disk.metallicity = 0.01;
        p.disk.r_c = 50.0;
        p
    };
    for (what, p) in [("Fig. 5.13", disk_map_of("batch-fig-5-13")), ("0.03 M☉, Z₀ = 0.01, R_c = 50 AU", other)] {
        let at = |batches: usize| params_run(&BatchParams { batches, ..p.clone() }).loading_reached_by(0.1);
        let (default, finer, finest) = (at(p.batches), at(2000), at(4000));
        assert!(finest > 0.0, "{what}: {finest}");
        assert!(
            (default / finest - 1.0).abs() < 0.07 && (finer / finest - 1.0).abs() < 0.07,
            "{what}: {default:.4} at {} batches, {finer:.4} at 2000, {finest:.4} at 4000",
            p.batches
        );
    }
}

/// The formation zone's quick path to its largest edge (no runs with half
/// the batches) equals the whole computation, and a dashed disk set equal to
/// the solid one (the same R_c) gives the same edges.
#[test]
fn the_formation_zone_quick_path_and_a_repeated_disk_set_give_the_same_edges() {
    use grainscope::scene::batches::formation_zone::Params;
    let p = Params {
        mass_min: 0.05,
        mass_max: 0.2,
        n_mass: 2,
        z_min: 0.03,
        z_max: 0.03,
        n_z: 1,
        r_c_1: 30.0,
        r_c_2: 30.0,
        run: BatchParams { batches: 40, ..BatchParams::default() },
        ..Params::default()
    };
    let params = SceneParams::FormationZone(p);
    let out = scene::compute(&params, &Progress::default()).expect("valid grid");
    let fig = &out.figures[0];
    assert_eq!(fig.series.len(), 2);
    assert_eq!(fig.series[0].points, fig.series[1].points);
    let widest = out.scalar("widest_zone").expect("widest");
    assert!(widest > 0.0);
    let quick = scene::scalar(&params, "widest_zone", &Progress::default()).expect("computes").expect("a quick path");
    assert_eq!(quick, widest);
}

/// The formation zone shared among 2 and 3 processes, as a browser shares
/// it among its workers (each takes every n-th disk, one gathers the edges
/// and finishes), gives the undivided result to the bit, in three rounds
/// (the first picture's runs, the rest, the result); the dashed set equal to
/// the solid one runs once either way.
#[test]
fn the_formation_zone_shared_among_processes_equals_the_undivided_one() {
    use grainscope::scene::batches::formation_zone::Params;
    use grainscope::scene::parts::in_turns;
    let p = Params {
        mass_min: 0.05,
        mass_max: 0.2,
        n_mass: 3,
        z_min: 0.02,
        z_max: 0.03,
        n_z: 1,
        r_c_1: 30.0,
        r_c_2: 60.0,
        run: BatchParams { batches: 40, ..BatchParams::default() },
        ..Params::default()
    };
    let params = SceneParams::FormationZone(p);
    let whole = scene::compute(&params, &Progress::default()).expect("valid grid");
    let bits = |o: &scene::SceneOutput| -> Vec<u64> {
        let points = o.figures.iter().flat_map(|f| f.series.iter().flat_map(|s| s.points.iter().flatten()));
        o.scalars.iter().map(|s| s.value).chain(points.copied()).map(f64::to_bits).collect()
    };
    for n in [2, 3] {
        let (shared, rounds) = in_turns(n, |progress| scene::compute(&params, progress)).expect("valid grid");
        assert_eq!(rounds, 3, "{n} processes");
        assert_eq!(bits(&shared), bits(&whole), "{n} processes");
    }
}
