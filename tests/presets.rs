//! Presets: every shipped preset loads, runs headless and round-trips; bad
//! presets and values give errors that name the problem.

use grainscope::preset::{Preset, PresetError, SHIPPED, resolve};
use grainscope::scene::{self, ParamError, Progress, SceneParams};

#[test]
fn shipped_presets_match_the_presets_folder() {
    let mut on_disk: Vec<String> = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/presets"))
        .expect("presets folder")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".ron"))
        .collect();
    on_disk.sort();
    let mut shipped: Vec<String> = SHIPPED.iter().map(|(f, _)| f.to_string()).collect();
    shipped.sort();
    assert_eq!(on_disk, shipped);
}

#[test]
fn every_shipped_preset_loads_runs_round_trips_and_has_glyphs_for_every_label() {
    use skrifa::MetadataProvider;
    let font = skrifa::FontRef::new(grainscope::figure::font_ttf()).expect("bundled font");
    let charmap = font.charmap();
    let mut missing = std::collections::BTreeSet::new();
    let dir = tempfile::tempdir().expect("tempdir");
    for (file, text) in SHIPPED {
        let preset = Preset::from_ron(text, file).unwrap_or_else(|e| panic!("{file}: {e}"));
        // Monte Carlo presets run for minutes: here one run with capped events
        // (CI runs them in full with the release binary).
        let mut quick = preset.scene.clone();
        if file.starts_with("mc-fig") {
            quick.set("runs", "1").expect("runs");
            quick.set("max_events_millions", "0.02").expect("event cap");
        }
        if file.ends_with("-capped.ron") {
            // Capped kernel tests take seconds per run: one run here.
            quick.set("runs", "1").expect("runs");
        }
        // The other heavy scenes run at their preview's setting (fewer
        // batches, a coarser grid): `.ci/run` runs every preset at its full
        // size with the release binary, and `reproduce` checks their numbers.
        if quick.info().heavy && !file.starts_with("mc-") {
            quick = quick.coarse().unwrap_or(quick);
        }
        let out = scene::compute(&quick, &Progress::default()).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert!(!out.figures.is_empty(), "{file}");
        // The browser's workers send results to the page as RON
        // (web/src/wire.rs): every number reads back to the same bits.
        let wire = ron::to_string(&out).unwrap_or_else(|e| panic!("{file}: {e}"));
        let back: scene::SceneOutput = ron::from_str(&wire).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(ron::to_string(&back).expect("again"), wire, "{file}");
        let bits = |o: &scene::SceneOutput| -> Vec<u64> {
            o.scalars
                .iter()
                .map(|s| s.value.to_bits())
                .chain(
                    o.figures
                        .iter()
                        .flat_map(|f| f.series.iter().flat_map(|s| s.points.iter().flatten().map(|x| x.to_bits()))),
                )
                .collect()
        };
        assert_eq!(bits(&back), bits(&out), "{file}: the wire changed a number");
        // Every character of every label must exist in the bundled font,
        // which draws the exported files and the window's text.
        for fig in &out.figures {
            let mut texts = vec![fig.title.clone(), fig.x.title(), fig.y.title()];
            texts.extend(fig.series.iter().map(|s| s.name.clone()));
            texts.extend(fig.family.iter().map(|f| f.title()));
            if let Some(h) = &fig.heatmap {
                texts.push(h.title());
                texts.extend(h.categories.iter().cloned());
            }
            let svg = grainscope::figure::svg_string(fig, (800, 550)).expect("svg");
            texts.extend(
                svg.split("<text").skip(1).filter_map(|t| Some(t.split_once('>')?.1.split('<').next()?.to_string())),
            );
            for c in texts.iter().flat_map(|t| t.chars()).filter(|c| !c.is_control()) {
                if charmap.map(c).is_none_or(|g| g.to_u32() == 0) {
                    missing.insert(format!("{c} (U+{:04X}) in {file}, figure {}", c as u32, fig.id));
                }
            }
        }
        // A non-finite result is a declared bound or a declared undefined
        // value, never a silent gap.
        for s in &out.scalars {
            let status = grainscope::scene::status(quick.censored(), s.key, s.value);
            assert!(status.why() != "not a finite number", "{file}: {} = {} has no declared meaning", s.key, s.value);
        }
        // An exported figure carries the preset: it reads back equal, and a
        // cheap scene recomputed from a PNG gives the same JSON (CI checks
        // every preset through the command line).
        let run = Preset { scene: quick.clone(), ..preset.clone() };
        let stamp = grainscope::provenance::Stamp::of(&run).expect("stamp");
        let cheap = !quick.info().heavy;
        let ext = if cheap { "png" } else { "svg" };
        let bytes =
            grainscope::provenance::figure_bytes(&out.figures[0], ext, (400, 275), Some(&stamp)).expect("bytes");
        let exported = dir.path().join(format!("{file}.{ext}"));
        std::fs::write(&exported, bytes).expect("write");
        let reopened = resolve(exported.to_str().expect("utf8")).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(reopened, run, "{file}: the exported state");
        if cheap {
            let again = scene::compute(&reopened.scene, &Progress::default()).expect("recomputes");
            assert_eq!(again.scalars_json(&[]), out.scalars_json(&[]), "{file}: the same results from the PNG");
        }
        let path = dir.path().join(file);
        preset.save(&path).expect("save");
        let back = Preset::load(&path).expect("load");
        assert_eq!(back, preset, "{file} round trip");
    }
    assert!(missing.is_empty(), "characters without a glyph in the bundled font: {missing:#?}");
}

