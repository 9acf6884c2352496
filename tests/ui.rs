//! The real UI driven without a window (egui_kittest).

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use grainscope::app::GrainscopeApp;
use grainscope::app::command::Command;
use grainscope::app::platform::native::NativePlatform;

/// A window on the desktop platform that keeps no session.
fn new_app() -> GrainscopeApp {
    GrainscopeApp::new(egui::Context::default(), Box::new(NativePlatform::new(None)))
}

fn harness() -> Harness<'static, GrainscopeApp> {
    harness_sized(1400.0, 1400.0)
}

fn harness_sized(w: f32, h: f32) -> Harness<'static, GrainscopeApp> {
    let app = new_app();
    Harness::builder().with_size(egui::vec2(w, h)).build_ui_state(|ui, app: &mut GrainscopeApp| app.show(ui), app)
}

/// Opens a scene as a user does: the scene navigator, then the scene's entry
/// ("Title · Figs. …") under its chapter.
fn open_scene(h: &mut Harness<'static, GrainscopeApp>, title: &str) {
    h.get_by_role_and_label(Role::ComboBox, "Scene").click();
    h.run();
    let prefix = format!("{title} · ");
    let wanted = title.to_string();
    h.get_by(move |n| n.role() == Role::Button && n.label().is_some_and(|l| l == wanted || l.starts_with(&prefix)))
        .click();
    // Heavy scenes keep repainting while their worker runs.
    h.run_steps(3);
}

#[test]
fn moving_the_velocity_slider_changes_the_shown_restitution() {
    let mut h = harness();
    h.run();
    // Default scene: the reference ice collision at 8 m/s, e = 0.657.
    h.get_by_label_contains("e = 0.65");
    h.get_by_role_and_label(Role::Slider, "impact velocity v").set_value_accesskit(4.0);
    h.run();
    assert!(h.query_by_label_contains("e = 0.65").is_none());
    h.get_by_label_contains("e = 0.22");
    let e = h.state().output().and_then(|o| o.scalar("e")).expect("e");
    assert!((e - 0.2247).abs() < 0.002, "{e}");
    // Slow enough to stick.
    h.get_by_role_and_label(Role::Slider, "impact velocity v").set_value_accesskit(1.0);
    h.run();
    h.get_by_label_contains("(sticks)");
}

#[test]
fn a_styling_control_does_not_recompute() {
    let mut h = harness();
    h.run();
    let before = h.state().output().map(|o| o as *const _);
    h.get_by_role_and_label(Role::Slider, "time cursor").set_value_accesskit(0.8);
    h.run();
    let after = h.state().output().map(|o| o as *const _);
    assert_eq!(before, after, "the output was recomputed for a cursor move");
}

#[test]
fn switching_scene_and_pinning_keeps_the_app_alive() {
    let mut h = harness();
    h.run();
    open_scene(&mut h, "Adhesive contact basics");
    assert!(h.query_all_by_label_contains("Regime of this aggregate collision").next().is_some());
    h.get_by_label("Pin curves").click();
    h.run();
    assert_eq!(h.state().state.session.pins.len(), 1);
    h.get_by_role_and_label(Role::Slider, "monomer radius r₀").set_value_accesskit(1.0);
    h.run();
    assert!(h.query_all_by_label_contains("pinned: monomer radius r₀").next().is_some());
}

/// Imports measurements from a typed path, as the "Load data" button does.
fn import(app: &mut GrainscopeApp, path: &std::path::Path) {
    use grainscope::app::command::Field;
    app.apply(Command::SetText(Field::DataPath, path.display().to_string()));
    app.apply(Command::LoadDataPath);
}

/// The notice of a refused control value: (key, why).
fn control_notice(h: &Harness<'static, GrainscopeApp>) -> Option<(String, String)> {
    h.state().state.control_notice.clone()
}

#[test]
fn importing_measurements_opens_the_fit_scene_and_bad_files_change_nothing() {
    let dir = tempfile::tempdir().expect("tempdir");
    let good = dir.path().join("good.csv");
    std::fs::write(&good, "velocity [m/s],restitution\n5,0.7\n10,0.75\n20,0.77\n").expect("write");
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "velocity [m/s],restitution\n5,0.7\n-10,0.75\n").expect("write");
    let mut app = new_app();
    let before = app.state.session.clone();
    import(&mut app, &bad);
    let mut after = app.state.session.clone();
    after.data_path = before.data_path.clone();
    assert_eq!(after, before, "a rejected file changed the session");
    import(&mut app, &good);
    assert_eq!(app.params().info().id, "fit");
    match app.params() {
        grainscope::scene::SceneParams::Fit(p) => assert_eq!(p.data.len(), 3),
        other => panic!("wrong scene {other:?}"),
    }
}

#[test]
fn a_restored_session_keeps_each_scenes_settings_by_id() {
    use grainscope::app::Session;
    let mut session = Session::default();
    let mut p = grainscope::scene::SceneParams::default_for("rocking").expect("scene");
    p.set("q", "12").expect("valid");
    session.params.insert("rocking".into(), p.clone());
    session.scene = "rocking".into();
    // A session written when the list had another order or fewer scenes, and
    // with one entry under a wrong id, loses only what it cannot place.
    session.params.remove("hysteresis");
    let stray = grainscope::scene::SceneParams::default_for("adhesion").expect("scene");
    session.params.insert("no-such-scene".into(), stray);
    let text = ron::to_string(&session).expect("serialises");
    let restored: Session = ron::from_str(&text).expect("parses");
    let restored = restored.repaired();
    assert_eq!(restored.params.get("rocking"), Some(&p));
    assert_eq!(restored.scene, "rocking");
    assert!(restored.params.contains_key("hysteresis"));
    assert!(!restored.params.contains_key("no-such-scene"));
    assert_eq!(restored.params.len(), grainscope::scene::SCENES.len());
}

/// Types `text` into the value field next to the slider labelled `label`
/// and presses Enter, as a user does.
fn type_into_slider(h: &mut Harness<'static, GrainscopeApp>, label: &str, text: &str) {
    h.get_by_role_and_label(Role::SpinButton, label).click();
    h.run_steps(3);
    h.run_steps(3);
    h.event(egui::Event::Text(text.to_string()));
    h.run_steps(3);
    h.key_press(egui::Key::Enter);
    h.run_steps(3);
    h.run_steps(3);
}

#[test]
fn a_typed_value_outside_its_range_is_refused_with_a_notice() {
    let mut h = harness();
    h.run();
    let velocity = |h: &Harness<'static, GrainscopeApp>| h.state().params().clone();
    let before = velocity(&h);
    for typed in ["1e300", "-1", "nan", "abc"] {
        type_into_slider(&mut h, "impact velocity v", typed);
        assert_eq!(velocity(&h), before, "'{typed}' changed the parameters");
        let (key, message) = control_notice(&h).expect("a notice");
        assert_eq!(key, "velocity");
        assert!(message.contains(typed) && message.contains("kept 8"), "{message}");
        assert!(message.contains("0.001 … 1000 m/s"), "{message}");
        h.get_by_label_contains(&format!("impact velocity v: {typed}"));
    }
    // A valid value is taken and clears the notice.
    type_into_slider(&mut h, "impact velocity v", "4");
    assert!(control_notice(&h).is_none());
    let e = h.state().output().and_then(|o| o.scalar("e")).expect("e");
    assert!((e - 0.2247).abs() < 0.002, "{e}");
}

