//! The transport of a scene whose result is a history: rewind, step,
//! play/pause, a scrubber, the time, the speed, loop and (outside the
//! lecture look) the movie export.

use super::Cx;
use crate::app::command::{Action, Command};
use crate::app::playback;
use crate::app::shortcuts::{self, Mode};

/// The transport, when the open scene's result is a history.
pub fn row(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let Some(out) = cx.state.outputs[cx.state.index()].clone() else { return };
    if let Some(c) = cx.state.params().cursor(&out) {
        show(ui, cx, &c.label);
    }
}

fn show(ui: &mut egui::Ui, cx: &mut Cx<'_>, label: &str) {
    let Some(mut t) = cx.state.time() else { return };
    let before = t;
    let state = cx.state;
    let lecture = cx.lecture();
    let mode = if state.presenter.is_some() { Mode::Presenter } else { Mode::Explorer };
    ui.horizontal_wrapped(|ui| {
        if ui.button("|◀").on_hover_text(shortcuts::hint(Action::Rewind, mode)).clicked() {
            cx.send(Command::StopPlaying);
            t = 0.0;
        }
        if ui.button("◀").on_hover_text(shortcuts::hint(Action::StepBack, mode)).clicked() {
            cx.send(Command::StopPlaying);
            t = playback::step(t, -1.0);
        }
        let play = if state.playback.playing { "❚❚ Pause" } else { "▶ Play" };
        if ui.button(play).on_hover_text(shortcuts::hint(Action::PlayPause, mode)).clicked() {
            cx.send(Command::Act(Action::PlayPause));
        }
        if ui.button("▶|").on_hover_text(shortcuts::hint(Action::StepForward, mode)).clicked() {
            cx.send(Command::StopPlaying);
            t = playback::step(t, 1.0);
        }
        let width = if lecture {
            200.0
        } else if cx.memo.compact {
            100.0
        } else {
            160.0
        };
        ui.spacing_mut().slider_width = width;
        let scrub =
            ui.add(egui::Slider::new(&mut t, 0.0..=1.0).show_value(false)).on_hover_text("scrub through the history");
        if scrub.dragged() {
            cx.send(Command::StopPlaying);
        }
        scrub.labelled_by(ui.label(egui::RichText::new(label).monospace()).id);
        let speed_text = |v: f64| match v {
            0.25 => "¼×".to_string(),
            0.5 => "½×".to_string(),
            v => format!("{v}×"),
        };
        let mut speed = state.playback.speed;
        egui::ComboBox::from_label("speed").selected_text(speed_text(speed)).width(60.0).show_ui(ui, |ui| {
            for v in playback::SPEEDS {
                ui.selectable_value(&mut speed, v, speed_text(v));
            }
        });
        if speed != state.playback.speed {
            cx.send(Command::SetSpeed(speed));
        }
        let mut looping = state.playback.looping;
        if ui.checkbox(&mut looping, "loop").changed() {
            cx.send(Command::SetLooping(looping));
        }
        if !lecture {
            let busy = state.movie_running;
            if ui
                .add_enabled(!busy, egui::Button::new(if busy { "Writing movie…" } else { "Movie" }))
                .on_hover_text(shortcuts::hint(Action::Movie, mode))
                .clicked()
            {
                cx.send(Command::Movie);
            }
        }
    });
    if t != before {
        cx.send(Command::SetTime(t));
    }
}
