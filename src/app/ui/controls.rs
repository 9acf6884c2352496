//! The open scene's controls: sliders with typed value fields, switches and
//! choices. A panel edits a copy of the parameters and reports the copy as
//! one command; a typed value outside its range is refused with a notice.

use super::Cx;
use crate::app::command::{Action, Command, Field};
use crate::app::platform::FileKind;
use crate::figure;
use crate::scene::monomer::MONOMER_KEYS;
use crate::scene::{ControlKind, SceneParams};

/// Which of the open scene's controls to draw.
#[derive(Clone, Copy)]
pub enum Select<'a> {
    /// All but those on the monomer card.
    Parameters,
    /// The monomer card's.
    Card,
    /// A slide's highlighted parameters, side by side.
    Slide(&'a [String]),
}

impl Select<'_> {
    fn id(&self) -> u8 {
        match self {
            Select::Parameters => 0,
            Select::Card => 1,
            Select::Slide(_) => 2,
        }
    }
}

/// The measurements of a scene that takes them: count, clear, import.
fn measurements(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let Some(n) = cx.state.params().clone().measurements().map(|d| d.len()) else { return };
    ui.horizontal(|ui| {
        ui.label(if n == 0 { "data: synthetic example".to_string() } else { format!("data: {n} measurements") });
        if n > 0 && ui.button("Clear data").clicked() {
            cx.send(Command::ClearData);
        }
    });
    ui.horizontal(|ui| {
        if ui
            .button("Import data…")
            .on_hover_text("CSV: 'velocity [m/s]', 'restitution', optional 'uncertainty'; or drop a .csv on the window")
            .clicked()
        {
            cx.send(Command::Pick(FileKind::Measurements));
        }
        if cx.state.paths {
            let label = ui.label("or path");
            let mut path = cx.state.session.data_path.clone();
            if ui.text_edit_singleline(&mut path).labelled_by(label.id).changed() {
                cx.send(Command::SetText(Field::DataPath, path));
            }
            if ui.button("Load data").clicked() {
                cx.send(Command::LoadDataPath);
            }
        }
    });
}