#[test]
fn a_typed_value_may_name_its_unit() {
    let mut h = harness();
    h.run();
    let velocity = |h: &Harness<'static, GrainscopeApp>| number(h.state().params(), "velocity");
    // The field's own unit, another unit of speed, and the thesis' notation.
    for (typed, want) in [("5 m/s", 5.0), ("400 cm/s", 4.0), ("3 m s^-1", 3.0)] {
        type_into_slider(&mut h, "impact velocity v", typed);
        assert!((velocity(&h) - want).abs() < 1e-12, "'{typed}' gave {}", velocity(&h));
        assert!(control_notice(&h).is_none());
    }
    // A unit of another kind is refused and named.
    type_into_slider(&mut h, "impact velocity v", "5 kg");
    assert!((velocity(&h) - 3.0).abs() < 1e-12);
    let (_, message) = control_notice(&h).expect("a notice");
    assert!(
        message.contains("\"kg\" is not a unit of the same kind as m/s") && message.contains("kept 3"),
        "{message}"
    );
}

#[test]
fn the_sweep_form_follows_the_scene() {
    let mut h = harness();
    h.run();
    let i = grainscope::scene::SCENES.iter().position(|s| s.title == "Smallest fragment").expect("scene");
    h.state_mut().apply(Command::OpenScene(i));
    h.run_steps(3);
    // The default form sweeps "velocity", which this scene does not have:
    // it starts from one of the scene's own parameters, inside its range.
    let sweep = h.state().state.sweep.clone();
    let mut params = h.state().params().clone();
    let knob = params.controls().into_iter().find(|c| c.key == sweep.key).expect("a parameter of the scene");
    match knob.kind {
        grainscope::scene::ControlKind::Number { min, max, .. } => {
            assert!(sweep.from >= min && sweep.to <= max && sweep.from < sweep.to, "{sweep:?} in {min} … {max}");
        }
        _ => panic!("{} is not a number parameter", sweep.key),
    }
}

#[test]
fn a_long_status_message_wraps_inside_the_window() {
    let width = 800.0;
    let mut h = Harness::builder()
        .with_size(egui::vec2(width, 700.0))
        .build_ui_state(|ui, app: &mut GrainscopeApp| app.show(ui), new_app());
    h.run();
    let long = format!("preset not loaded: {}", "a very long path segment/".repeat(20));
    import(h.state_mut(), std::path::Path::new(&long));
    h.run();
    let node = h.get_by_label_contains("a very long path segment");
    assert!(node.rect().max.x <= width + 0.5, "the message runs off the window: {:?}", node.rect());
    assert!(node.rect().height() > 30.0, "the message did not wrap: {:?}", node.rect());
}

#[test]
fn an_unreadable_session_file_starts_clean_and_is_kept() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("session.ron");
    std::fs::write(&path, "(scene: \"rocking\", params: {\"rocking\": Rocking((q: ").expect("write");
    let on_disk = || Box::new(NativePlatform::new(Some(path.clone())));
    let mut app = GrainscopeApp::new(egui::Context::default(), on_disk());
    app.restore_session();
    assert_eq!(app.state.session, grainscope::app::Session::default());
    let notices = &app.state.notices;
    assert_eq!(notices.len(), 1, "{notices:?}");
    assert!(notices[0].contains("kept as"), "{notices:?}");
    assert!(!path.exists());
    // Saving writes a fresh, readable session next to the kept file.
    app.state.session.scene = "rocking".into();
    app.save_session();
    let mut again = GrainscopeApp::new(egui::Context::default(), on_disk());
    again.restore_session();
    assert_eq!(again.state.session.scene, "rocking");
    assert!(again.state.notices.is_empty());
    assert_eq!(std::fs::read_dir(dir.path()).expect("dir").count(), 2);
}

/// The radius of the adhesion scene (m).
fn monomer_radius(h: &Harness<'static, GrainscopeApp>) -> f64 {
    number(h.state().params(), "radius")
}

/// The value of the number parameter `key`, SI (NaN if there is none).
fn number(p: &grainscope::scene::SceneParams, key: &str) -> f64 {
    let mut p = p.clone();
    p.controls()
        .into_iter()
        .find_map(|c| match c.kind {
            grainscope::scene::ControlKind::Number { value, .. } if c.key == key => Some(*value),
            _ => None,
        })
        .unwrap_or(f64::NAN)
}

#[test]
fn value_fields_take_their_range_ends_keep_unedited_values_and_refuse_fractions() {
    let mut h = harness();
    h.run();
    open_scene(&mut h, "Adhesive contact basics");
    // An exact value the field shows rounded ("0.12 µm"): focusing the field
    // and leaving it unedited keeps the value.
    {
        let app = h.state_mut();
        let id = app.state.session.scene.clone();
        let p = app.state.session.params.get_mut(&id).expect("params");
        p.set("radius", "1.2345e-7").expect("valid");
    }
    h.run();
    type_into_slider(&mut h, "monomer radius r₀", "");
    assert_eq!(monomer_radius(&h), 1.2345e-7);
    assert!(control_notice(&h).is_none());
    // The lower end of the range, typed in display units (0.01 µm = 1e-8 m).
    type_into_slider(&mut h, "monomer radius r₀", "0.01");
    assert!(control_notice(&h).is_none(), "{:?}", control_notice(&h));
    assert!((monomer_radius(&h) / 1e-8 - 1.0).abs() < 1e-12, "{}", monomer_radius(&h));
    // A whole-number field refuses a fraction instead of rounding it.
    // Restitution computes on the job runner: its result changes the layout,
    // so the field is clicked only once the result is in.
    open_scene(&mut h, "Restitution");
    wait_until(&mut h, 120, |a| !a.busy());
    let before = h.state().params().clone();
    type_into_slider(&mut h, "velocities", "2.5");
    assert_eq!(h.state().params(), &before);
    let (key, message) = control_notice(&h).expect("a notice");
    assert_eq!(key, "n_velocities");
    assert!(message.contains("2.5 is not a whole number"), "{message}");
}

/// The label of the open scene's first parameter control.
fn first_control(h: &Harness<'static, GrainscopeApp>) -> String {
    let mut p = h.state().params().clone();
    p.controls().first().map(|c| c.label.to_string()).expect("every scene has a parameter")
}

