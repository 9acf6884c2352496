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
    for f in ["collision-regimes.csv", "collision-regimes.svg", "collision-regimes.png", "scalars.json"] {
        assert!(dir.path().join(f).exists(), "{f}");
    }
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
    let out = grainscope(&["reproduce", "--quick", "--out", d]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let md = std::fs::read_to_string(dir.path().join("reproduce.md")).expect("md");
    assert!(md.contains("| Fig. 2.2 |"));
    assert!(dir.path().join("reproduce.csv").exists());
    assert!(dir.path().join("restitution-ice/restitution-velocity.png").exists());
    assert!(dir.path().join("experiments-fig-2-11/fig-2-11-wall-mica.svg").exists());
    assert!(dir.path().join("material-parameters/yield-length.csv").exists());
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
