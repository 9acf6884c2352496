//! Every quick path (`Scene::scalar`, used by sweeps and "what matters")
//! equals the full computation, over parameters drawn from their documented
//! ranges: numbers (log-uniform where the control is logarithmic), switches
//! and choices, with the ends of a range in order. Counts (points on a
//! curve, radii of a panel) are drawn among their three smallest values,
//! which keeps the full computations short without changing what a quick
//! path skips.

use grainscope::scene::controls::ControlKind;
use grainscope::scene::{self, Progress, SCENES, SceneParams};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Draws every documented parameter of `p` at random.
fn draw(p: &mut SceneParams, rng: &mut StdRng) {
    for c in p.controls() {
        if c.style_only {
            continue;
        }
        let default = c.default.clone();
        match c.kind {
            ControlKind::Number { value, min, max, log, .. } => {
                *value = if log && min > 0.0 {
                    (min.ln() + rng.random::<f64>() * (max / min).ln()).exp()
                } else {
                    min + rng.random::<f64>() * (max - min)
                };
            }
            ControlKind::Count { value, min, max } => {
                let top = match default {
                    Some(scene::controls::DefaultValue::Count(d)) => d.clamp(min, max).min(min + 2),
                    _ => min,
                };
                *value = rng.random_range(min..=top);
            }
            ControlKind::Toggle(value) => *value = rng.random(),
            ControlKind::Choice { value, options } => {
                value.set_key(options[rng.random_range(0..options.len())].0);
            }
            ControlKind::Material(_) => {}
        }
    }
    p.material_changed();
    // A range's ends in order: "x_min" never above "x_max", the innermost
    // batch ("r_in_au") never outside the outermost ("r_out_au"). Swapped in
    // the controls themselves: `set` checks the whole set, which another
    // pair still out of order would fail.
    let numbers: Vec<(&str, f64)> = p
        .controls()
        .iter()
        .filter_map(|c| match c.value() {
            scene::controls::DefaultValue::Number(v) => Some((c.key, v)),
            _ => None,
        })
        .collect();
    let partner = |key: &str| -> Option<String> {
        match key {
            "r_in_au" => Some("r_out_au".to_string()),
            "r_out_au" => Some("r_in_au".to_string()),
            _ => key
                .strip_suffix("_min")
                .map(|stem| format!("{stem}_max"))
                .or_else(|| key.strip_suffix("_max").map(|stem| format!("{stem}_min"))),
        }
    };
    let lower = |key: &str| key == "r_in_au" || key.ends_with("_min");
    let swapped: Vec<(String, f64)> = numbers
        .iter()
        .filter_map(|(key, v)| {
            let other = partner(key)?;
            let (_, w) = numbers.iter().find(|(k, _)| *k == other)?;
            let out_of_order = if lower(key) { v > w } else { w > v };
            out_of_order.then(|| (key.to_string(), *w))
        })
        .collect();
    for c in p.controls() {
        if let (Some((_, w)), ControlKind::Number { value, .. }) = (swapped.iter().find(|(k, _)| k == c.key), c.kind) {
            *value = *w;
        }
    }
}

/// The same value: equal, or both the same kind of non-finite.
fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

/// About eight minutes on two cores (the full computations at random
/// restitution parameters): run with `cargo test --release --test quick_paths
/// -- --ignored`.
#[test]
#[ignore]
fn quick_paths_equal_the_full_computation_over_random_parameters() {
    let progress = Progress::default();
    let mut rng = StdRng::seed_from_u64(43);
    let mut checked = 0;
    for info in SCENES {
        let defaults = SceneParams::default_for(info.id).expect("a scene");
        // The scalar keys, from the preview where a scene has one (the same keys).
        let preview = defaults.coarse().unwrap_or_else(|| defaults.clone());
        let keys: Vec<&str> = match scene::compute(&preview, &progress) {
            Ok(out) => out.scalars.iter().map(|s| s.key).collect(),
            Err(_) => continue,
        };
        // Only scenes with a quick path for some key.
        let quick: Vec<&str> = keys.into_iter().filter(|k| defaults.quick_scalar(k, &progress).is_some()).collect();
        if quick.is_empty() {
            continue;
        }
        for draw_no in 0..10 {
            let mut p = defaults.clone();
            draw(&mut p, &mut rng);
            let full = p.validate().map_err(scene::SceneError::from).and_then(|_| scene::compute(&p, &progress));
            for key in &quick {
                let fast = scene::scalar(&p, key, &progress);
                match (&full, fast) {
                    (Ok(out), Ok(Some(v))) => {
                        let want = out.scalar(key).expect("the full computation reports it");
                        assert!(
                            same(v, want),
                            "{}, draw {draw_no}, {key}: quick {v} against full {want} at {p:?}",
                            info.id
                        );
                        checked += 1;
                    }
                    (Err(_), Err(_)) => {}
                    (full, fast) => panic!(
                        "{}, draw {draw_no}, {key}: the full computation gives {:?}, the quick path {fast:?}",
                        info.id,
                        full.as_ref().map(|o| o.scalar(key))
                    ),
                }
            }
        }
    }
    assert!(checked >= 20, "only {checked} values compared");
}