#[test]
fn every_scene_shows_its_first_parameter_without_scrolling_at_projector_and_desktop_sizes() {
    for (w, ht) in [(1024.0, 768.0), (1920.0, 1080.0)] {
        let mut h = harness_sized(w, ht);
        h.run_steps(2);
        let mut seen = std::collections::BTreeSet::new();
        for _ in 0..grainscope::scene::SCENES.len() {
            let scene = h.state().state.session.scene.clone();
            seen.insert(scene.clone());
            let label = first_control(&h);
            let node = h.query_all_by_label_contains(&label).next();
            let rect = node.map(|n| n.rect()).unwrap_or_else(|| panic!("{scene}: no control '{label}' at {w}×{ht}"));
            assert!(
                rect.top() >= 0.0 && rect.bottom() <= ht,
                "{scene}: '{label}' at {rect:?} is below the fold of {w}×{ht}"
            );
            // Page Down walks the navigator, chapter by chapter.
            h.key_press(egui::Key::PageDown);
            h.run_steps(2);
        }
        assert_eq!(seen.len(), grainscope::scene::SCENES.len(), "Page Down visits every scene once");
    }
}

#[test]
fn lecture_mode_gives_the_plots_most_of_a_projector_screen() {
    let (w, ht) = (1024.0, 768.0);
    let mut h = harness_sized(w, ht);
    h.run_steps(2);
    let outside = h.state().plot_area().expect("plots").area();
    h.get_by_label("Lecture mode").click();
    h.run_steps(3);
    assert!(h.state().state.session.lecture);
    let area = h.state().plot_area().expect("plots");
    let share = area.area() / (w * ht);
    // Three quarters and more: the top bar and the strip that picks the panels take one line each.
    assert!(share >= 0.75, "plots cover {:.0} % of the window in lecture mode", 100.0 * share);
    assert!(area.area() > outside, "lecture mode makes the plots larger");
    // The parameters are one click away, over the plots.
    h.get_by_label("Parameters").click();
    h.run_steps(2);
    assert!(h.query_all_by_label_contains(&first_control(&h)).next().is_some());
    // Escape leaves lecture mode.
    h.key_press(egui::Key::Escape);
    h.run_steps(2);
    assert!(!h.state().state.session.lecture);
}

#[test]
fn switching_scenes_and_themes_never_panics() {
    let mut h = harness_sized(1024.0, 768.0);
    h.run_steps(2);
    for k in 0..grainscope::scene::SCENES.len() {
        {
            let app = h.state_mut();
            app.state.session.light = k % 2 == 0;
            app.state.session.lecture = k % 3 == 0;
        }
        h.run_steps(2);
        h.key_press(egui::Key::PageDown);
        h.run_steps(2);
    }
}

fn velocity(h: &Harness<'static, GrainscopeApp>) -> f64 {
    number(h.state().params(), "velocity")
}

/// Runs frames until the open scene's result is ready.
fn settle(h: &mut Harness<'static, GrainscopeApp>) {
    for _ in 0..600 {
        h.step();
        if !h.state().busy() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    h.run_steps(2);
}

fn scene_id(h: &Harness<'static, GrainscopeApp>) -> &'static str {
    h.state().params().info().id
}

const DECK: &str = r#"(
    title: "Test lecture",
    slides: [
        (title: "Slow ice", notes: "Notes of the first slide.", preset: Some("ice-bounce-8ms"), set: ["velocity=4"], highlight: ["velocity"]),
        (title: "Restitution", notes: "Notes of the second slide.", preset: Some("restitution-ice"), enlarge: Some("restitution")),
        (title: "Adhesion", notes: "Notes of the third slide.", preset: Some("adhesion-ice-monomers")),
    ],
)"#;

/// A deck is presented with the keys a clicker sends: forward, back, jump,
/// notes, leave; coming back to a slide shows it as the deck defines it.
#[test]
fn a_deck_advances_and_goes_back_with_the_keys_and_restores_each_slide() {
    let deck = grainscope::deck::Deck::from_ron(DECK, "test", None).expect("deck");
    let mut h = harness_sized(1024.0, 768.0);
    settle(&mut h);
    // The explorer before the deck: another scene, and hysteresis at 9 m/s.
    let mut mine = h.state().params().clone();
    mine.set("velocity", "9").expect("velocity");
    h.state_mut().apply(Command::SetParams(Box::new(mine)));
    let rocking = grainscope::scene::SCENES.iter().position(|s| s.id == "rocking").expect("scene");
    h.state_mut().apply(Command::OpenScene(rocking));
    settle(&mut h);
    h.state_mut().apply(Command::Present(Box::new(deck), 0));
    settle(&mut h);
    assert_eq!(scene_id(&h), "hysteresis");
    assert_eq!(velocity(&h), 4.0);
    assert!(h.state().state.session.lecture, "presenting uses the lecture look");
    h.get_by_label_contains("Slow ice");
    // The highlighted control is at hand beside the plots, and live.
    h.get_by_role_and_label(Role::Slider, "impact velocity v").set_value_accesskit(6.0);
    settle(&mut h);
    assert_eq!(velocity(&h), 6.0);
    h.key_press(egui::Key::ArrowRight);
    settle(&mut h);
    assert_eq!(scene_id(&h), "restitution");
    h.key_press(egui::Key::PageUp);
    settle(&mut h);
    assert_eq!(scene_id(&h), "hysteresis");
    assert_eq!(velocity(&h), 4.0, "the slide as the deck defines it");
    h.key_press(egui::Key::Space);
    h.key_press(egui::Key::Space);
    settle(&mut h);
    assert_eq!(scene_id(&h), "adhesion");
    h.key_press(egui::Key::Num2);
    settle(&mut h);
    assert_eq!(scene_id(&h), "restitution");
    h.key_press(egui::Key::End);
    settle(&mut h);
    assert_eq!(h.state().state.presenter.as_ref().map(|p| p.index), Some(2));
    h.key_press(egui::Key::ArrowRight);
    settle(&mut h);
    assert_eq!(h.state().state.presenter.as_ref().map(|p| p.index), Some(2), "stays at the last slide");
    assert!(h.query_by_label_contains("Notes of the third slide").is_none());
    h.key_press(egui::Key::N);
    settle(&mut h);
    h.get_by_label_contains("Notes of the third slide");
    // The notes also open in a window of their own, with what comes next.
    h.key_press(egui::Key::W);
    settle(&mut h);
    h.get_by_label("last slide");
    h.key_press(egui::Key::W);
    settle(&mut h);
    assert!(h.query_by_label("last slide").is_none());
    h.key_press(egui::Key::Escape);
    settle(&mut h);
    assert!(h.state().state.presenter.as_ref().is_none());
    assert!(!h.state().state.session.lecture, "leaving restores the look from before");
    // ... and the scene and parameters from before.
    assert_eq!(scene_id(&h), "rocking");
    assert_eq!(number(&h.state().state.session.params["hysteresis"], "velocity"), 9.0);
    // A clicker's Shift+F5 resumes the deck at the slide it was left on, F5
    // starts it from the first.
    h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::F5);
    settle(&mut h);
    assert_eq!(h.state().state.presenter.as_ref().map(|p| p.index), Some(2), "resumed where it was left");
    assert_eq!(scene_id(&h), "adhesion");
    h.key_press(egui::Key::F5);
    settle(&mut h);
    assert_eq!(h.state().state.presenter.as_ref().map(|p| p.index), Some(0), "F5 starts from the first slide");
    assert_eq!(scene_id(&h), "hysteresis");
    h.key_press(egui::Key::Escape);
    settle(&mut h);
    h.key_press(egui::Key::F5);
    settle(&mut h);
    assert_eq!(h.state().state.presenter.as_ref().map(|p| p.index), Some(0));
}

