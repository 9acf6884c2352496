//! Scene-level checks: caching never changes results, outputs are complete.

use grainscope::physics::collision::{Options, Outcome, Setup, collide, sticking_velocity};
use grainscope::scene::{self, Caches, Progress, SCENES, SceneParams};

fn small_restitution() -> SceneParams {
    let mut p = SceneParams::default_for("restitution").expect("scene");
    for (k, v) in [("n_velocities", "24"), ("n_radii", "5"), ("n_t_vis", "2")] {
        p.set(k, v).expect("valid");
    }
    p
}

#[test]
fn cached_recomputation_equals_a_fresh_one() {
    let mut caches = Caches::default();
    let p1 = small_restitution();
    scene::compute_cached(&p1, &Progress::default(), &mut caches).expect("first");
    for (k, v) in [("v_min", "0.8"), ("velocity", "20"), ("t_vis_max", "1e-11"), ("t_vis", "3e-12")] {
        let mut p2 = p1.clone();
        p2.set(k, v).expect("valid");
        let cached = scene::compute_cached(&p2, &Progress::default(), &mut caches).expect("cached");
        let fresh = scene::compute(&p2, &Progress::default()).expect("fresh");
        assert_eq!(cached, fresh, "after changing {k}");
    }
}

#[test]
fn cancelled_computation_reports_cancellation() {
    let progress = Progress::default();
    progress.cancel();
    let err = scene::compute(&small_restitution(), &progress).expect_err("cancelled");
    assert!(matches!(err, scene::SceneError::Cancelled));
}

/// Every scene computed once at its defaults (the Monte Carlo scenes with
/// one short run), shared by the tests that need a scene's full result.
fn defaults() -> &'static std::collections::BTreeMap<&'static str, scene::SceneOutput> {
    static DEFAULTS: std::sync::OnceLock<std::collections::BTreeMap<&'static str, scene::SceneOutput>> =
        std::sync::OnceLock::new();
    DEFAULTS.get_or_init(|| {
        SCENES
            .iter()
            .map(|info| {
                let mut quick = SceneParams::default_for(info.id).expect("scene");
                // The Monte Carlo scenes run for minutes by default: one short run here.
                if quick.set("max_events_millions", "0.02").is_ok() {
                    quick.set("runs", "1").expect("runs");
                }
                (info.id, scene::compute(&quick, &Progress::default()).expect(info.id))
            })
            .collect()
    })
}

#[test]
fn every_scene_computes_with_defaults_and_documents_its_parameters() {
    for info in SCENES {
        let mut p = SceneParams::default_for(info.id).expect("scene");
        let out = &defaults()[info.id];
        assert!(!out.figures.is_empty() && !out.scalars.is_empty(), "{}", info.id);
        for fig in &out.figures {
            assert!(fig.series.iter().any(|s| !s.points.is_empty()), "{}: {}", info.id, fig.id);
        }
        for c in p.controls() {
            assert!(!c.doc.is_empty() && !c.label.is_empty(), "{}: {}", info.id, c.key);
            c.check().expect("defaults are valid");
        }
    }
}

#[test]
fn inverted_ranges_are_rejected() {
    let mut p = small_restitution();
    p.set("v_min", "50").expect("in range");
    p.set("v_max", "10").expect("in range");
    let err = scene::compute(&p, &Progress::default()).expect_err("inverted");
    assert!(err.to_string().contains("v_min"), "{err}");
}

#[test]
fn the_registry_lists_each_scene_once_under_its_own_id() {
    let mut ids: Vec<&str> = SCENES.iter().map(|s| s.id).collect();
    for id in &ids {
        let p = SceneParams::default_for(id).expect("registered");
        assert_eq!(p.info().id, *id);
    }
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), SCENES.len(), "duplicate scene ids");
}

/// Every object key of a JSON value, at any depth.
fn json_keys(v: &serde_json::Value, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                out.push(k.clone());
                json_keys(x, out);
            }
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| json_keys(x, out)),
        _ => {}
    }
}