/// The open scene's controls: all but the monomer card's, the card's, or
/// only those of a slide (its highlighted parameters, side by side).
pub fn show(ui: &mut egui::Ui, cx: &mut Cx<'_>, select: Select<'_>) {
    let only = match select {
        Select::Slide(keys) => Some(keys),
        _ => None,
    };
    let state = cx.state;
    let card_keys = state.params().monomer_card().map(|_| shown_keys(state.params()));
    let shown = |key: &str| match select {
        Select::Slide(keys) => keys.iter().any(|k| k == key),
        Select::Card => card_keys.as_ref().is_some_and(|k| k.contains(&key)),
        Select::Parameters => !is_card_key(key) || card_keys.is_none(),
    };
    if matches!(select, Select::Parameters) {
        measurements(ui, cx);
    }
    let mut material_changed = false;
    // A refused typed value: shown under its control until the control
    // takes a valid value (or another is refused).
    let shown_notice = state.control_notice.clone();
    let mut refused: Option<(String, String)> = None;
    let mut accepted: Option<String> = None;
    let mut params = state.params().clone();
    {
        let mut controls = params.controls();
        // A slide's few highlighted controls sit side by side, wrapping to a
        // second line rather than cutting their labels.
        let in_row = only.is_some();
        let mut body = |ui: &mut egui::Ui| {
            for c in controls.iter_mut().filter(|c| shown(c.key)) {
                let (key, label, unit, doc) = (c.key, c.label, c.unit, c.doc);
                if in_row {
                    // A control that would not fit the rest of the line starts
                    // the next one (egui would cut its label instead).
                    let font = egui::TextStyle::Body.resolve(ui.style());
                    let text = ui.painter().layout_no_wrap(label.to_string(), font, egui::Color32::WHITE).size().x;
                    let need = text + ui.spacing().slider_width + 120.0;
                    if ui.available_size_before_wrap().x < need {
                        ui.end_row();
                    }
                }
                match &mut c.kind {
                    ControlKind::Number { value, min, max, log, display_scale } => {
                        let mut shown = **value * *display_scale;
                        let (lo, hi) = (*min * *display_scale, *max * *display_scale);
                        let is_log = *log;
                        let shown_unit = crate::units::pretty(unit);
                        let suffix = if unit.is_empty() { String::new() } else { format!(" {shown_unit}") };
                        let current = shown;
                        let slider = egui::Slider::new(&mut shown, lo..=hi).logarithmic(is_log).suffix(suffix.clone());
                        let (changed, typed) =
                            typed_slider(ui, slider, current, label, doc, unit, |v| field_text(v, is_log));
                        // The range is checked in SI units, with a rounding allowance
                        // for the conversion to display units.
                        let si = shown / *display_scale;
                        let slack = 1e-12 * min.abs().max(max.abs());
                        let typed_error = typed.as_deref().and_then(|t| crate::units::parse_in(t, unit).err());
                        if changed && si.is_finite() && si >= *min - slack && si <= *max + slack {
                            **value = si.clamp(*min, *max);
                            accepted = Some(key.to_string());
                        } else if changed || typed_error.is_some() {
                            let text = typed.unwrap_or_else(|| format!("{}{suffix}", figure::human(shown)));
                            let why = match typed_error {
                                Some(e) => format!("is refused: {e}; valid range"),
                                None => "is outside the valid range".to_string(),
                            };
                            refused = Some((
                                key.to_string(),
                                format!(
                                    "{label}: {text} {why} {} … {}{suffix}; kept {}{suffix}",
                                    figure::human(lo),
                                    figure::human(hi),
                                    figure::human(**value * *display_scale),
                                ),
                            ));
                        }
                    }
                    ControlKind::Count { value, min, max } => {
                        let mut shown = **value as f64;
                        let current = shown;
                        let slider = egui::Slider::new(&mut shown, *min as f64..=*max as f64).integer();
                        let (changed, typed) = typed_slider(ui, slider, current, label, doc, "", |v| format!("{v:.0}"));
                        // The widget rounds to whole numbers; what was typed decides.
                        let typed_whole = typed.as_deref().and_then(parse_number).is_none_or(|v| v.fract() == 0.0);
                        let whole = shown.is_finite() && shown.fract() == 0.0 && typed_whole;
                        if changed && whole && shown >= *min as f64 && shown <= *max as f64 {
                            **value = shown as usize;
                            accepted = Some(key.to_string());
                        } else if changed || typed.as_deref().is_some_and(|t| parse_number(t).is_none() || !typed_whole)
                        {
                            let text = typed.unwrap_or_else(|| shown.to_string());
                            refused = Some((
                                key.to_string(),
                                format!(
                                    "{label}: {text} is not a whole number in the valid range {min} … {max}; kept {}",
                                    **value
                                ),
                            ));
                        }
                    }
                    ControlKind::Toggle(v) => {
                        ui.checkbox(v, label).on_hover_text(doc);
                    }
                    ControlKind::Material(m) => {
                        egui::ComboBox::from_label(label).selected_text(m.name.clone()).show_ui(ui, |ui| {
                            for candidate in crate::physics::material::materials() {
                                if ui.selectable_label(m.name == candidate.name, &candidate.name).clicked() {
                                    **m = candidate.clone();
                                    material_changed = true;
                                }
                            }
                        });
                    }
                    ControlKind::Choice { value, options } => {
                        let shown = options.iter().find(|(k, _)| *k == value.key()).map_or("?", |(_, l)| *l);
                        egui::ComboBox::from_label(label).selected_text(shown).show_ui(ui, |ui| {
                            for (k, l) in options.iter() {
                                if ui.selectable_label(value.key() == *k, *l).clicked() {
                                    value.set_key(k);
                                }
                            }
                        });
                    }
                }
                if !in_row {
                    ui.end_row();
                }
                if let Some((k, message)) = &shown_notice
                    && k == key
                    && accepted.as_deref() != Some(key)
                {
                    ui.add(egui::Label::new(egui::RichText::new(message).color(ui.visuals().warn_fg_color)).wrap());
                    ui.end_row();
                }
            }
        };
        if in_row {
            // The caller's line wraps (a slide's headline row).
            body(ui);
        } else {
            egui::Grid::new(("controls", select.id())).num_columns(1).striped(false).show(ui, |ui| body(ui));
        }
    }
    if material_changed {
        params.material_changed();
    }
    if &params != state.params() {
        cx.send(Command::SetParams(Box::new(params)));
    }
    if let Some((key, message)) = refused {
        cx.send(Command::Refuse { key, message });
    } else if let Some(key) = accepted {
        cx.send(Command::Accept(key));
    }
    if matches!(select, Select::Parameters)
        && ui
            .button("Reset to defaults")
            .on_hover_text(crate::app::shortcuts::hint(Action::ResetScene, crate::app::shortcuts::Mode::Explorer))
            .clicked()
    {
        cx.send(Command::Act(crate::app::command::Action::ResetScene));
    }
}