/// A slider drag is one undo step: Ctrl+Z restores the value from before
/// the drag, Ctrl+Shift+Z the dragged one.
#[test]
fn undo_restores_the_value_from_before_a_slider_drag() {
    let mut h = harness();
    h.run();
    assert_eq!(velocity(&h), 8.0);
    let rect = h.get_by_role_and_label(Role::Slider, "impact velocity v").rect();
    let y = rect.center().y;
    h.drag_at(egui::pos2(rect.left() + 0.7 * rect.width(), y));
    h.run();
    for k in 1..=5 {
        h.hover_at(egui::pos2(rect.left() + (0.7 - 0.1 * k as f32) * rect.width(), y));
        h.run();
    }
    h.drop_at(egui::pos2(rect.left() + 0.2 * rect.width(), y));
    h.run();
    let dragged = velocity(&h);
    assert!(dragged < 8.0, "the drag moved the slider: {dragged}");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(velocity(&h), 8.0, "one drag, one step");
    h.key_press_modifiers(egui::Modifiers::COMMAND | egui::Modifiers::SHIFT, egui::Key::Z);
    h.run();
    assert_eq!(velocity(&h), dragged);
}

/// Play advances the time cursor without recomputing the model; pause
/// stops it; the shortcut list opens with F1.
#[test]
fn play_advances_the_time_cursor_and_pause_stops_it() {
    let mut h = harness();
    h.run();
    let before = h.state().output().map(|o| o as *const _);
    let t0 = h.state().state.time().expect("the collision has a time cursor");
    h.key_press(egui::Key::Space);
    h.run_steps(3);
    h.get_by_label("❚❚ Pause");
    assert!(h.state().state.playback.playing);
    let t1 = h.state().state.time().expect("time");
    assert!(t1 > t0, "{t0} → {t1}");
    assert_eq!(before, h.state().output().map(|o| o as *const _), "playing never recomputes");
    h.get_by_label("❚❚ Pause").click();
    h.run_steps(3);
    let t2 = h.state().state.time().expect("time");
    h.run_steps(10);
    assert!(!h.state().state.playback.playing);
    assert_eq!(h.state().state.time(), Some(t2));
    h.key_press(egui::Key::CloseBracket);
    h.run();
    assert!((h.state().state.time().expect("time") - (t2 + 0.01)).abs() < 1e-9);
    h.key_press(egui::Key::H);
    h.run();
    h.get_by_label("Keyboard shortcuts");
    h.get_by_label_contains("undo the last parameter change");
}

/// A figure exported from the window reopens its state when opened (or dropped).
#[test]
fn an_exported_figure_reopens_its_state() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut h = harness();
    h.run();
    h.get_by_role_and_label(Role::Slider, "impact velocity v").set_value_accesskit(3.0);
    h.run();
    let exported = h.state().params().clone();
    h.state_mut().state.session.export_dir = dir.path().display().to_string();
    h.key_press(egui::Key::E);
    h.run();
    // The files are written on a thread of their own.
    let png = dir.path().join("hysteresis-energy-budget.png");
    for _ in 0..400 {
        if h.state().status().starts_with("wrote the export") {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(25));
        h.step();
    }
    assert!(png.exists(), "{}", h.state().status());
    h.get_by_role_and_label(Role::Slider, "impact velocity v").set_value_accesskit(5.0);
    h.run();
    h.state_mut().apply(Command::OpenPath(png.display().to_string()));
    h.run();
    assert_eq!(h.state().params(), &exported);
    let plain = dir.path().join("plain.png");
    std::fs::write(&plain, b"not a png").expect("write");
    h.state_mut().apply(Command::OpenPath(plain.display().to_string()));
    h.run();
    assert_eq!(h.state().params(), &exported, "a file without state changes nothing");
}

/// A deck built in the window: two states added as slides, saved, and read
/// back with each slide's parameters.
#[test]
fn a_deck_built_from_the_window_saves_each_state() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("lecture.ron");
    let mut h = harness();
    h.run();
    h.get_by_label("Deck").click();
    h.run();
    h.get_by_label("Add the current state as a slide").click();
    h.run();
    h.get_by_role_and_label(Role::Slider, "impact velocity v").set_value_accesskit(2.0);
    h.run();
    let slow = h.state().params().clone();
    h.get_by_label("Add the current state as a slide").click();
    h.run();
    h.get_by_role_and_label(Role::TextInput, "deck file").focus();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run();
    h.get_by_role_and_label(Role::TextInput, "deck file").type_text(path.to_str().expect("utf8"));
    h.run();
    h.get_by_label("Save deck").click();
    h.run();
    let deck = grainscope::deck::Deck::load(&path).unwrap_or_else(|e| panic!("{e}: {}", h.state().status()));
    assert_eq!(deck.params.len(), 2);
    assert_eq!(deck.params[1], slow);
    assert_eq!(number(&deck.params[0], "velocity"), 8.0);
}

/// A click on a cell of the collision-speed map opens its card; for two
/// monomers the card opens the contact scene at the cell's velocity.
#[test]
fn clicking_a_map_cell_inspects_it_and_opens_the_collision() {
    let mut h = harness();
    h.run_steps(2);
    open_scene(&mut h, "Collision speeds");
    settle(&mut h);
    let frame = h.state().plot_frame("collision-speed").expect("the map is drawn");
    // The lower-left cell: two monomers.
    let at = frame.left_bottom() + egui::vec2(3.0, -3.0);
    h.drag_at(at);
    h.run_steps(2);
    h.drop_at(at);
    h.run_steps(3);
    let card = h.state().state.inspection().cloned().expect("the click opens a card");
    assert!(card.point[0] < 2.2 && card.point[1] < 2.2, "a lower-left cell: {}", card.title);
    let dv: f64 = card
        .rows
        .iter()
        .find(|(k, _)| k == "relative velocity Δv")
        .and_then(|(_, v)| v.trim_end_matches(" m/s").parse().ok())
        .expect("Δv row");
    assert!(card.bars.as_ref().is_some_and(|(_, b)| b.len() == 5), "Δv by source");
    assert!(card.outcome.is_some());
    h.get_by_label("Open as a collision").click();
    h.run_steps(3);
    assert_eq!(scene_id(&h), "hysteresis");
    let v = velocity(&h);
    assert!((v / dv - 1.0).abs() < 0.01, "velocity {v} vs Δv {dv}");
    let r = number(h.state().params(), "radius_1");
    assert!((1e-7..1.3e-7).contains(&r), "a monomer-sized radius {r}");
}