#[test]
fn the_schema_reads_and_writes_every_parameter_in_place() {
    use grainscope::scene::DefaultValue;
    use grainscope::scene::schema::SpecKind;
    for info in SCENES {
        let mut p = SceneParams::default_for(info.id).expect("scene");
        let specs = p.specs();
        let mut keys = p.keys();
        // The window's controls are the schema's parameters, in its order.
        let controls: Vec<(&str, DefaultValue)> = p.controls().iter().map(|c| (c.key, c.value())).collect();
        assert_eq!(controls.iter().map(|c| c.0).collect::<Vec<_>>(), keys, "{}", info.id);
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), specs.len(), "{}: a key is declared twice", info.id);
        // Every key is a field that presets and links carry.
        let mut stored = Vec::new();
        json_keys(&serde_json::to_value(&p).expect("json"), &mut stored);
        for s in specs {
            assert!(stored.iter().any(|k| k == s.key), "{}: {} is no stored field", info.id, s.key);
            assert!(!s.doc.is_empty() && !s.label.is_empty(), "{}: {}", info.id, s.key);
            assert!(s.doc_line().contains("default"), "{}: {}", info.id, s.key);
            // get reads the field the control edits.
            let value = p.get(s.key).expect("a value");
            assert_eq!(controls.iter().find(|c| c.0 == s.key).map(|c| &c.1), Some(&value), "{}: {}", info.id, s.key);
            assert_eq!(s.default.as_ref(), Some(&value), "{}: {} at the default", info.id, s.key);
            // Typed set: the ends of the range are taken, a value beyond them
            // is refused and changes nothing.
            if let SpecKind::Number { min, max, .. } = s.kind {
                assert!(min.is_finite() && max.is_finite() && min < max, "{}: {} has no finite range", info.id, s.key);
                let mut q = p.clone();
                for x in [min, max] {
                    q.set_number(s.key, x).expect("in range");
                    assert_eq!(q.get(s.key), Some(DefaultValue::Number(x)), "{}: {}", info.id, s.key);
                }
                let before = q.clone();
                assert!(q.set_number(s.key, max * 2.0 + 1.0).is_err(), "{}: {}", info.id, s.key);
                assert!(q.set_number(s.key, f64::NAN).is_err(), "{}: {}", info.id, s.key);
                assert_eq!(q, before, "{}: {} changed on a refused value", info.id, s.key);
            }
            if let SpecKind::Count { min, max } = s.kind {
                let mut q = p.clone();
                q.set_number(s.key, max as f64).expect("in range");
                assert_eq!(q.get(s.key), Some(DefaultValue::Count(max)), "{}: {}", info.id, s.key);
                assert!(q.set_number(s.key, min as f64 + 0.5).is_err(), "{}: {} takes a fraction", info.id, s.key);
            }
        }
        assert_eq!(p.get("no_such_parameter"), None);
    }
}

#[test]
fn a_quantity_shared_by_scenes_is_declared_alike() {
    // The same key means the same quantity, declared once (scene::quantities):
    // same unit and valid range wherever it appears. These keys name different
    // quantities in different chapters, or the search grid of the fit:
    let distinct =
        ["velocity", "radius", "alpha", "gamma", "t_vis", "t_vis_min", "t_vis_max", "yield_strength", "r_min", "r_max"];
    let mut seen: std::collections::BTreeMap<&str, (String, String)> = Default::default();
    for info in SCENES {
        let mut p = SceneParams::default_for(info.id).expect("scene");
        for c in p.controls() {
            if distinct.contains(&c.key) {
                continue;
            }
            let range = match c.kind {
                grainscope::scene::ControlKind::Number { min, max, .. } => format!("{min:e}…{max:e}"),
                _ => continue,
            };
            let entry = seen.entry(c.key).or_insert_with(|| (c.si_unit.to_string(), range.clone()));
            assert_eq!(
                entry,
                &(c.si_unit.to_string(), range),
                "{}: {} differs from its other declarations",
                info.id,
                c.key
            );
        }
    }
}

/// The `batches` parameter of a batch scene.
fn batch_count(p: &SceneParams) -> usize {
    match p.get("batches") {
        Some(grainscope::scene::controls::DefaultValue::Count(n)) => n,
        other => panic!("batches: {other:?}"),
    }
}