#[test]
fn required_presets_reproduce_their_stories() {
    let e = |name: &str| {
        let p = resolve(name).expect(name);
        scene::compute(&p.scene, &Progress::default()).expect(name)
    };
    let bounce = e("ice-bounce-8ms");
    assert!((bounce.scalar("e").expect("e") - 0.66).abs() <= 0.02);
    assert_eq!(e("ice-stick-2ms").scalar("sticks"), Some(1.0));
    assert!((e("ice-quasistatic").scalar("e").expect("e") - 0.93).abs() <= 0.02);
    let r = e("restitution-ice");
    assert!(r.scalar("v_stick").expect("v_stick") > r.scalar("v_c").expect("v_c"));
}

#[test]
fn old_presets_with_missing_fields_load_with_defaults() {
    let p = Preset::from_ron("(scene: Hysteresis((collision: (velocity: 3.0))))", "<text>").expect("loads");
    match p.scene {
        SceneParams::Hysteresis(h) => {
            assert_eq!(h.collision.velocity, 3.0);
            assert_eq!(h.collision.t_vis, 1e-11);
        }
        other => panic!("wrong scene {other:?}"),
    }
}

/// A short disk map written as a preset whose batch run starts with `keys`
/// (each followed by ", "): its parameters and its figures as text.
fn disk_map_run(keys: &str) -> (SceneParams, String) {
    let text = format!("(scene: DiskMap((run: ({keys}disk: (metallicity: 0.05, alpha: 1e-5), duration_yr: 3e4))))");
    let p = Preset::from_ron(&text, "<text>").expect("loads");
    let out = scene::compute(&p.scene, &Progress::default()).expect("runs");
    (p.scene, format!("{:?}", out.figures))
}

/// A batch preset written before the `settling` key existed ran with
/// differential settling among the relative velocities: it keeps it, while a
/// new scene uses App. 5.B's midplane velocities.
#[test]
fn batch_presets_without_the_settling_key_keep_the_velocities_they_were_written_with() {
    let run = |settling: &str| disk_map_run(&format!("{settling}batches: 30, "));
    let (old, old_out) = run("");
    let (with, with_out) = run("settling: true, ");
    let (without, without_out) = run("settling: false, ");
    assert_eq!(old, with, "a preset without the key reads as settling: true");
    assert_eq!(old_out, with_out, "and gives the same results");
    assert_ne!(with_out, without_out, "settling changes the run");
    let fresh = SceneParams::default_for("disk-map").expect("the disk map scene");
    let ron = ron::to_string(&fresh).expect("serialises");
    assert!(ron.contains("settling:false"), "a new scene uses the midplane velocities and says so: {ron}");
    assert_ne!(without, old);
}

/// A batch preset written before the `surface_density` key existed read Σ_d
/// from neighbour annuli with 250 batches by default: it keeps both, while a
/// new scene uses the kernel estimate and 500 batches.
#[test]
fn batch_presets_without_the_surface_density_key_keep_the_annuli_and_their_batch_count() {
    let run = |keys: &str| disk_map_run(&format!("settling: false, {keys}"));
    let (old, old_out) = run("");
    let (annuli, annuli_out) = run("surface_density: \"annuli\", batches: 250, ");
    let (_, kernel_out) = run("surface_density: \"kernel\", batches: 250, ");
    assert_eq!(old, annuli, "a preset without the keys reads as the annuli and 250 batches");
    assert_eq!(old_out, annuli_out, "and gives the same results");
    assert_ne!(annuli_out, kernel_out, "the estimate changes the run");
    let fresh = SceneParams::default_for("disk-map").expect("the disk map scene");
    let ron = ron::to_string(&fresh).expect("serialises");
    assert!(ron.contains("surface_density:\"kernel\"") && ron.contains("batches:500"), "{ron}");
}

