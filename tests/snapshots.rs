//! Snapshot images of every scene as the window draws it, rendered without a
//! display by egui_kittest on wgpu (Mesa's software renderer on Linux), kept
//! in `tests/snapshots/` so that a change to any figure shows in review.
//!
//! Every scene is drawn at 1024 × 768 (a projector) in lecture mode, and the
//! first scene also in the ordinary layout, dark and light, at 1024 × 768 and
//! 1920 × 1080, and a family drawn by the "Draw family" tool over the smallest
//! fragment scene, in the window and in lecture mode. The Monte Carlo column scenes run one short run (2 × 10⁴
//! events) and the formation zone 200 batches a disk so that the suite stays
//! quick; everything else is drawn at its defaults. A figure that changes on purpose is refreshed with
//! `UPDATE_SNAPSHOTS=1 cargo test --release --test snapshots`; a failing
//! comparison leaves `NAME.new.png` and `NAME.diff.png` beside the kept image.
//! The kept images were drawn by Mesa's software Vulkan driver (lavapipe),
//! which `.ci/run` installs; another renderer may differ by a few pixels.

use std::time::{Duration, Instant};

use egui_kittest::{Harness, SnapshotOptions};
use grainscope::app::GrainscopeApp;
use grainscope::app::platform::native::NativePlatform;

/// How far a drawn picture may stray from the kept one: egui_kittest's
/// per-pixel colour threshold (0.6), and at most four pixels beyond it.
/// Lavapipe has drawn the same frame twice on one machine with two or three
/// antialiased pixels just past the threshold; four stays well below a real
/// change (a moved label or line changes hundreds).
fn tolerance() -> SnapshotOptions {
    SnapshotOptions::new().max_failed_pixels(4)
}

/// A window on the desktop platform that keeps no session.
fn new_app() -> GrainscopeApp {
    GrainscopeApp::new(egui::Context::default(), Box::new(NativePlatform::new(None)))
}
use grainscope::scene::{SCENES, SceneParams};

/// How long one scene may take to compute before the test gives up.
const PATIENCE: Duration = Duration::from_secs(240);

/// A harness that renders with wgpu, or none where this machine has no wgpu
/// adapter (no GPU and no Mesa software driver): then the comparison is
/// skipped with a message, except in CI (`CI` set), where it must run.
fn harness(w: f32, h: f32) -> Option<Harness<'static, GrainscopeApp>> {
    let build = || {
        let app = new_app();
        Harness::builder()
            .with_size(egui::vec2(w, h))
            .wgpu()
            .build_ui_state(|ui, app: &mut GrainscopeApp| app.show(ui), app)
    };
    match std::panic::catch_unwind(build) {
        Ok(h) => Some(h),
        Err(_) if std::env::var_os("CI").is_none() => {
            // Written to the terminal itself, past the test harness's
            // capture of `eprintln!`, so that a skip is seen where it happens.
            use std::io::Write;
            let _ = writeln!(
                std::io::stderr(),
                "WARNING: snapshots skipped: no wgpu adapter here (on Debian/Ubuntu, `apt install \
                 mesa-vulkan-drivers` gives Mesa's software renderer, which drew the kept images)"
            );
            None
        }
        Err(e) => std::panic::resume_unwind(e),
    }
}

/// The parameters a scene is drawn with: its defaults, with the Monte Carlo
/// column cut to one short run and the formation zone's 30 disks to 200
/// batches each (the same figure within a few per cent; its full size is a minute of each test).
fn snapshot_params(id: &str) -> SceneParams {
    let mut p = SceneParams::default_for(id).expect("a registered scene");
    if p.set("max_events_millions", "0.02").is_ok() {
        p.set("runs", "1").expect("a Monte Carlo scene has runs");
    }
    if id == "formation-zone" {
        p.set("batches", "200").expect("the formation zone has batches");
    }
    p
}