/// Moving the monomer radius in one aggregate scene moves it in every scene
/// that shares the monomer, and not in one that keeps its own.
#[test]
fn the_monomer_card_is_shared_between_scenes() {
    let mut h = harness();
    h.run_steps(2);
    open_scene(&mut h, "Mass–porosity track");
    h.run_steps(2);
    type_into_slider(&mut h, "monomer radius a₀", "0.5");
    h.run_steps(2);
    let here = number(h.state().params(), "monomer_radius");
    assert!((here - 5e-7).abs() < 1e-15, "{here}");
    open_scene(&mut h, "Stokes number");
    assert!((number(h.state().params(), "monomer_radius") - 5e-7).abs() < 1e-15, "linked");
    // A scene that keeps its own monomer is left alone.
    h.get_by_label("own monomer").click();
    h.run_steps(2);
    type_into_slider(&mut h, "monomer radius a₀", "0.2");
    h.run_steps(2);
    open_scene(&mut h, "Mass–porosity track");
    assert!((number(h.state().params(), "monomer_radius") - 5e-7).abs() < 1e-15, "not linked");
}

/// Runs frames until `done` holds (or `secs` pass); the runner's results
/// arrive from other threads.
fn wait_until(h: &mut Harness<'static, GrainscopeApp>, secs: u64, done: impl Fn(&GrainscopeApp) -> bool) {
    let start = std::time::Instant::now();
    while !done(h.state()) && start.elapsed() < std::time::Duration::from_secs(secs) {
        h.step();
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    h.run_steps(2);
}

/// Runs frames until the family sweep has pinned its curves (or an error).
fn wait_for_pins(h: &mut Harness<'static, GrainscopeApp>) {
    wait_until(h, 60, |a| !a.state.session.pins.is_empty() || a.state.error.is_some());
}

#[test]
fn draw_family_pins_one_curve_set_per_value_in_a_light_scene() {
    use grainscope::app::command::Sweep;
    let mut h = harness();
    h.run();
    let i = grainscope::scene::SCENES.iter().position(|s| s.title == "Smallest fragment").expect("scene");
    h.state_mut().apply(Command::OpenScene(i));
    settle(&mut h);
    h.state_mut().apply(Command::SetSweep(Sweep { key: "alpha".into(), from: 3.2, to: 3.8, steps: 4 }));
    h.run_steps(2);
    h.get_by_label("Draw family").click();
    wait_for_pins(&mut h);
    let s = &h.state().state;
    assert_eq!(s.session.pins.len(), 4, "status {:?}, error {:?}", s.status, s.error);
    // The slope is a linear control: evenly spaced values, 3.5 among them.
    let labels: Vec<&str> = s.session.pins.iter().map(|p| p.label.as_str()).collect();
    assert_eq!(labels, ["alpha = 3.2", "alpha = 3.4", "alpha = 3.6", "alpha = 3.8"]);
    assert!(s.session.pins.iter().all(|p| !p.curves.is_empty()));
    assert_eq!(s.status, "swept 4 values");
    // Every pinned curve carries its swept value, for the family's colour bar.
    let values: Vec<f64> = s.session.pins.iter().flat_map(|p| p.curves.iter().filter_map(|(_, c)| c.family)).collect();
    assert!(values.iter().all(|v| (3.2..=3.8).contains(v)) && values.len() >= 4, "{values:?}");
}

#[test]
fn draw_family_survives_a_heavy_scenes_own_computation() {
    use grainscope::app::command::Sweep;
    let mut h = harness();
    h.run();
    open_scene(&mut h, "Restitution");
    // Small grids, so that each value takes a fraction of a second.
    let mut p = h.state().params().clone();
    for (k, v) in [("n_velocities", "8"), ("n_radii", "6"), ("n_t_vis", "2")] {
        p.set(k, v).expect("a documented key");
    }
    h.state_mut().apply(Command::SetParams(Box::new(p)));
    settle(&mut h);
    h.state_mut().apply(Command::SetSweep(Sweep { key: "surface_energy".into(), from: 0.1, to: 1.0, steps: 2 }));
    h.state_mut().apply(Command::DrawFamily);
    wait_for_pins(&mut h);
    let s = &h.state().state;
    assert_eq!(s.session.pins.len(), 2, "status {:?}, error {:?}", s.status, s.error);
    // The sticking-velocity panel colours its own curves by T_vis: pins drawn
    // there keep no γ value, so its colour bar stays T_vis.
    for pin in &s.session.pins {
        for (figure, series) in &pin.curves {
            let own = figure == "sticking-velocity";
            assert_eq!(series.family.is_none(), own, "{figure}: {:?}", series.family);
        }
    }
}

#[test]
fn what_matters_ranks_the_parameters_of_the_jkr_sticking_velocity() {
    let mut h = harness();
    h.run();
    h.state_mut().apply(Command::SetMatters("v_c".into(), 2.0));
    h.get_by_label("What matters").click();
    // A liveness bound, generous for a machine busy with the other tests.
    wait_until(&mut h, 240, |a| a.state.matters.result.is_some());
    let s = &h.state().state;
    let (_, m) = s.matters.result.as_ref().expect("a result");
    assert!(m.here.mean.is_some_and(|v| v > 0.0));
    // v_c ∝ γ^{5/6} (2.25).
    let gamma = m.rows.iter().find(|r| r.key == "surface_energy").expect("γ");
    assert!((gamma.elasticity.expect("defined") - 5.0 / 6.0).abs() < 1e-6);
    h.get_by_label("What moves");
    h.get_by_label("+0.833");
}

#[test]
fn panels_that_do_not_fit_show_one_at_a_time_and_the_choice_is_kept_per_scene() {
    let mut h = harness_sized(1024.0, 768.0);
    let i = grainscope::scene::SCENES.iter().position(|s| s.id == "restitution").expect("scene");
    h.state_mut().apply(Command::OpenScene(i));
    wait_until(&mut h, 60, |a| a.output().is_some());
    settle(&mut h);
    // Three panels beside the side panel do not fit at 1024 × 768: the first alone.
    assert_eq!(h.state().state.session.panels.get("restitution"), None);
    assert!(h.query_all_by_label("Restitution against velocity").count() >= 1);
    assert!(h.state().plot_frame("restitution-velocity").is_some());
    assert!(h.state().plot_frame("sticking-velocity").is_none(), "one panel at a time");
    let frame = h.state().plot_frame("restitution-velocity").expect("drawn");
    assert!(frame.width() >= 400.0 && frame.height() >= 260.0, "{frame:?}");
    // Pick another panel in the strip; then every panel at once.
    h.get_by_label_contains("Sticking velocity against").click();
    settle(&mut h);
    assert!(h.state().plot_frame("sticking-velocity").is_some());
    assert!(h.state().plot_frame("restitution-velocity").is_none());
    h.get_by_label("All panels").click();
    settle(&mut h);
    assert!(
        h.state().plot_frame("restitution-velocity").is_some() && h.state().plot_frame("sticking-velocity").is_some()
    );
    // Another scene and back: the choice stays with its scene.
    h.state_mut().apply(Command::OpenScene(i - 1));
    settle(&mut h);
    h.state_mut().apply(Command::OpenScene(i));
    settle(&mut h);
    assert_eq!(h.state().state.session.panels.get("restitution").map(String::as_str), Some("all"));
}

#[test]
fn the_sensitivity_key_opens_the_view_and_a_map_draws_over_two_parameters() {
    let mut h = harness();
    let i = grainscope::scene::SCENES.iter().position(|s| s.id == "hysteresis").expect("scene");
    h.state_mut().apply(Command::OpenScene(i));
    h.run();
    assert!(!h.state().state.matters.open);
    h.key_press(egui::Key::M);
    h.run();
    assert!(h.state().state.matters.open, "M opens the sensitivity view");
    wait_until(&mut h, 60, |a| a.state.matters.result.is_some());
    // The first result of the scene is chosen when none was.
    let output = h.state().state.matters.output.clone();
    assert!(!output.is_empty());
    h.state_mut().apply(Command::DrawSensitivity("surface_energy".into(), "t_vis".into()));
    // Other tests of this binary share the machine's threads: the map's job
    // may wait its turn.
    wait_until(&mut h, 240, |a| a.state.matters.curve.is_some() || a.state.error.is_some());
    let (at, fig) = h.state().state.matters.curve.clone().unwrap_or_else(|| {
        panic!("no map after 240 s: error {:?}, status {:?}", h.state().state.error, h.state().state.status)
    });
    assert_eq!(&at, h.state().params());
    let heat = fig.heatmap.expect("a colour map");
    assert_eq!(heat.values.len(), heat.x.len() * heat.y.len());
    assert_eq!(fig.x.label, "surface energy γ");
}

#[test]
fn an_exported_sensitivity_view_reopens_from_its_file() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut h = harness();
    h.run();
    h.state_mut().apply(Command::SetMatters("v_c".into(), 3.0));
    h.state_mut().apply(Command::WhatMatters);
    h.state_mut().apply(Command::DrawSensitivity("surface_energy".into(), String::new()));
    wait_until(&mut h, 60, |a| a.state.matters.result.is_some() && a.state.matters.curve.is_some());
    h.state_mut().state.session.export_dir = dir.path().display().to_string();
    h.state_mut().apply(Command::ExportSensitivity);
    // The figure renders on the export lane: wait for its files.
    let written = dir.path().join("hysteresis-v_c-sensitivity.png");
    let start = std::time::Instant::now();
    while !written.exists() && start.elapsed() < std::time::Duration::from_secs(60) {
        h.step();
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    let png = std::fs::read_dir(dir.path())
        .expect("folder")
        .flatten()
        .map(|e| e.path())
        .find(|p| p.extension().is_some_and(|x| x == "png"))
        .expect("the curve as PNG");
    assert!(dir.path().join("hysteresis-v_c-what-matters.csv").exists(), "the table");
    // A fresh window opens the file: the scene, the view, its result and curve.
    let mut h = harness();
    h.run();
    let bytes = std::fs::read(&png).expect("read");
    let name = png.display().to_string();
    h.state_mut().apply(Command::OpenBytes(grainscope::app::platform::Picked { name, bytes }));
    h.run();
    wait_until(&mut h, 60, |a| a.state.matters.result.is_some() && a.state.matters.curve.is_some());
    let m = &h.state().state.matters;
    assert!(m.open);
    assert_eq!((m.output.as_str(), m.factor, m.x.as_str(), m.y.as_str()), ("v_c", 3.0, "surface_energy", ""));
}

#[test]
fn what_matters_in_a_heavy_scene_answers_coarsely_first() {
    let mut h = harness();
    h.run();
    let i = grainscope::scene::SCENES.iter().position(|s| s.id == "formation-zone").expect("scene");
    h.state_mut().apply(Command::OpenScene(i));
    // Two disks instead of thirty, so that the test stays short.
    let mut p = h.state().params().clone();
    for (k, v) in [("n_mass", "2"), ("n_z", "1")] {
        p.set(k, v).expect("a documented key");
    }
    h.state_mut().apply(Command::SetParams(Box::new(p)));
    h.state_mut().apply(Command::SetMatters("widest_zone".into(), 2.0));
    h.state_mut().apply(Command::WhatMatters);
    wait_until(&mut h, 120, |a| a.state.matters.result.is_some());
    let s = &h.state().state;
    assert!(s.matters.coarse, "the first answer of a heavy scene is the coarse one");
    let (at, m) = s.matters.result.as_ref().expect("a coarse answer");
    assert_eq!(at, h.state().params(), "the answer belongs to the open parameters");
    assert!(m.rows.iter().any(|r| r.key == "alpha"));
    assert!(h.query_all_by_label_contains("coarse first answer").next().is_some());
    // The full pass runs on; closing the view leaves it be.
    assert!(h.state().busy());
}

/// A platform may start a scene from lighter defaults (a browser's Monte
/// Carlo columns); the scene says so beside its parameters.
#[test]
fn lighter_defaults_are_said() {
    let mut h = harness();
    h.run();
    let i = grainscope::scene::SCENES.iter().position(|s| s.id == "adhesion").expect("a scene");
    let note = "this scene starts at 3 m/s here";
    assert!(h.state_mut().lighten_defaults("adhesion", &[("nonsense", "1")], note).is_err());
    assert!(h.state_mut().lighten_defaults("no-such-scene", &[], note).is_err());
    h.state_mut().lighten_defaults("adhesion", &[("velocity", "3")], note).expect("a known key");
    // A scene at its defaults moves to the lighter ones.
    h.state_mut().apply(Command::OpenScene(i));
    h.run();
    let mut want = grainscope::scene::SceneParams::default_for("adhesion").expect("defaults");
    want.set("velocity", "3").expect("in range");
    assert_eq!(h.state().params(), &want);
    h.get_by_label(note);
}

/// A platform that gives links, as the browser's does.
struct LinkingPlatform(grainscope::app::platform::NullPlatform);

impl grainscope::app::platform::Platform for LinkingPlatform {
    fn pick_file(&mut self, kind: grainscope::app::platform::FileKind) {
        self.0.pick_file(kind)
    }
    fn save_file(&mut self, kind: grainscope::app::platform::FileKind, suggested: &str, bytes: Vec<u8>) {
        self.0.save_file(kind, suggested, bytes)
    }
    fn poll(&mut self) -> Vec<grainscope::app::platform::Answer> {
        self.0.poll()
    }
    fn read(&mut self, name: &str) -> Result<Vec<u8>, String> {
        self.0.read(name)
    }
    fn write(&mut self, name: &str, bytes: &[u8]) -> Result<String, String> {
        self.0.write(name, bytes)
    }
    fn write_all(&mut self, folder: &str, files: &[(String, Vec<u8>)]) -> Result<Vec<String>, String> {
        self.0.write_all(folder, files)
    }
    fn load_session(&mut self) -> grainscope::session::Restored {
        self.0.load_session()
    }
    fn save_session(&mut self, bytes: &[u8]) -> Result<(), String> {
        self.0.save_session(bytes)
    }
    fn now(&self) -> f64 {
        self.0.now()
    }
    fn share_link(&mut self, query: &str) -> Result<grainscope::app::platform::SharedLink, String> {
        let address = format!("https://example.org/grainscope/{query}");
        Ok(grainscope::app::platform::SharedLink { said: format!("link: {address}"), address })
    }
}

#[test]
fn the_link_button_shows_the_address_and_its_code_until_closed() {
    let app = GrainscopeApp::new(egui::Context::default(), Box::new(LinkingPlatform(Default::default())));
    let mut h = Harness::builder()
        .with_size(egui::vec2(1024.0, 768.0))
        .build_ui_state(|ui, app: &mut GrainscopeApp| app.show(ui), app);
    h.run();
    h.get_by_role_and_label(Role::Button, "Link").click();
    h.run();
    let card = h.state().state.link.clone().expect("a link card");
    assert!(card.address.starts_with("https://example.org/grainscope/?"), "{}", card.address);
    assert!(card.modules.is_some());
    h.get_by_label("Link to this state");
    h.get_by_label(&card.address);
    // Escape closes the card first, and nothing else.
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(h.state().state.link.is_none());
    assert!(h.query_by_label("Link to this state").is_none());
}

#[test]
fn the_command_palette_finds_and_runs_an_action_by_name() {
    let mut h = harness_sized(1024.0, 768.0);
    h.run_steps(2);
    // F2 opens it (a key no browser keeps), listing actions with their keys.
    h.key_press(egui::Key::F2);
    h.run_steps(2);
    assert_eq!(h.state().state.palette.as_deref(), Some(""));
    // "Undo" in the top bar and in the palette, beside its keys.
    assert_eq!(h.query_all_by_label("Undo").count(), 2);
    h.get_by_label("Ctrl+Z");
    // Typing narrows the list; Enter runs the first match and closes it.
    h.get_by_role_and_label(Role::TextInput, "Find").type_text("lecture");
    h.run_steps(2);
    assert_eq!(h.query_all_by_label("Undo").count(), 1, "the filter leaves Undo out of the palette");
    h.key_press(egui::Key::Enter);
    h.run_steps(3);
    assert!(h.state().state.session.lecture, "lecture mode is on");
    assert!(h.state().state.palette.is_none());
    // Esc closes it without running anything.
    h.key_press(egui::Key::F2);
    h.run_steps(2);
    assert!(h.state().state.palette.is_some());
    h.key_press(egui::Key::Escape);
    h.run_steps(2);
    assert!(h.state().state.palette.is_none() && h.state().state.session.lecture);
}

/// A deck of twelve cheap slides, to reach slides past 9 by number.
fn twelve_slides() -> grainscope::deck::LoadedDeck {
    let slide = |k: usize| {
        let preset = ["restitution-ice", "ice-bounce-8ms", "adhesion-ice-monomers"][k % 3];
        format!("(title: \"Slide {}\", notes: \"\", preset: Some(\"{preset}\"))", k + 1)
    };
    let slides: Vec<String> = (0..12).map(slide).collect();
    let text = format!("(title: \"Twelve\", slides: [{}])", slides.join(", "));
    grainscope::deck::Deck::from_ron(&text, "twelve", None).expect("deck")
}

fn slide_index(h: &Harness<'static, GrainscopeApp>) -> Option<usize> {
    h.state().state.presenter.as_ref().map(|p| p.index)
}

/// The classroom's tools by key and by button, as a lecturer uses them: a
/// blank screen on B and "." (any key brings it back and does nothing
/// else), a slide past 9 by its number and Enter, the timer, ink drawn on
/// a figure (undone, then gone on the next slide), the pointer, and Esc
/// closing the sensitivity window before anything else.
#[test]
fn the_classroom_tools_work_by_key_and_by_button() {
    let mut h = harness_sized(1024.0, 768.0);
    settle(&mut h);
    h.state_mut().apply(Command::Present(Box::new(twelve_slides()), 0));
    settle(&mut h);
    let tools = |h: &Harness<'static, GrainscopeApp>| h.state().state.classroom.clone();

    // Blank: B, then any key brings the screen back without acting.
    h.key_press(egui::Key::B);
    settle(&mut h);
    assert!(tools(&h).blank);
    h.key_press(egui::Key::ArrowRight);
    settle(&mut h);
    assert!(!tools(&h).blank);
    assert_eq!(slide_index(&h), Some(0), "the key that brought the screen back did nothing else");
    h.key_press(egui::Key::Period);
    settle(&mut h);
    assert!(tools(&h).blank, "a clicker's \".\" blanks the screen");
    h.key_press(egui::Key::Period);
    settle(&mut h);
    assert!(!tools(&h).blank);

    // Slides past 9: the digits, then Enter.
    h.key_press(egui::Key::Num1);
    h.key_press(egui::Key::Num1);
    h.key_press(egui::Key::Enter);
    settle(&mut h);
    assert_eq!(slide_index(&h), Some(10), "slide 11");
    h.key_press(egui::Key::Num1);
    h.key_press(egui::Key::Num0);
    h.key_press(egui::Key::Enter);
    settle(&mut h);
    assert_eq!(slide_index(&h), Some(9), "slide 10");
    h.key_press(egui::Key::Num4);
    settle(&mut h);
    assert_eq!(slide_index(&h), Some(3), "a single digit still jumps at once");
    // A number typed after a pause is a number of its own.
    h.state_mut().apply(Command::Clock(3.0));
    h.key_press(egui::Key::Num9);
    h.key_press(egui::Key::Num9);
    h.key_press(egui::Key::Enter);
    settle(&mut h);
    assert!(h.state().status().contains("no slide 99"), "{}", h.state().status());

    // The timer counts from the deck's start; a countdown shows what is left.
    let before = h.state().state.presenter.as_ref().map_or(0.0, |p| p.elapsed);
    h.state_mut().apply(Command::Clock(75.0));
    h.state_mut().apply(Command::SetCountdown(Some(45.0 * 60.0)));
    h.step();
    let elapsed = h.state().state.presenter.as_ref().map_or(0.0, |p| p.elapsed);
    assert!(elapsed >= before + 75.0 && elapsed < before + 76.0, "{before} → {elapsed}");
    let left = (2700.0 - elapsed).floor() as u64;
    h.get_by_label_contains(&format!("{}:{:02} left", left / 60, left % 60));

    // Ink by its button: a drag over the figure leaves a stroke; U undoes it;
    // a stroke left on the slide is gone on the next one.
    h.get_by_label("Tools").click();
    settle(&mut h);
    h.get_by_label_contains("Ink (I)").click();
    settle(&mut h);
    assert!(tools(&h).ink);
    let frame = h.state().plot_area().expect("a plot");
    let draw = |h: &mut Harness<'static, GrainscopeApp>| {
        let (a, b) = (frame.left_top() + egui::vec2(40.0, 40.0), frame.center());
        h.hover_at(a);
        h.drag_at(a);
        h.step();
        for k in 1..=8 {
            h.hover_at(a + (b - a) * (k as f32 / 8.0));
            h.step();
        }
        h.drop_at(b);
        settle(h);
    };
    draw(&mut h);
    assert_eq!(tools(&h).strokes.len(), 1, "one stroke");
    assert!(tools(&h).strokes[0].points.len() >= 5);
    // The stroke is kept in the axis units of the plot it was drawn on too
    // (exports draw it there).
    let stroke = &tools(&h).strokes[0];
    assert!(!stroke.on.is_empty(), "on a plot");
    assert!(stroke.on.iter().all(|(_, p)| p.len() == stroke.points.len() && p.iter().flatten().all(|v| v.is_finite())));
    h.key_press(egui::Key::U);
    settle(&mut h);
    assert!(tools(&h).strokes.is_empty(), "undone");
    draw(&mut h);
    assert_eq!(tools(&h).strokes.len(), 1);
    h.key_press(egui::Key::I);
    h.key_press(egui::Key::ArrowRight);
    settle(&mut h);
    // (The 9 typed before jumped to slide 9.)
    assert_eq!(slide_index(&h), Some(9));
    assert!(tools(&h).strokes.is_empty(), "ink belongs to its slide");

    // The pointer by its key.
    h.key_press(egui::Key::O);
    settle(&mut h);
    assert!(tools(&h).pointer);

    // Esc closes the sensitivity window first, then leaves the deck.
    h.key_press(egui::Key::Escape);
    settle(&mut h);
    assert!(h.state().state.presenter.is_none());
    h.key_press(egui::Key::M);
    settle(&mut h);
    assert!(h.state().state.matters.open, "the sensitivity window opened");
    h.key_press(egui::Key::Escape);
    settle(&mut h);
    assert!(!h.state().state.matters.open, "Esc closed it");
}

