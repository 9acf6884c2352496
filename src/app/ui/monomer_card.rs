//! The monomer card: one monomer shared by every scene that builds
//! aggregates, edited in any of them, with what it sets at every scale.

use super::Cx;
use super::controls::{self, Select};
use crate::scene::Scalar;
use crate::scene::monomer;
use crate::units;

/// The card: the monomer's controls and the numbers it sets.
pub fn show(ui: &mut egui::Ui, cx: &mut Cx<'_>) {
    let Some(card) = cx.state.params().monomer_card() else { return };
    let own = cx.state.params().own_monomer();
    let sharing = cx.state.scenes_sharing_monomer();
    let derived = match &cx.memo.card {
        Some((c, values)) if *c == card => values.clone(),
        _ => {
            let values = monomer::scalars(&monomer::monomer_of(&card), true);
            cx.memo.card = Some((card.clone(), values.clone()));
            values
        }
    };
    let system = crate::scene::chapter(cx.state.index()).units();
    egui::Frame::group(ui.style()).show(ui, |ui| {
        let heading =
            if own { "Monomer · this scene's own".to_string() } else { format!("Monomer · shared by {sharing} scenes") };
        ui.label(egui::RichText::new(heading).strong()).on_hover_text(
            "The monomer every aggregate scene builds on: a change here is seen by every scene that shares it",
        );
        controls::show(ui, cx, Select::Card);
        egui::Grid::new("monomer-derived").num_columns(2).spacing([10.0, 2.0]).show(ui, |ui| {
            for s in &derived {
                let label = s.label.trim_start_matches("monomer: ");
                ui.label(label);
                let shown = ui.add(egui::Label::new(value_text(s, system)).wrap());
                if s.value.is_infinite() {
                    shown.on_hover_text(
                        "the ch. 2 model finds no bounce up to 10 km/s: the bulk viscous loss exceeds the rebound, far outside the model's range",
                    );
                }
                ui.end_row();
            }
        });
    });
}

/// A derived value as text, in the units the scene's chapter uses.
fn value_text(s: &Scalar, system: units::System) -> String {
    if s.value.is_infinite() {
        return "none up to 10\u{a0}km/s".into();
    }
    units::text(s.value, s.unit, system)
}
