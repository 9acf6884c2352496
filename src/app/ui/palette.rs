//! The command palette: every action by its name, with its keys, filtered
//! as one types; Enter runs the first match, a click the one clicked, Esc
//! closes. F2 or the Commands button opens it, on the desktop and in the
//! browser alike. Names, meanings and keys come from the one action table
//! ([`Action::text`], [`shortcuts::SHORTCUTS`]).

use super::Cx;
use crate::app::command::{Action, Command};
use crate::app::shortcuts::{self, Mode};

/// The actions whose name or meaning holds every word of `filter` (any
/// case), best first: the name itself, then names whose words begin with
/// the words typed ("ink" finds Ink before Link), then names that hold
/// them, then meanings; each group in the palette's order. Those of
/// presenting a deck only while `presenting`, those of exploring only
/// while not.
pub fn matching(filter: &str, presenting: bool) -> Vec<Action> {
    let words: Vec<String> = filter.split_whitespace().map(str::to_lowercase).collect();
    let holds = |text: &str| words.iter().all(|w| text.contains(w.as_str()));
    let begins = |name: &str| {
        words.iter().all(|w| name.split(|c: char| !c.is_alphanumeric()).any(|n| n.starts_with(w.as_str())))
    };
    let mut found: Vec<(u8, Action)> = Action::ALL
        .iter()
        .copied()
        // The palette does not offer itself.
        .filter(|a| *a != Action::Palette && a.presenting().is_none_or(|p| p == presenting))
        .filter_map(|a| {
            let t = a.text();
            let name = t.name.to_lowercase();
            let rank = if name.split_whitespace().eq(words.iter().map(String::as_str)) {
                0
            } else if begins(&name) {
                1
            } else if holds(&name) {
                2
            } else {
                3
            };
            holds(&format!("{name} {}", t.does.to_lowercase())).then_some((rank, a))
        })
        .collect();
    found.sort_by_key(|(rank, _)| *rank);
    found.into_iter().map(|(_, a)| a).collect()
}

/// The palette's window, while it is open.
pub fn window(ctx: &egui::Context, cx: &mut Cx<'_>) {
    let Some(filter) = cx.state.palette.clone() else { return };
    let presenting = cx.state.presenter.is_some();
    let mode = if presenting { Mode::Presenter } else { Mode::Explorer };
    let found = matching(&filter, presenting);
    let text_size = super::look::body_size(cx.lecture());
    let mut text = filter;
    let mut run = None;
    let mut close = false;
    // Within the screen at 1024 px in the lecture look too: the meanings
    // are cut to the room left (in full as a tooltip).
    let width = (ctx.content_rect().width() - 48.0).clamp(240.0, 900.0);
    egui::Window::new("Commands")
        .collapsible(false)
        .resizable(false)
        .min_width(width)
        .max_width(width)
        .anchor(egui::Align2::CENTER_TOP, [0.0, 48.0])
        .show(ctx, |ui| {
            let edit = ui
                .horizontal(|ui| {
                    let find = ui.label("Find");
                    ui.add(
                        egui::TextEdit::singleline(&mut text)
                            .hint_text("type a command's name; Enter runs the first")
                            .desired_width((width - 80.0).min(380.0)),
                    )
                    .labelled_by(find.id)
                })
                .inner;
            edit.request_focus();
            if edit.changed() {
                cx.send(Command::SetPalette(Some(text.clone())));
            }
            let (enter, escape) = ui.input(|i| (i.key_pressed(egui::Key::Enter), i.key_pressed(egui::Key::Escape)));
            egui::ScrollArea::vertical().max_height(ctx.content_rect().height() * 0.6).show(ui, |ui| {
                egui::Grid::new("palette").num_columns(3).striped(true).show(ui, |ui| {
                    for (k, a) in found.iter().enumerate() {
                        let t = a.text();
                        let name = egui::RichText::new(t.name).size(text_size);
                        if ui.selectable_label(k == 0, name).on_hover_text(t.does).clicked() {
                            run = Some(*a);
                        }
                        ui.label(egui::RichText::new(shortcuts::keys(*a, mode)).monospace());
                        ui.add(egui::Label::new(egui::RichText::new(t.does).weak()).truncate()).on_hover_text(t.does);
                        ui.end_row();
                    }
                });
            });
            if found.is_empty() {
                ui.label("no command matches");
            }
            if enter {
                run = run.or(found.first().copied());
            }
            close = escape;
        });
    if let Some(a) = run {
        cx.send(Command::SetPalette(None));
        cx.send(Command::Act(a));
    } else if close {
        cx.send(Command::SetPalette(None));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_palette_finds_actions_by_any_word_of_their_text() {
        let all = matching("", false);
        assert!(all.contains(&Action::Undo) && all.contains(&Action::Pin) && !all.contains(&Action::NextSlide));
        assert!(matching("", true).contains(&Action::NextSlide) && !matching("", true).contains(&Action::Pin));
        assert_eq!(matching("undo", false).first(), Some(&Action::Undo));
        // A match in the name comes before one in the meaning.
        assert_eq!(matching("un", false)[..3], [Action::Undo, Action::UndoInk, Action::Redo]);
        assert!(!all.contains(&Action::Palette));
        assert_eq!(matching("LECTURE mode", false), vec![Action::ToggleLecture, Action::Leave]);
        assert_eq!(matching("pinned", false), vec![Action::ClearPins]);
        assert!(matching("no such thing", false).is_empty());
        // Names whose words begin with the words typed come first.
        assert_eq!(matching("ink", false)[..2], [Action::Ink, Action::UndoInk]);
        assert_eq!(matching("ink in exports", false).first(), Some(&Action::InkInExports));
        assert_eq!(matching("start show", true).first(), Some(&Action::StartShow));
    }
}