#[test]
fn batch_scenes_preview_with_at_most_40_batches_and_draw_the_same_figures() {
    for id in ["surface-density", "batch-lifelines", "disk-map", "planetesimal-yield", "formation-zone", "scale-ladder"]
    {
        let p = SceneParams::default_for(id).expect("scene");
        let coarse = p.coarse().unwrap_or_else(|| panic!("{id} has no preview"));
        let batches = batch_count(&coarse);
        assert!(batches <= 40, "{id}: {batches} batches");
        let full_batches = batch_count(&p);
        assert!(full_batches > batches, "{id}: the preview is not cheaper");
        let out = scene::compute(&coarse, &Progress::default()).expect("preview");
        let ids = |o: &scene::SceneOutput| o.figures.iter().map(|f| f.id.clone()).collect::<Vec<_>>();
        assert_eq!(ids(&out), ids(&defaults()[id]), "{id}");
    }
    // The restitution scene previews with fewer radii, with the same figures.
    let p = SceneParams::default_for("restitution").expect("scene");
    let coarse = p.coarse().expect("restitution has a preview");
    assert_ne!(coarse, p, "the preview is the full computation");
    let ids = |o: &scene::SceneOutput| o.figures.iter().map(|f| f.id.clone()).collect::<Vec<_>>();
    let out = scene::compute(&coarse, &Progress::default()).expect("preview");
    assert_eq!(ids(&out), ids(&defaults()["restitution"]));
    // Capped kernel tests preview with the uncapped method.
    let mut k = SceneParams::default_for("kernel-tests").expect("scene");
    k.set("group_mass_cap", "1e-3").expect("valid");
    let coarse = k.coarse().expect("a capped kernel test has a preview");
    let SceneParams::KernelTests(c) = &coarse else { panic!("not a kernel test") };
    assert_eq!(c.group_mass_cap, 1.0);
    assert_eq!(ids(&scene::compute(&coarse, &Progress::default()).expect("preview")), ids(&defaults()["kernel-tests"]));
    // Light scenes have none.
    assert!(SceneParams::default_for("hysteresis").expect("scene").coarse().is_none());
}

#[test]
fn the_adaptive_restitution_curve_is_the_model_within_1e4() {
    // e(v) is drawn through adaptively placed collisions: at every velocity
    // of the grid it must be what the model gives there.
    let mut p = SceneParams::default_for("restitution").expect("scene");
    for (k, v) in [("n_radii", "2"), ("n_t_vis", "1")] {
        p.set(k, v).expect("valid");
    }
    let out = scene::compute(&p, &Progress::default()).expect("scene");
    let curve = &out.figures[0].series.iter().find(|s| s.name == "e (model)").expect("e(v)").points;
    assert_eq!(curve.len(), 200);
    let v_s = out.scalars.iter().find(|s| s.key == "v_stick").expect("v_s").value;
    let setup = Setup::reference_ice();
    let opts = Options::default();
    let mut bounced = 0;
    for &[v, e] in curve.iter().step_by(7) {
        let direct = collide(&setup, v, &opts).expect("collides");
        if direct.outcome == Outcome::Stick {
            assert!(v <= v_s * (1.0 + 1e-5) && e == 0.0, "v = {v}: sticks, drawn {e}, v_s = {v_s}");
        } else {
            bounced += 1;
            assert!((e - direct.e_adhesive).abs() <= 1e-4, "v = {v}: drawn {e}, model {}", direct.e_adhesive);
        }
    }
    assert!(bounced > 15, "{bounced}");
}

#[test]
fn the_sticking_velocity_panel_is_the_model_within_its_precision() {
    // Each v_s(R) curve is found from guesses along its radii at a looser
    // solver tolerance: every point must still be the model's v_s within the
    // panel's 10⁻³ (here against searches to 10⁻⁶ at the default tolerance).
    let mut p = SceneParams::default_for("restitution").expect("scene");
    for (k, v) in [("n_radii", "12"), ("n_t_vis", "3"), ("n_velocities", "20")] {
        p.set(k, v).expect("valid");
    }
    let out = scene::compute(&p, &Progress::default()).expect("scene");
    let fig = out.figures.iter().find(|f| f.id == "sticking-velocity").expect("v_s(R)");
    let mut checked = 0;
    for s in fig.series.iter().filter(|s| s.family.is_some()) {
        for &[r_um, v] in &s.points {
            // Equal spheres of reduced radius R: each of radius 2R.
            let mut c = grainscope::scene::collisions::restitution::Params::default().collision;
            c.radius_1 = 2.0 * r_um * 1e-6;
            c.radius_2 = c.radius_1;
            c.t_vis = s.family.expect("a T_vis");
            let tight = sticking_velocity(&c.setup(), &Options::default(), 1e-6).expect("v_s");
            if !tight.is_finite() {
                continue;
            }
            assert!((v / tight - 1.0).abs() <= 1e-3, "R = {r_um} µm, T_vis = {:?}: drawn {v}, model {tight}", s.family);
            checked += 1;
        }
    }
    assert!(checked >= 30, "{checked}");
}

