//! The monomer card: every aggregate scene takes it by key, and a change of
//! the monomer reaches the porosity track, the Monte Carlo column and the
//! batch model through their `compute`.

use grainscope::scene::monomer::MONOMER_KEYS;
use grainscope::scene::{Progress, SCENES, SceneParams, compute};

fn scene(id: &str, set: &[(&str, &str)]) -> SceneParams {
    let mut p = SceneParams::default_for(id).expect("scene");
    for (k, v) in set {
        p.set(k, v).unwrap_or_else(|e| panic!("{id}: {k}={v}: {e}"));
    }
    p
}

fn scalar(p: &SceneParams, key: &str) -> f64 {
    let out = compute(p, &Progress::default()).expect("computes");
    out.scalar(key).unwrap_or_else(|| panic!("{}: no {key}", p.info().id))
}

#[test]
fn every_aggregate_scene_takes_the_card_by_key() {
    let with_card: Vec<&str> = SCENES
        .iter()
        .filter(|s| SceneParams::default_for(s.id).and_then(|p| p.monomer_card()).is_some())
        .map(|s| s.id)
        .collect();
    assert!(with_card.len() >= 14, "{with_card:?}");
    for id in with_card {
        let p = scene(
            id,
            &[("rolling_law", "contact"), ("hysteresis", "0.7"), ("surface_energy_ice", "0.5"), ("xi_crit", "2e-10")],
        );
        let card = p.monomer_card().expect("card");
        assert_eq!(card.len(), MONOMER_KEYS.len());
        // Another scene takes this card whole.
        let mut q = SceneParams::default_for("stokes-number").expect("scene");
        assert!(q.set_monomer_card(&card), "{id}");
        assert_eq!(q.monomer_card(), Some(card));
    }
    // Scenes without aggregates have no card.
    assert!(SceneParams::default_for("hysteresis").and_then(|p| p.monomer_card()).is_none());
}

#[test]
fn the_surface_energy_reaches_the_porosity_track_the_column_and_the_batch_model() {
    let doubled = [("surface_energy_ice", "1.48")];
    type Case<'a> = (&'a str, &'a [(&'a str, &'a str)], &'a str);
    let cases: [Case; 3] = [
        ("porosity-track", &[], "phi_planetesimal"),
        (
            "mass-distribution",
            &[("t_end_yr", "2000"), ("runs", "1"), ("groups_per_decade", "10"), ("snapshots", "3"), ("radius_au", "2")],
            "phi_p",
        ),
        (
            "disk-map",
            &[("batches", "40"), ("duration_yr", "3e5"), ("disk_mass", "0.2"), ("metallicity", "0.05")],
            "converted",
        ),
    ];
    for (id, base, probe) in cases {
        let a = scene(id, base);
        let mut b = a.clone();
        for (k, v) in doubled {
            b.set(k, v).expect("set");
        }
        let (ea, eb) = (scalar(&a, "monomer_E_roll"), scalar(&b, "monomer_E_roll"));
        // The calibrated law scales as γ^{4/3}.
        assert!((eb / ea - 2f64.powf(4.0 / 3.0)).abs() < 1e-9, "{id}: {ea} → {eb}");
        let out_a = compute(&a, &Progress::default()).expect("a");
        let out_b = compute(&b, &Progress::default()).expect("b");
        let (pa, pb) = (out_a.scalar(probe), out_b.scalar(probe));
        let figures_differ = out_a.figures != out_b.figures;
        assert!(figures_differ || pa != pb, "{id}: the model did not see the change ({probe}: {pa:?} vs {pb:?})");
    }
}

#[test]
fn the_rolling_law_moves_the_formation_zone_of_fig_5_9() {
    let edge = |law: &str| scalar(&scene("scale-ladder", &[("rolling_law", law)]), "formation_edge");
    let calibrated = edge("calibrated");
    // Fig. 5.9: the 0.2 M☉, Z₀ = 0.05, R_c = 30 AU disk forms planetesimals out to ~20 AU.
    assert!((15.0..30.0).contains(&calibrated), "{calibrated}");
    for law in ["contact", "dominik-tielens"] {
        let e = edge(law);
        assert!((10.0..40.0).contains(&e) && e != calibrated, "{law}: {e} vs {calibrated}");
    }
    // The ladder's disk step is the batch model's own result.
    let map =
        scene("disk-map", &[("disk_mass", "0.2"), ("metallicity", "0.05"), ("batches", "500"), ("r_out_au", "300")]);
    assert_eq!(scalar(&map, "outermost_planetesimals"), calibrated);
}

#[test]
fn clicked_points_of_tracks_and_families_are_inspected() {
    let p = scene("growth-tracks", &[("tracks", "4")]);
    let out = compute(&p, &Progress::default()).expect("tracks");
    let fig = out.figures.iter().find(|f| f.id == "growth-tracks-mass").expect("figure");
    let point =
        fig.series.iter().find(|s| !s.points.is_empty()).map(|s| s.points[s.points.len() / 2]).expect("a track");
    let card = p.inspect(&out, &fig.id, point).expect("a point on a track is inspected");
    assert_eq!(card.point, point);
    assert!(card.rows.iter().any(|(k, _)| k == "Stokes number Ωt_s"));
    let column = &card.actions.first().expect("open the local column").open;
    assert_eq!(column.info().id, "mass-distribution");
    assert_eq!(column.monomer_card(), p.monomer_card());
    // Far from every track: nothing.
    assert!(p.inspect(&out, &fig.id, [1e4, 1e-30]).is_none());
}
