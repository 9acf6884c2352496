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
