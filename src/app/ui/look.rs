//! The window's look: theme and text sizes for the ordinary and the lecture
//! look, the bundled font, and how plots are drawn in each.

use super::Memo;
use super::plot;
use crate::figure;
use std::sync::Arc;

/// Applies the theme and text sizes: lecture mode is light, high-contrast
/// and large; otherwise the chosen light or dark theme at normal size.
pub fn apply(ctx: &egui::Context, memo: &mut Memo, lecture: bool, light: bool) {
    if !memo.fonts_installed {
        memo.fonts_installed = true;
        install_fonts(ctx);
    }
    let compact = memo.compact;
    let want = (lecture, light, compact);
    if memo.look_applied == Some(want) {
        return;
    }
    let lecture_changed = memo.look_applied.is_none_or(|(l, _, _)| l != want.0);
    memo.look_applied = Some(want);
    let light = want.0 || want.1;
    ctx.set_theme(if light { egui::Theme::Light } else { egui::Theme::Dark });
    ctx.all_styles_mut(|style| {
        use egui::{FontFamily, FontId, TextStyle};
        // Lecture: body ≥ 18 px for a projector; normal: body ≥ 14 px.
        let sizes = if lecture { [16.0, 19.0, 19.0, 26.0, 17.0] } else { [12.0, 14.0, 14.0, 20.0, 13.0] };
        style.text_styles = [
            (TextStyle::Small, FontId::new(sizes[0], FontFamily::Proportional)),
            (TextStyle::Body, FontId::new(sizes[1], FontFamily::Proportional)),
            (TextStyle::Button, FontId::new(sizes[2], FontFamily::Proportional)),
            (TextStyle::Heading, FontId::new(sizes[3], FontFamily::Proportional)),
            (TextStyle::Monospace, FontId::new(sizes[4], FontFamily::Monospace)),
        ]
        .into();
        style.spacing.interact_size.y = if lecture || compact { 26.0 } else { 18.0 };
        // On a phone a swipe scrolls; it does not select the text it starts on.
        style.interaction.selectable_labels = !compact;
    });
    if lecture {
        // High contrast: black text on white, strong strokes.
        ctx.style_mut_of(egui::Theme::Light, |style| {
            style.visuals.override_text_color = Some(egui::Color32::BLACK);
            style.visuals.widgets.noninteractive.fg_stroke.color = egui::Color32::BLACK;
            style.visuals.panel_fill = egui::Color32::WHITE;
            style.visuals.extreme_bg_color = egui::Color32::WHITE;
        });
    } else {
        ctx.style_mut_of(egui::Theme::Light, |style| style.visuals = egui::Visuals::light());
    }
    // Labels and tick numbers light on the dark theme, not mid-grey on black.
    ctx.style_mut_of(egui::Theme::Dark, |style| {
        style.visuals.widgets.noninteractive.fg_stroke.color = egui::Color32::from_gray(215);
    });
    ctx.set_zoom_factor(1.0);
    if lecture_changed {
        ctx.send_viewport_cmd(egui::ViewportCommand::Fullscreen(lecture));
    }
}

/// The size of text set explicitly beside figures (tabs, cards, tables):
/// 18 px for a lecture hall, 14 px otherwise.
pub fn body_size(lecture: bool) -> f32 {
    if lecture { 18.0 } else { 14.0 }
}

/// How plots are drawn in the current look.
pub fn plot_look(ui: &egui::Ui, lecture: bool) -> plot::Look {
    plot::Look {
        line: if lecture { 3.0 } else { 2.0 },
        text: if lecture { 18.0 } else { 14.0 },
        dark: ui.visuals().dark_mode,
        legend: true,
    }
}

/// Makes the bundled DejaVu Sans the first proportional font, so every
/// figure label has its glyphs: powers of ten, arrows, Greek letters,
/// subscripts. egui's own fonts (feature `egui-fonts`) stay as fallbacks and
/// as the monospace font; without them DejaVu Sans is the only font.
fn install_fonts(ctx: &egui::Context) {
    let mut fonts = egui::FontDefinitions::default();
    fonts.font_data.insert("dejavu-sans".into(), Arc::new(egui::FontData::from_static(figure::font_ttf())));
    fonts.families.entry(egui::FontFamily::Proportional).or_default().insert(0, "dejavu-sans".into());
    fonts.families.entry(egui::FontFamily::Monospace).or_default().push("dejavu-sans".into());
    ctx.set_fonts(fonts);
}