/// The Sensitivity view's study over whole ranges: its runs, filled in share
/// by share, are those of the same design computed by the model (the plan of
/// `grainscope sensitivity`), and so are its Morris measures; its tab shows
/// them with the parameters ranked.
#[test]
fn a_study_over_whole_ranges_gives_the_models_indices() {
    use grainscope::global_sensitivity::{Design, Factor, Method, answer, run_values};
    let mut h = harness();
    h.run();
    let factor = |key: &str, from: f64, to: f64| Factor { key: key.into(), log: true, from, to };
    let design = Design {
        method: Method::Morris { trajectories: 6, levels: 4 },
        factors: vec![factor("velocity", 3.0, 30.0), factor("radius_1", 1e-6, 4e-6)],
        seed: 2015,
    };
    let study = grainscope::sensitivity::WholeRange { design: design.clone(), log_output: false };
    h.state_mut().apply(Command::SetMatters("e".into(), 2.0));
    h.state_mut().apply(Command::MattersWhole(true));
    h.state_mut().apply(Command::SetWholeRange(Box::new(study)));
    h.state_mut().apply(Command::RunWholeRange);
    assert!(h.state().state.matters.whole.running);
    wait_until(&mut h, 240, |a| !a.state.matters.whole.running);
    let params = h.state().state.params().clone();
    let w = &h.state().state.matters.whole;
    assert_eq!(w.values.len(), 18, "error {:?}", h.state().state.error);
    let values = run_values(&params, &design, "e", "", 0..18, &grainscope::scene::Progress::default()).expect("runs");
    assert_eq!(w.values, values);
    let direct = answer(&design, &values, false).expect("a design").expect("enough runs");
    assert_eq!(w.answer.as_ref(), Some(&direct));
    let morris = direct.morris.expect("Morris");
    assert!(morris.iter().all(|m| m.mu_star.is_finite() && m.effects == 6));
    h.run_steps(2);
    h.get_by_label("μ* with its 95 % interval");
    h.get_by_label("Parameters and their ranges");
    h.get_by_label("18 runs analysed; 0 undefined (left out), 0 at a bound (entered at it)");
}