/// Steps frames until the open scene's result is drawn.
fn settle(h: &mut Harness<'static, GrainscopeApp>, what: &str) {
    let start = Instant::now();
    h.run_steps(2);
    while h.state().busy() || h.state().output().is_none() {
        assert!(start.elapsed() < PATIENCE, "{what}: no result after {PATIENCE:?}");
        std::thread::sleep(Duration::from_millis(20));
        h.run_steps(1);
    }
    // Lay out once more with the final result (legend sizes, colour bars).
    h.run_steps(3);
}

/// Opens scene `id` with its snapshot parameters in the given look.
fn open(h: &mut Harness<'static, GrainscopeApp>, id: &str, lecture: bool, light: bool) {
    let app = h.state_mut();
    app.state.session.scene = id.to_string();
    app.state.session.params.insert(id.to_string(), snapshot_params(id));
    app.state.session.lecture = lecture;
    app.state.session.light = light;
}

/// Opens scene `id` in the given look and compares its picture with the kept
/// one; an error names what differs.
fn check(
    h: &mut Harness<'static, GrainscopeApp>,
    id: &str,
    name: &str,
    lecture: bool,
    light: bool,
) -> Result<(), String> {
    open(h, id, lecture, light);
    settle(h, name);
    h.try_snapshot_options(name, &tolerance()).map_err(|e| format!("{name}: {e}"))
}

#[test]
fn every_scene_in_lecture_mode_at_projector_size() {
    let Some(mut h) = harness(1024.0, 768.0) else { return };
    // Every scene is compared before failing, so that one run shows every changed figure.
    let failures: Vec<String> = SCENES
        .iter()
        .filter_map(|s| check(&mut h, s.id, &format!("lecture-1024x768/{}", s.id), true, true).err())
        .collect();
    assert!(failures.is_empty(), "{} of {} snapshots differ:\n{}", failures.len(), SCENES.len(), failures.join("\n"));
}

#[test]
fn every_scene_in_the_window_at_projector_size() {
    let Some(mut h) = harness(1024.0, 768.0) else { return };
    let failures: Vec<String> = SCENES
        .iter()
        .filter_map(|s| check(&mut h, s.id, &format!("window-1024x768/scenes/{}", s.id), false, false).err())
        .collect();
    assert!(failures.is_empty(), "{} of {} snapshots differ:\n{}", failures.len(), SCENES.len(), failures.join("\n"));
}

