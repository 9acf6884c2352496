//! docs/parameters.md is the schema's reference, generated: it must match
//! what the schema says now. `UPDATE_REFERENCE=1 cargo test --release --test
//! parameter_reference` rewrites it.

use std::path::Path;

#[test]
fn the_parameter_reference_matches_the_schema() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/parameters.md");
    let generated = grainscope::scene::parameter_reference();
    if std::env::var_os("UPDATE_REFERENCE").is_some() {
        std::fs::write(&path, &generated).expect("write docs/parameters.md");
    }
    let written = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        written == generated,
        "docs/parameters.md differs from the schema: rerun with UPDATE_REFERENCE=1 to regenerate it"
    );
    // Every scene has its table, and a parameter of the first one is listed.
    for info in grainscope::scene::SCENES {
        assert!(generated.contains(&format!("### `{}`", info.id)), "{}", info.id);
    }
    assert!(generated.contains("| `velocity` | impact velocity v | m s^-1 |"));
}

/// Every parameter that sets a resolution, a sample or a limit of a numerical
/// method is declared `numerical` (the sensitivity tools report those apart),
/// and no parameter of the physics is.
#[test]
fn the_numerical_resolutions_are_declared_and_the_physics_is_not() {
    const NUMERICAL: [&str; 13] = [
        "rtol",
        "groups_per_decade",
        "batches",
        "dlnm",
        "runs",
        "seed",
        "steps_per_period",
        "column_mass",
        "max_events_millions",
        "f_limit",
        "f_m",
        "group_mass_cap",
        "tracks",
    ];
    const PHYSICS: [&str; 8] =
        ["velocity", "t_vis", "k", "alpha", "disk_mass", "surface_energy", "v_eros", "smoothing"];
    let mut seen = 0;
    for info in grainscope::scene::SCENES {
        let params = grainscope::scene::SceneParams::default_for(info.id).expect("scene");
        for spec in params.specs() {
            if NUMERICAL.contains(&spec.key) && !spec.figure_only {
                assert!(spec.numerical, "{}: '{}' sets a numerical resolution", info.id, spec.key);
                seen += 1;
            }
            if PHYSICS.contains(&spec.key) {
                assert!(!spec.numerical, "{}: '{}' is physics", info.id, spec.key);
            }
        }
    }
    assert!(seen >= 20, "only {seen} numerical parameters found");
    let reference = grainscope::scene::parameter_reference();
    assert!(reference.contains("(numerical resolution) |"), "the reference marks them");
}
