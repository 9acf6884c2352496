//! The continuity audit (`grainscope audit`, src/audit.rs): it passes on
//! every light shipped preset, with every finding fixed or declared, and it
//! finds what it exists to find — the thesis's crack-law switch at
//! k = 0.018 and 0.022, which makes v_stick jump.

use grainscope::audit::{Options, audit};
use grainscope::preset::{Preset, SHIPPED};
use grainscope::scene::schema::Value;
use grainscope::scene::{Irregularity, Progress, SceneParams};

fn shipped(name: &str) -> SceneParams {
    let (file, text) = SHIPPED.iter().find(|(f, _)| *f == name).expect("shipped preset");
    Preset::from_ron(text, file).expect("shipped presets load").scene
}

#[test]
fn every_light_preset_passes() {
    let mut failing = Vec::new();
    for (file, text) in SHIPPED {
        let p = Preset::from_ron(text, file).expect("shipped presets load");
        if p.scene.info().heavy {
            continue;
        }
        let report = audit(&p.scene, &Options::default(), &Progress::default()).expect("the audit runs");
        assert!(report.computations > 1, "{file}: nothing was swept");
        if report.failures().next().is_some() {
            failing.push(format!("{file}\n{}", report.text()));
        }
    }
    assert!(failing.is_empty(), "undeclared findings:\n{}", failing.join("\n"));
}

#[test]
fn the_thesis_crack_law_makes_v_stick_jump_and_the_full_relation_does_not() {
    let options = Options { points: 24, refine: 12, only: vec!["k".into()], ceilings: Vec::new() };
    let mut thesis = shipped("restitution-ice.ron");
    thesis.set_value("crack_law", &Value::Text("thesis".into())).expect("a documented option");
    let report = audit(&thesis, &options, &Progress::default()).expect("the audit runs");
    let steps: Vec<_> = report
        .findings
        .iter()
        .filter(|f| f.kind == Irregularity::Step && f.scalar == "v_stick" && f.declared.is_none())
        .collect();
    // (2.17) holds for 0.018 ≤ k ≤ 0.022 and (2.16) outside: a jump at each end,
    // bracketed to within 2⁻¹² of a grid interval.
    for edge in [0.018, 0.022] {
        assert!(
            steps.iter().any(|f| f.at[0] <= edge && edge <= f.at[1] * (1.0 + 1e-12) && f.at[1] / f.at[0] < 1.001),
            "no step of v_stick at k = {edge}:\n{}",
            report.text()
        );
    }

    let full = shipped("restitution-ice.ron");
    let report = audit(&full, &options, &Progress::default()).expect("the audit runs");
    assert!(report.failures().next().is_none(), "{}", report.text());
}

#[test]
fn an_unknown_parameter_is_named() {
    let options = Options { only: vec!["kk".into()], ..Options::default() };
    let e = audit(&shipped("restitution-ice.ron"), &options, &Progress::default()).expect_err("refused");
    assert!(e.to_string().contains("'kk'"), "{e}");
}
