//! The command line, end to end.

use std::process::Command;

fn grainscope(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_grainscope")).args(args).output().expect("runs")
}

#[test]
fn run_json_prints_the_scalars() {
    let out = grainscope(&["run", "ice-bounce-8ms", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    let e = v["e"].as_f64().expect("e");
    assert!((e - 0.66).abs() <= 0.02);
    assert!(v["t_c"].as_f64().expect("t_c") > 0.0);
}

#[test]
fn set_overrides_a_parameter() {
    let out = grainscope(&["run", "ice-bounce-8ms", "--set", "velocity=2", "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(v["sticks"].as_f64(), Some(1.0));
}

#[test]
fn out_writes_csv_svg_png() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path().to_str().expect("utf8");
    let out = grainscope(&["run", "presets/adhesion-ice-monomers.ron", "--out", d]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for f in ["collision-regimes.csv", "collision-regimes.svg", "collision-regimes.png", "scalars.json", "preset.ron"] {
        assert!(dir.path().join(f).exists(), "{f}");
    }
    // The folder names the build that made it, and its preset computes it again.
    let preset = std::fs::read_to_string(dir.path().join("preset.ron")).expect("preset.ron");
    let first = preset.lines().next().expect("a line");
    assert!(first.starts_with("// computed by grainscope ") && first.contains("(commit "), "{first}");
    let again = grainscope(&["run", dir.path().join("preset.ron").to_str().expect("utf8"), "--json"]);
    let before = std::fs::read_to_string(dir.path().join("scalars.json")).expect("scalars");
    let a: serde_json::Value = serde_json::from_slice(&again.stdout).expect("json");
    let b: serde_json::Value = serde_json::from_str(&before).expect("json");
    assert_eq!(a, b);
}

#[test]
fn preset_only_prints_the_state_a_figure_reopens() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path().to_str().expect("utf8");
    let out = grainscope(&["run", "ice-bounce-8ms", "--set", "velocity=3", "--out", d]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let from_preset = grainscope(&["run", "ice-bounce-8ms", "--set", "velocity=3", "--preset-only"]);
    let png = dir.path().join("contact-radius.png");
    let from_png = grainscope(&["run", png.to_str().expect("utf8"), "--preset-only"]);
    assert!(from_png.status.success(), "{}", String::from_utf8_lossy(&from_png.stderr));
    assert_eq!(from_png.stdout, from_preset.stdout);
    let text = String::from_utf8_lossy(&from_png.stdout);
    assert!(text.contains("velocity: 3.0"), "{text}");
    // Without --set the state differs: the check can fail.
    let plain = grainscope(&["run", "ice-bounce-8ms", "--preset-only"]);
    assert_ne!(plain.stdout, from_png.stdout);
    // It computes nothing, so it does not combine with the outputs of a run.
    assert!(!grainscope(&["run", "ice-bounce-8ms", "--preset-only", "--json"]).status.success());
}

#[test]
fn bad_input_exits_non_zero_with_a_message() {
    for args in [
        vec!["run", "no-such-preset"],
        vec!["run", "ice-bounce-8ms", "--set", "velocity=-3"],
        vec!["run", "ice-bounce-8ms", "--set", "velocity"],
        vec!["run", "ice-bounce-8ms", "--set", "colour=red"],
        vec!["params", "nope"],
        vec!["frobnicate"],
    ] {
        let out = grainscope(&args);
        assert!(!out.status.success(), "{args:?}");
        assert!(!out.stderr.is_empty(), "{args:?}");
    }
}

/// Runs a command whose standard output is a pipe nobody reads (the reader
/// closed before the command writes, as `| head -1` does once it has its line).
fn grainscope_into_closed_pipe(args: &[&str]) -> std::process::Output {
    let (reader, writer) = std::io::pipe().expect("pipe");
    drop(reader);
    Command::new(env!("CARGO_BIN_EXE_grainscope"))
        .args(args)
        .stdout(writer)
        .stderr(std::process::Stdio::piped())
        .output()
        .expect("runs")
}

#[test]
fn a_closed_pipe_ends_every_command_quietly() {
    let dir = tempfile::tempdir().expect("tempdir");
    let data = dir.path().join("data.csv");
    std::fs::write(&data, "velocity [m/s],restitution\n5,0.7\n10,0.75\n20,0.77\n40,0.7\n").expect("write");
    let data = data.to_str().expect("utf8");
    for args in [
        vec!["presets"],
        vec!["params", "restitution"],
        vec!["run", "ice-bounce-8ms"],
        vec!["run", "ice-bounce-8ms", "--json"],
        vec!["fit", data, "--materials", "AF,mica", "--geometry", "wall", "--radius", "2.45e-6", "--grid", "4"],
        vec!["--help"],
        vec!["--version"],
    ] {
        let out = grainscope_into_closed_pipe(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!stderr.contains("panicked") && !stderr.contains("Broken pipe"), "{args:?}: {stderr}");
        assert!(out.status.success(), "{args:?}: {:?} {stderr}", out.status);
    }
}

#[test]
fn errors_are_said_once_with_the_value_as_written() {
    let out = grainscope(&["run", "no-such-preset"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.matches("no such file").count(), 1, "{stderr}");
    let out = grainscope(&["run", "ice-bounce-8ms", "--set", "velocity=-0.5e-0"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("velocity = -0.5e-0 is outside its valid range"), "{stderr}");
    let dir = tempfile::tempdir().expect("tempdir");
    let preset = dir.path().join("bad.ron");
    std::fs::write(&preset, "(scene: Hysteresis((collision: (velocity: -1e0))))").expect("write");
    let out = grainscope(&["run", preset.to_str().expect("utf8")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.matches("is outside its valid range").count(), 1, "{stderr}");
    assert!(stderr.contains("bad.ron:1:43: velocity = -1e0 is outside its valid range"), "{stderr}");
}

#[test]
fn an_under_determined_fit_warns_and_reports_no_range() {
    let dir = tempfile::tempdir().expect("tempdir");
    let data = dir.path().join("one.csv");
    std::fs::write(&data, "velocity [m/s],restitution\n10,0.7\n").expect("write");
    let args = ["fit", data.to_str().expect("utf8"), "--materials", "AF,mica", "--geometry", "wall"];
    let out = grainscope(&[&args[..], &["--radius", "2.45e-6", "--grid", "4", "--json"]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("under-determined fit: 1 measurement for 3 free parameters"), "{stderr}");
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    for key in ["gamma", "t_vis", "yield_strength"] {
        assert_eq!(v[key]["kind"], "undetermined", "{key}: {v}");
        assert!(v[key]["low"].is_null() && v[key]["high"].is_null(), "{key}: {v}");
    }
    assert!(v["warning"].as_str().is_some_and(|w| w.contains("under-determined")));
}

#[test]
fn presets_and_params_list() {
    let out = grainscope(&["presets"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("ice-bounce-8ms.ron"));
    let out = grainscope(&["params", "restitution"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("t_vis"));
}

#[test]
fn reproduce_writes_the_table() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path().to_str().expect("utf8");
    // Chapters 2, 3 and 6 take seconds; `.ci/run` runs every chapter with
    // the Monte Carlo rows and checks that every figure has its row.
    let out = grainscope(&["reproduce", "--quick", "--without-monte-carlo", "--chapters", "2,3,6", "--out", d]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let md = std::fs::read_to_string(dir.path().join("reproduce.md")).expect("md");
    assert!(md.contains("| Fig. 2.2 |"));
    assert!(!md.contains("| FAIL |"));
    // Every figure of these chapters that a scene draws has a row (all but the schematic 2.1).
    for figure in ["Fig. 2.4 ", "Fig. 2.6 ", "Fig. 2.11 ", "Fig. 3.1 ", "Fig. 6.3 "] {
        assert!(md.contains(&format!("| {figure}")), "no row for {figure}");
    }
    for other in ["| Fig. 4.", "| Fig. 5.", "| Sect. 4.", "| Sect. 5."] {
        assert!(!md.contains(other), "a row of a chapter not asked for: {other}");
    }
    let summary = md.lines().last().expect("summary line");
    assert!(summary.contains("figures checked"), "{summary}");
    assert!(dir.path().join("reproduce.csv").exists());
    assert!(dir.path().join("restitution-ice/restitution-velocity.png").exists());
    assert!(dir.path().join("experiments-fig-2-11/fig-2-11-wall-mica.svg").exists());
    assert!(dir.path().join("material-parameters/yield-length.csv").exists());
    assert!(dir.path().join("debris-fig-6-3").exists());
    assert!(!dir.path().join("batch-fig-5-9").exists());
    let out = grainscope(&["reproduce", "--chapters", "7", "--out", d]);
    assert!(!out.status.success());
}

#[test]
fn fit_command_recovers_the_synthetic_parameters() {
    let out = grainscope(&[
        "fit",
        "assets/examples/wall-mica-synthetic.csv",
        "--materials",
        "AF,mica",
        "--geometry",
        "wall",
        "--radius",
        "2.45e-6",
        "--grid",
        "10",
        "--json",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    // Truth of the synthetic data: the Wall et al. mica fit of Table 2.3.
    for (key, truth) in [("gamma", 0.13), ("t_vis", 9.79e-11), ("yield_strength", 1.92e8)] {
        let lo = v[key]["low"].as_f64().expect("low");
        let hi = v[key]["high"].as_f64().expect("high");
        assert!(lo <= truth * 1.1 && truth * 0.9 <= hi, "{key}: {truth} vs [{lo}, {hi}]");
    }
}

#[test]
fn fit_command_rejects_malformed_data_with_the_line() {
    let dir = tempfile::tempdir().expect("tempdir");
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "velocity [m/s],restitution\n3,0.5\n4,oops\n").expect("write");
    let out = grainscope(&[
        "fit",
        bad.to_str().expect("utf8"),
        "--materials",
        "AF,mica",
        "--geometry",
        "wall",
        "--radius",
        "2e-6",
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 3") && err.contains("oops"), "{err}");
    let out = grainscope(&[
        "fit",
        bad.to_str().expect("utf8"),
        "--materials",
        "unobtainium",
        "--geometry",
        "wall",
        "--radius",
        "2e-6",
    ]);
    assert!(!out.status.success());
}

/// A figure written by `run --out` reopens its state: `run FIGURE.png
/// --json` prints what the preset printed, for each kind of file.
#[test]
fn an_exported_figure_runs_as_its_preset() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path().to_str().expect("utf8");
    let first = grainscope(&["run", "ice-bounce-8ms", "--set", "velocity=3", "--out", d, "--json"]);
    assert!(first.status.success(), "{}", String::from_utf8_lossy(&first.stderr));
    for file in ["energy-budget.png", "contact-radius.svg", "elastic-force.csv"] {
        let path = dir.path().join(file);
        let again = grainscope(&["run", path.to_str().expect("utf8"), "--json"]);
        assert!(again.status.success(), "{file}: {}", String::from_utf8_lossy(&again.stderr));
        assert_eq!(again.stdout, first.stdout, "{file}");
    }
    let plain = dir.path().join("plain.png");
    std::fs::write(&plain, b"not an image").expect("write");
    let refused = grainscope(&["run", plain.to_str().expect("utf8"), "--json"]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("carries no grainscope state"));
}

/// A deck's handout: one folder per slide with its figures, each carrying
/// the slide's state, and an index with every title and note.
#[test]
fn a_deck_handout_lists_every_slide() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = dir.path().to_str().expect("utf8");
    let out = grainscope(&["deck", "sticking-and-rolling", "--out", d]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let deck = grainscope::deck::resolve("sticking-and-rolling").expect("shipped deck");
    let index = std::fs::read_to_string(dir.path().join("index.md")).expect("index");
    for (i, (slide, params)) in deck.deck.slides.iter().zip(&deck.params).enumerate() {
        assert!(index.contains(&slide.title), "{}", slide.title);
        assert!(index.contains(slide.notes.lines().next().unwrap_or_default()));
        let folder = dir.path().join(grainscope::deck::slide_folder(i, slide));
        let png = std::fs::read_dir(&folder)
            .expect("slide folder")
            .filter_map(|e| e.ok())
            .map(|e| e.path())
            .find(|p| p.extension().is_some_and(|e| e == "png"))
            .expect("a figure");
        assert_eq!(&grainscope::preset::read_embedded(&png).expect("state").scene, params, "{}", slide.title);
    }
    let movie = grainscope(&["movie", "restitution-ice", "--out", d]);
    assert_eq!(movie.status.code(), Some(2), "a scene without time has no movie");
    assert!(String::from_utf8_lossy(&movie.stderr).contains("no time to play"));
}

#[test]
fn a_sweep_resumes_and_its_shards_merge_into_the_same_bytes() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |name: &str| dir.path().join(name).to_str().expect("utf8").to_string();
    let sweep = |out: &str, shard: &str| {
        grainscope(&[
            "sweep",
            "ice-bounce-8ms",
            "--vary",
            "surface_energy=log:0.1:1:6",
            "--vary",
            "velocity=lin:2:20:3",
            "--scalars",
            "e,e_D",
            "--shard",
            shard,
            "--out",
            out,
        ])
    };
    let whole = sweep(&d("whole"), "1/1");
    assert!(whole.status.success(), "{}", String::from_utf8_lossy(&whole.stderr));
    let table = std::fs::read_to_string(dir.path().join("whole/sweep.csv")).expect("table");
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(lines[0], "point,surface_energy [J m^-2],velocity [m s^-1],e,e_D,error");
    assert_eq!(lines.len(), 1 + 18);
    // e at (γ, v) is the `run` result there.
    let one = grainscope(&["run", "ice-bounce-8ms", "--set", "surface_energy=1", "--set", "velocity=20", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&one.stdout).expect("json");
    let last: Vec<&str> = lines[18].split(',').collect();
    assert_eq!(last[3].parse::<f64>().ok(), v["e"].as_f64(), "{}", lines[18]);
    for path in ["whole/sweep.png", "whole/sweep.svg", "whole/sweep.ron"] {
        assert!(dir.path().join(path).exists(), "{path}");
    }
    // Shards, merged: the same bytes.
    for k in 1..=3 {
        let out = sweep(&d(&format!("shard{k}")), &format!("{k}/3"));
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let merged = grainscope(&["sweep-merge", &d("shard1"), &d("shard2"), &d("shard3"), "--out", &d("merged")]);
    assert!(merged.status.success(), "{}", String::from_utf8_lossy(&merged.stderr));
    for f in ["sweep.csv", "sweep.ron"] {
        assert_eq!(
            std::fs::read(dir.path().join("merged").join(f)).ok(),
            std::fs::read(dir.path().join("whole").join(f)).ok(),
            "{f}"
        );
    }
    // A shard missing: refused, naming what is missing.
    let short = grainscope(&["sweep-merge", &d("shard1"), &d("shard2"), "--out", &d("short")]);
    assert!(!short.status.success());
    assert!(String::from_utf8_lossy(&short.stderr).contains("in no shard"));
    // A run cut short: the rows it appended are reused, a torn line is not.
    let resumed = dir.path().join("resumed");
    std::fs::create_dir_all(&resumed).expect("dir");
    std::fs::copy(dir.path().join("whole/sweep.ron"), resumed.join("sweep.ron")).expect("copy");
    let partial = format!("{}\n{}\n{}\n{}\n{}", lines[0], lines[1], lines[5], lines[9], &lines[12][..6]);
    std::fs::write(resumed.join("sweep.partial.csv"), partial).expect("write");
    let again = sweep(resumed.to_str().expect("utf8"), "1/1");
    assert!(again.status.success(), "{}", String::from_utf8_lossy(&again.stderr));
    assert!(String::from_utf8_lossy(&again.stdout).contains("(3 already done, 0 failed)"));
    assert_eq!(std::fs::read_to_string(resumed.join("sweep.csv")).expect("table"), table);
    assert!(!resumed.join("sweep.partial.csv").exists());
    // Another sweep into the same folder is refused; a bad range names itself.
    let other = grainscope(&["sweep", "ice-bounce-8ms", "--vary", "velocity=lin:2:20:4", "--out", &d("whole")]);
    assert!(!other.status.success());
    let bad = grainscope(&["sweep", "ice-bounce-8ms", "--vary", "speed=lin:2:20:4", "--out", &d("bad")]);
    assert!(String::from_utf8_lossy(&bad.stderr).contains("no parameter 'speed'"));
}

#[test]
fn matters_reports_the_jkr_exponent_of_the_sticking_velocity() {
    let out = grainscope(&["matters", "ice-bounce-8ms", "--output", "v_c", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    let first = &v["parameters"][0];
    assert_eq!(first["key"], "surface_energy");
    assert!((first["elasticity"].as_f64().expect("number") - 5.0 / 6.0).abs() < 1e-6, "{first}");
    let bad = grainscope(&["matters", "ice-bounce-8ms", "--output", "nothing"]);
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("no scalar 'nothing'"));
    let bad = grainscope(&["matters", "ice-bounce-8ms", "--output", "v_c", "--factor", "0.5"]);
    assert!(!bad.status.success());
}

#[test]
fn matters_reports_the_numerical_resolution_apart_from_the_physics() {
    let out = grainscope(&["matters", "restitution-ice", "--output", "v_stick", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    let rows = v["parameters"].as_array().expect("rows");
    let numerical: Vec<bool> = rows.iter().map(|r| r["numerical"].as_bool().expect("flag")).collect();
    let keys: Vec<&str> = rows.iter().map(|r| r["key"].as_str().expect("key")).collect();
    let at = |key: &str| keys.iter().position(|k| *k == key).unwrap_or_else(|| panic!("no row {key}: {keys:?}"));
    assert!(numerical[at("rtol")] && !numerical[at("surface_energy")] && !numerical[at("t_vis")], "{keys:?}");
    // Every physical parameter comes before every numerical one.
    assert!(numerical.windows(2).all(|w| w[0] <= w[1]), "{keys:?} {numerical:?}");
    let text = grainscope(&["matters", "restitution-ice", "--output", "v_stick"]);
    let text = String::from_utf8_lossy(&text.stdout);
    let heading = text.find("numerical resolution").expect("the heading");
    assert!(
        heading < text.find("\nrtol").expect("rtol's row") && heading > text.find("\nt_vis").expect("a row"),
        "{text}"
    );
    // A count that sets the resolution shows the result at half and twice
    // it (here the rocking frequency at 200 and 800 steps a period, equal to
    // 10⁻⁹: converged), with no elasticity.
    let out = grainscope(&["matters", "rolling-psl-aluminium-rocking", "--output", "f_measured", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    let rows = v["parameters"].as_array().expect("rows");
    let steps = rows.iter().find(|r| r["key"] == "steps_per_period").expect("the steps' row");
    assert!(steps["numerical"].as_bool().expect("flag") && steps["elasticity"].is_null(), "{steps}");
    let here = v["value"].as_f64().expect("value");
    for end in ["low", "high"] {
        let x = steps[end].as_f64().expect("an end");
        assert!(x != here && ((x - here) / here).abs() < 1e-8, "{end}: {x} against {here}");
    }
}

#[test]
fn audit_passes_a_light_preset_and_fails_the_thesis_crack_law_with_status_1() {
    let out = grainscope(&["audit", "ice-bounce-8ms", "--points", "8"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("hysteresis") && text.contains("declared: a threshold"), "{text}");

    let out = grainscope(&["audit", "restitution-ice", "--only", "k", "--set", "crack_law=thesis"]);
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("FAIL step      v_stick along k"), "{text}");
    assert!(String::from_utf8_lossy(&out.stderr).contains("the audit fails for 1 of 1 presets"));

    let out = grainscope(&["audit", "restitution-ice", "--only", "kk"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("'kk'"));
}

#[test]
fn a_sensitivity_design_runs_in_shards_merges_and_analyses_to_the_same_indices() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |name: &str| dir.path().join(name).to_str().expect("utf8").to_string();
    let design = |out: &str, shard: &str| {
        grainscope(&[
            "sensitivity",
            "ice-bounce-8ms",
            "--method",
            "sobol",
            "--samples",
            "16",
            "--vary",
            "velocity=log:3:30",
            "--vary",
            "radius_1=log:1e-6:4e-6",
            "--tie",
            "radius_2=radius_1",
            "--output",
            "e",
            "--shard",
            shard,
            "--out",
            out,
        ])
    };
    let whole = design(&d("whole"), "1/1");
    assert!(whole.status.success(), "{}", String::from_utf8_lossy(&whole.stderr));
    let text = String::from_utf8_lossy(&whole.stdout).to_string();
    assert!(text.contains("parameter,S1,S1_conf,ST,ST_conf"), "{text}");
    assert!(String::from_utf8_lossy(&whole.stderr).contains("64 runs"));
    for k in ["1", "2"] {
        let out = design(&d(&format!("shard{k}")), &format!("{k}/2"));
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        assert!(!dir.path().join(format!("shard{k}/indices.csv")).exists(), "a shard is not analysed alone");
    }
    let merged = grainscope(&["sweep-merge", &d("shard1"), &d("shard2"), "--out", &d("merged")]);
    assert!(merged.status.success(), "{}", String::from_utf8_lossy(&merged.stderr));
    let analysed = grainscope(&["sensitivity", "--analyse", &d("merged")]);
    assert!(analysed.status.success(), "{}", String::from_utf8_lossy(&analysed.stderr));
    for f in ["sweep.csv", "sweep.ron", "indices.csv"] {
        assert_eq!(
            std::fs::read(dir.path().join("merged").join(f)).ok(),
            std::fs::read(dir.path().join("whole").join(f)).ok(),
            "{f}"
        );
    }
    // The tie holds: every run's spheres are equal (radius_2 is not a
    // column, and the restitution of equal spheres is what was computed).
    let ron = std::fs::read_to_string(dir.path().join("whole/sweep.ron")).expect("sweep.ron");
    assert!(ron.contains("radius_2=radius_1") && ron.contains("Sobol"), "{ron}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("whole/sensitivity.json")).expect("json"))
            .expect("json");
    assert!(json["analysis"]["program"].as_str().is_some_and(|p| p.starts_with("grainscope")), "{json}");
    assert_eq!(json["analysis"]["runs"].as_u64(), Some(64));
    // The impact velocity decides e here more than the size does.
    let st = |i: usize| json["analysis"]["sobol"]["indices"][i]["total"].as_f64().expect("ST");
    assert!(st(0) > st(1), "{json}");
    // Bad input is named.
    let bad =
        grainscope(&["sensitivity", "ice-bounce-8ms", "--vary", "velocity=log:3", "--output", "e", "--out", &d("x")]);
    assert!(!bad.status.success() && String::from_utf8_lossy(&bad.stderr).contains("NAME=lin|log:FROM:TO"));
    let bad = grainscope(&[
        "sensitivity",
        "ice-bounce-8ms",
        "--method",
        "sobol",
        "--samples",
        "100",
        "--vary",
        "velocity=log:3:30",
        "--output",
        "e",
        "--out",
        &d("y"),
    ]);
    assert!(!bad.status.success() && String::from_utf8_lossy(&bad.stderr).contains("power of two"));
    let grid = grainscope(&["sensitivity", "--analyse", &d("nothing")]);
    assert!(!grid.status.success());
}

#[test]
fn a_sweep_runs_the_points_of_a_table_and_ties_a_parameter_to_another() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |name: &str| dir.path().join(name).to_str().expect("utf8").to_string();
    std::fs::write(dir.path().join("points.csv"), "velocity [m/s],surface_energy\n2,0.74\n8,0.74\n1e-3,0.5\n30,1.2\n")
        .expect("write");
    let out =
        grainscope(&["sweep", "ice-bounce-8ms", "--points", &d("points.csv"), "--scalars", "sticks", "--out", &d("t")]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let table = std::fs::read_to_string(dir.path().join("t/sweep.csv")).expect("table");
    // The values as written (1e-3 reads back as 0.001), in the table's order.
    assert_eq!(
        table,
        "point,velocity [m s^-1],surface_energy [J m^-2],sticks,error\n0,2,0.74,1,\n1,8,0.74,0,\n2,0.001,0.5,1,\n3,30,1.2,0,\n"
    );
    // Resumed: nothing computed again.
    let again =
        grainscope(&["sweep", "ice-bounce-8ms", "--points", &d("points.csv"), "--scalars", "sticks", "--out", &d("t")]);
    assert!(String::from_utf8_lossy(&again.stdout).contains("(4 already done, 0 failed)"));
    // A point outside a range, and a malformed row, are named.
    std::fs::write(dir.path().join("bad.csv"), "velocity\n1e9\n").expect("write");
    let bad = grainscope(&["sweep", "ice-bounce-8ms", "--points", &d("bad.csv"), "--out", &d("b")]);
    assert!(String::from_utf8_lossy(&bad.stderr).contains("velocity = 1e9 is outside"), "{bad:?}");
    std::fs::write(dir.path().join("bad.csv"), "velocity\n1\nfast\n").expect("write");
    let bad = grainscope(&["sweep", "ice-bounce-8ms", "--points", &d("bad.csv"), "--out", &d("b")]);
    assert!(String::from_utf8_lossy(&bad.stderr).contains("row 2"), "{bad:?}");

    // Equal spheres: radius_2 follows radius_1, so v_stick falls as R^(-5/6)
    // or so; a log grid's middle value is printed as written.
    let out = grainscope(&[
        "sweep",
        "restitution-ice",
        "--vary",
        "radius_1=log:1e-6:4e-6:3",
        "--tie",
        "radius_2=radius_1",
        "--scalars",
        "v_stick",
        "--out",
        &d("tied"),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let table = std::fs::read_to_string(dir.path().join("tied/sweep.csv")).expect("table");
    let rows: Vec<Vec<&str>> = table.lines().skip(1).map(|l| l.split(',').collect()).collect();
    assert_eq!(rows[1][1], "0.000002", "{table}");
    let v: Vec<f64> = rows.iter().map(|r| r[2].parse().expect("v_stick")).collect();
    let slope = (v[2] / v[0]).ln() / 4f64.ln();
    assert!((-1.3..-0.8).contains(&slope), "{slope}: {table}");
    let untied = grainscope(&[
        "sweep",
        "restitution-ice",
        "--vary",
        "radius_1=log:1e-6:4e-6:3",
        "--scalars",
        "v_stick",
        "--out",
        &d("untied"),
    ]);
    assert!(untied.status.success());
    assert_ne!(std::fs::read_to_string(dir.path().join("untied/sweep.csv")).expect("table"), table);
    let bad = grainscope(&[
        "sweep",
        "restitution-ice",
        "--vary",
        "radius_1=log:1e-6:4e-6:3",
        "--tie",
        "radius_1=radius_2",
        "--out",
        &d("c"),
    ]);
    assert!(String::from_utf8_lossy(&bad.stderr).contains("must be another, not varied"), "{bad:?}");
}