#[test]
fn every_slide_of_the_shipped_decks_in_presenter_mode_at_projector_size() {
    use grainscope::app::command::Command;
    let Some(mut h) = harness(1024.0, 768.0) else { return };
    let mut failures = Vec::new();
    let mut slides = 0;
    for (file, _) in grainscope::deck::SHIPPED {
        let name = file.trim_end_matches(".ron");
        let mut deck = grainscope::deck::resolve(name).expect("a shipped deck");
        // Monte Carlo slides cut to one short run and the formation zone to
        // 200 batches a disk, as in the scene snapshots.
        for p in &mut deck.params {
            if p.set("max_events_millions", "0.02").is_ok() {
                p.set("runs", "1").expect("a Monte Carlo scene has runs");
            }
            if matches!(p, SceneParams::FormationZone(_)) {
                p.set("batches", "200").expect("the formation zone has batches");
            }
        }
        let n = deck.deck.slides.len();
        h.state_mut().apply(Command::Present(Box::new(deck), 0));
        for i in 0..n {
            h.state_mut().apply(Command::GoToSlide(i));
            settle(&mut h, name);
            // The timer at 0:00 in every picture.
            h.state_mut().apply(Command::Act(grainscope::app::command::Action::RestartTimer));
            h.step();
            let shot = format!("presenter-1024x768/{name}-{:02}", i + 1);
            failures.extend(h.try_snapshot_options(&shot, &tolerance()).err().map(|e| format!("{shot}: {e}")));
            slides += 1;
        }
        h.state_mut().apply(Command::StopPresenting);
    }
    assert!(failures.is_empty(), "{} of {slides} slides differ:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn the_ordinary_layout_dark_and_light_at_projector_and_desktop_sizes() {
    let first = SCENES[0].id;
    let mut failures = Vec::new();
    for (w, ht) in [(1024.0, 768.0), (1920.0, 1080.0)] {
        let Some(mut h) = harness(w, ht) else { return };
        for light in [false, true] {
            let name = format!("window-{w}x{ht}/{first}-{}", if light { "light" } else { "dark" });
            failures.extend(check(&mut h, first, &name, false, light).err());
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Draws a family (the "Draw family" tool) over scene `id` and compares the
/// picture: the pinned curves coloured by the swept value, with its colour bar.
fn check_family(
    h: &mut Harness<'static, GrainscopeApp>,
    id: &str,
    name: &str,
    lecture: bool,
    sweep: grainscope::app::command::Sweep,
) -> Result<(), String> {
    use grainscope::app::command::Command;
    open(h, id, lecture, false);
    settle(h, name);
    h.state_mut().apply(Command::ClearPins);
    h.state_mut().apply(Command::SetSweep(sweep));
    h.state_mut().apply(Command::DrawFamily);
    let start = Instant::now();
    while h.state().state.session.pins.is_empty() && h.state().state.error.is_none() {
        assert!(start.elapsed() < PATIENCE, "{name}: no family after {PATIENCE:?}");
        std::thread::sleep(Duration::from_millis(20));
        h.run_steps(1);
    }
    settle(h, name);
    h.try_snapshot_options(name, &tolerance()).map_err(|e| format!("{name}: {e}"))
}

#[test]
fn a_family_draws_over_its_scene_in_the_window_and_in_lecture_mode() {
    use grainscope::app::command::Sweep;
    let Some(mut h) = harness(1024.0, 768.0) else { return };
    let slope = || Sweep { key: "alpha".into(), from: 3.2, to: 3.8, steps: 4 };
    let mut failures = Vec::new();
    failures
        .extend(check_family(&mut h, "smallest-fragment", "family-1024x768/smallest-fragment", false, slope()).err());
    failures.extend(
        check_family(&mut h, "smallest-fragment", "family-1024x768/smallest-fragment-lecture", true, slope()).err(),
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn what_matters_for_the_sticking_velocity() {
    use grainscope::app::command::Command;
    let Some(mut h) = harness(1024.0, 768.0) else { return };
    let mut failures = Vec::new();
    for lecture in [false, true] {
        open(&mut h, "hysteresis", lecture, false);
        settle(&mut h, "what matters");
        h.state_mut().apply(Command::SetMatters("v_c".into(), 2.0));
        h.state_mut().apply(Command::WhatMatters);
        let start = Instant::now();
        while h.state().state.matters.result.is_none() {
            assert!(start.elapsed() < PATIENCE, "no answer after {PATIENCE:?}");
            std::thread::sleep(Duration::from_millis(20));
            h.run_steps(1);
        }
        // The sticking velocity against γ over its whole range.
        // A map in the normal window, a curve in lecture mode.
        let second = if lecture { "" } else { "radius_1" };
        h.state_mut().apply(Command::DrawSensitivity("surface_energy".into(), second.into()));
        while h.state().state.matters.curve.is_none() {
            assert!(start.elapsed() < PATIENCE, "no curve after {PATIENCE:?}");
            std::thread::sleep(Duration::from_millis(20));
            h.run_steps(1);
        }
        settle(&mut h, "what matters");
        let name = format!("matters-1024x768/hysteresis-v_c{}", if lecture { "-lecture" } else { "" });
        failures.extend(h.try_snapshot_options(&name, &tolerance()).err().map(|e| format!("{name}: {e}")));
        h.state_mut().apply(Command::CloseMatters);
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