/// A platform's lighter defaults (the browser's Monte Carlo columns) are
/// said while the scene runs at them; a link that sets those parameters
/// wins, and the panel says what it runs instead.
#[test]
fn a_links_parameters_win_over_lighter_defaults_and_are_said() {
    let mut app = new_app();
    let sets = [("runs", "1"), ("groups_per_decade", "14"), ("f_limit", "0.3")];
    app.lighten_defaults("mass-distribution", &sets, "starts lighter").expect("lighter");
    let open = |app: &mut GrainscopeApp, query: &str| match grainscope::links::open(query).expect("link") {
        grainscope::links::Opened::Preset(preset, name) => app.apply(Command::ApplyPreset(preset, name)),
        _ => panic!("{query} opens no preset"),
    };
    open(&mut app, "?scene=mass-distribution&runs=1&groups_per_decade=14&f_limit=0.3");
    assert_eq!(app.state.lighter_note().as_deref(), Some("starts lighter"));
    open(&mut app, "?scene=mass-distribution&groups_per_decade=60&runs=4&f_limit=0.3");
    let p = app.state.params();
    assert_eq!(p.get("groups_per_decade"), Some(60.0.into()));
    assert_eq!(p.get("runs"), Some(4usize.into()));
    let note = app.state.lighter_note().expect("a note");
    assert!(note.starts_with("Runs as set:") && note.contains("runs 4") && note.contains("60"), "{note}");
    assert!(!note.contains("f = 0.3") && !note.contains("starts lighter"), "{note}");
    // A scene without lighter defaults says nothing.
    open(&mut app, "?preset=ice-bounce-8ms");
    assert_eq!(app.state.lighter_note(), None);
}