/// The model data that inspecting a clicked point needs (a browser's page
/// receives it from its worker as bytes) reads back to the same inspections.
#[test]
fn inspected_model_data_survives_bytes() {
    let mut families = SceneParams::default_for("families").expect("scene");
    families.set("max_events_millions", "0.02").expect("events");
    families.set("runs", "1").expect("runs");
    let disk_map = SceneParams::default_for("disk-map").expect("scene").coarse().expect("preview");
    for p in [disk_map, families] {
        let out = scene::compute(&p, &Progress::default()).expect("computes");
        let text = ron::to_string(&out).expect("written");
        let back: scene::SceneOutput = ron::from_str(&text).expect("read back");
        let fig = &out.figures[0];
        let mut seen = 0;
        for s in fig.series.iter().filter(|s| !s.points.is_empty()).take(6) {
            let at = s.points[s.points.len() / 2];
            let here = p.inspect(&out, &fig.id, at);
            assert_eq!(here, p.inspect(&back, &fig.id, at), "{}", p.info().id);
            seen += usize::from(here.is_some());
        }
        assert!(seen > 0, "{}: nothing to inspect on {}", p.info().id, fig.id);
    }
}

/// "What matters" shared among 2 and 3 processes, as a browser shares its
/// points among its workers, ranks the parameters of the collision's
/// restitution coefficient exactly as one process does.
#[test]
fn what_matters_shared_among_processes_equals_the_undivided_ranking() {
    use grainscope::scene::parts::in_turns;
    use grainscope::sensitivity::what_matters;
    let params = grainscope::preset::resolve("ice-bounce-8ms").expect("shipped").scene;
    let whole = what_matters(&params, "e", 2.0, &Progress::default()).expect("ranks");
    assert!(whole.rows.len() > 5);
    for n in [2, 3] {
        let (shared, rounds) = in_turns(n, |p| what_matters(&params, "e", 2.0, p)).expect("ranks");
        assert!(rounds >= 2, "{n} processes: nothing was shared");
        assert_eq!(shared, whole, "{n} processes");
    }
}

/// A column's scalars say how many of its runs the event limit stopped, so
/// that a sweep or a script reading `run --json` sees a run that ended short
/// of its end time: both runs at 0.01 million events, neither with the end
/// time within reach; and the erosion balance counts the runs of its three
/// thresholds together.
#[test]
fn a_column_counts_its_runs_stopped_by_the_event_limit() {
    let limited = |millions: &str, t_end_yr: &str| {
        let mut p = SceneParams::default_for("mass-distribution").expect("scene");
        for (key, value) in
            [("runs", "2"), ("max_events_millions", millions), ("t_first_yr", "1"), ("t_end_yr", t_end_yr)]
        {
            p.set(key, value).expect(key);
        }
        let out = scene::compute(&p, &Progress::default()).expect("computes");
        let t_end = out.scalar("t_end").expect("t_end");
        (out.scalar("runs_at_event_limit").expect("scalar"), t_end / grainscope::physics::constants::YEAR)
    };
    let (stopped, reached) = limited("0.01", "10000");
    assert_eq!(stopped, 2.0);
    assert!(reached < 1e4, "{reached} yr");
    let (stopped, reached) = limited("1", "10");
    assert_eq!(stopped, 0.0);
    assert!((reached - 10.0).abs() < 0.1, "{reached} yr");
    // The erosion balance counts the runs of its three thresholds together.
    let mut p = SceneParams::default_for("erosion-balance").expect("scene");
    for (key, value) in [("runs", "1"), ("max_events_millions", "0.01")] {
        p.set(key, value).expect(key);
    }
    let out = scene::compute(&p, &Progress::default()).expect("computes");
    assert_eq!(out.scalar("runs_at_event_limit"), Some(3.0));
}