#[test]
fn unknown_keys_are_reported_with_their_location() {
    let text = "(\n    scene: Hysteresis((\n        collision: (velocty: 3.0),\n    )),\n)";
    match Preset::from_ron(text, "bad.ron") {
        Err(PresetError::Syntax { line, message, .. }) => {
            assert_eq!(line, 3, "{message}");
            assert!(message.contains("velocty"), "{message}");
        }
        other => panic!("expected a syntax error, got {other:?}"),
    }
}

#[test]
fn malformed_and_out_of_range_presets_are_errors_not_panics() {
    let cases = [
        "",
        "(",
        "(scene: Nonsense(()))",
        "(scene: Hysteresis((collision: (velocity: \"fast\"))))",
        "(scene: Hysteresis((collision: (velocity: -1.0))))",
        "(scene: Hysteresis((collision: (t_vis: 1.0))))",
        "(scene: Restitution((n_velocities: 0)))",
        "(scene: Adhesion((radius: inf)))",
        "(scene: Hysteresis((collision: (projectile: (name: \"x\", youngs_modulus: -1.0, poisson_ratio: 0.3, density: 1.0, surface_energy: 1.0)))))",
    ];
    for text in cases {
        let err = Preset::from_ron(text, "case.ron").expect_err(text);
        let message = err.to_string();
        assert!(message.starts_with("case.ron"), "{text}: {message}");
    }
}

#[test]
fn set_names_bad_keys_and_values_and_changes_nothing() {
    let mut p = SceneParams::default_for("hysteresis").expect("scene");
    let before = p.clone();
    assert!(matches!(p.set("nope", "1"), Err(ParamError::UnknownKey { .. })));
    assert!(matches!(p.set("velocity", "abc"), Err(ParamError::Parse { .. })));
    assert!(matches!(p.set("velocity", "1e9"), Err(ParamError::OutOfRange { .. })));
    assert!(matches!(p.set("velocity", "NaN"), Err(ParamError::OutOfRange { .. })));
    assert_eq!(p, before);
    p.set("velocity", "4").expect("valid");
    p.set("projectile", "PSL").expect("material");
    assert_ne!(p, before);
}

#[test]
fn saving_to_an_unwritable_path_fails_and_keeps_the_old_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let preset = resolve("ice-bounce-8ms").expect("preset");
    let err = preset.save(&dir.path().join("missing-folder/x.ron")).expect_err("unwritable");
    assert!(err.to_string().contains("missing-folder"), "{err}");
    // An existing file is replaced only by a complete new one.
    let path = dir.path().join("keep.ron");
    std::fs::write(&path, "old").expect("write");
    preset.save(&path).expect("save");
    assert!(Preset::load(&path).is_ok());
}

/// The browser's font (`assets/fonts/DejaVuSans-web.ttf`, a subset of the
/// bundled DejaVu Sans) holds every character the sources, the presets and
/// the decks use: the explorer's labels, the figures' titles and units.
#[test]
fn the_browsers_font_has_every_character_the_sources_use() {
    use skrifa::MetadataProvider;
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let bytes = std::fs::read(root.join("assets/fonts/DejaVuSans-web.ttf")).expect("the browser's font");
    let font = skrifa::FontRef::new(&bytes).expect("a font");
    let charmap = font.charmap();
    let mut texts = Vec::new();
    let mut dirs = vec![root.join("src"), root.join("presets"), root.join("web/src")];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).expect("a folder").filter_map(Result::ok) {
            let path = entry.path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs" || e == "ron") {
                texts.push((path.clone(), std::fs::read_to_string(&path).expect("text")));
            }
        }
    }
    assert!(texts.len() > 50, "{} files", texts.len());
    let mut missing = std::collections::BTreeSet::new();
    for (path, text) in &texts {
        for c in text.chars().filter(|c| !c.is_control()) {
            if charmap.map(c).is_none() {
                missing.insert((c, path.strip_prefix(root).unwrap_or(path).display().to_string()));
            }
        }
    }
    assert!(missing.is_empty(), "characters without a glyph in the browser's font: {missing:?}");
}