/// A platform without typed paths (the browser) shows no path fields: no
/// preset path with its Load and Save, no data path, no export folder; the
/// desktop shows them.
#[test]
fn a_platform_without_paths_shows_no_path_fields() {
    let build = |app: GrainscopeApp| {
        let mut h = Harness::builder()
            .with_size(egui::vec2(1400.0, 1000.0))
            .build_ui_state(|ui, app: &mut GrainscopeApp| app.show(ui), app);
        h.run();
        h
    };
    let desktop = build(new_app());
    desktop.get_by_label("Load");
    desktop.get_by_label("export folder");
    let page = build(GrainscopeApp::new(
        egui::Context::default(),
        Box::new(grainscope::app::platform::NullPlatform::default()),
    ));
    page.get_by_label("Open preset…");
    for label in ["Load", "Save", "export folder", "or path", "Load data"] {
        assert!(page.query_by_label(label).is_none(), "{label} is shown");
    }
}

/// A phone's screen (390 × 844 points): the figure takes the width, the
/// parameters wait in a drawer that the bar's "Parameters" opens in place
/// of the figures and closes again; held sideways (844 × 390) as well.
#[test]
fn a_phones_screen_shows_the_figure_across_and_the_parameters_in_a_drawer() {
    for (w, h) in [(390.0, 844.0), (844.0, 390.0)] {
        let mut h = harness_sized(w, h);
        h.run();
        assert!(h.query_by_label("Reset to defaults").is_none(), "{w}: the parameters are out of the way");
        let area = h.state().plot_area().expect("a plot");
        assert!(area.width() > 0.6 * w && area.right() <= w, "{w}: the plots span {area:?}");
        h.get_by(|n| n.role() != Role::Label && n.label().as_deref() == Some("Parameters")).click();
        h.run();
        h.get_by_label("Reset to defaults");
        assert!(h.state().state.drawer);
        h.get_by(|n| n.role() != Role::Label && n.label().as_deref() == Some("Parameters")).click();
        h.run();
        assert!(h.query_by_label("Reset to defaults").is_none(), "{w}: the drawer closes");
    }
}