/// Adds `slider` with its value field made for typing: typed text is taken
/// only on Enter (or leaving the field) and not clamped, so the caller can
/// refuse an out-of-range value with a notice; the field's own text of
/// `current`, left unedited, keeps the exact value (`text_of` formats the
/// field). Returns whether the value changed and the text typed, if any.
fn typed_slider(
    ui: &mut egui::Ui,
    slider: egui::Slider<'_>,
    current: f64,
    label: &str,
    doc: &str,
    unit: &str,
    text_of: impl Fn(f64) -> String + Copy,
) -> (bool, Option<String>) {
    let typed = std::cell::RefCell::new(None::<String>);
    let changed = {
        let slider = slider
            .text(label)
            .clamping(egui::SliderClamping::Never)
            .update_while_editing(false)
            .custom_formatter(move |v, _| text_of(v))
            .custom_parser(|text| {
                if text.trim() == text_of(current) {
                    // Left as shown: no change from the field's rounding.
                    return Some(current);
                }
                *typed.borrow_mut() = Some(text.trim().to_string());
                crate::units::parse_in(text, unit).ok()
            });
        ui.add(slider).on_hover_text(doc).changed()
    };
    (changed, typed.into_inner())
}

/// The text of a value field: powers of ten on logarithmic sliders, four
/// significant digits on linear ones.
fn field_text(v: f64, log: bool) -> String {
    let a = v.abs();
    if log && (a >= 1e4 || (a > 0.0 && a < 1e-2)) && a.is_finite() {
        // Decades as powers of ten: "10⁴", "2.5×10⁻⁷".
        let e = a.log10().floor() as i32;
        let m = figure::human(v / 10f64.powi(e));
        match m.as_str() {
            "1" => figure::ticks::power_of_ten(e),
            "−1" => format!("−{}", figure::ticks::power_of_ten(e)),
            "10" => figure::ticks::power_of_ten(e + 1),
            _ => format!("{m}×10{}", figure::ticks::superscript(e)),
        }
    } else if log {
        figure::human(v)
    } else if v == 0.0 || !v.is_finite() {
        format!("{v}")
    } else if (1e-3..1e5).contains(&a) {
        let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
    } else {
        format!("{v:.3e}").replace(".000e", "e")
    }
}

/// Reads a whole number as typed into a count field ("−" as minus).
fn parse_number(text: &str) -> Option<f64> {
    crate::units::parse_in(text, "").ok()
}

/// Whether `key` is edited on the card rather than among the parameters.
pub fn is_card_key(key: &str) -> bool {
    MONOMER_KEYS.contains(&key) || key == "own_monomer"
}

/// The card's controls that apply to the scene's current monomer: the
/// surface energy of its material and the parameter of its rolling law.
pub fn shown_keys(params: &SceneParams) -> Vec<&'static str> {
    use crate::physics::monomer::RollingLaw;
    let m = params.monomer();
    let icy = m.is_none_or(|m| m.icy);
    let mut keys = vec![
        "monomer_radius",
        "icy",
        if icy { "surface_energy_ice" } else { "surface_energy_silicate" },
        "rolling_law",
    ];
    match m.map(|m| m.rolling) {
        Some(RollingLaw::Contact { .. }) => keys.push("hysteresis"),
        Some(RollingLaw::DominikTielens { .. }) => keys.push("xi_crit"),
        _ => {}
    }
    keys.push("own_monomer");
    keys
}
