//! The monomer card: one monomer shared by every scene that builds
//! aggregates, edited in any of them, with what it sets at every scale.

use super::{GrainscopeApp, Select};
use crate::figure;
use crate::scene::monomer::{self, Card, MONOMER_KEYS};
use crate::scene::{SCENES, Scalar, SceneParams};

/// Whether `key` is edited on the card rather than among the parameters.
pub(super) fn is_card_key(key: &str) -> bool {
    MONOMER_KEYS.contains(&key) || key == "own_monomer"
}

/// The card's controls that apply to the scene's current monomer: the
/// surface energy of its material and the parameter of its rolling law.
pub(super) fn shown_keys(params: &SceneParams) -> Vec<&'static str> {
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

/// What the card shows and the link between scenes.
#[derive(Default)]
pub(super) struct MonomerLink {
    /// The open scene and its card in the last frame: a change within the
    /// same scene is an edit to share.
    seen: Option<(usize, Option<Card>)>,
    /// The derived values of the last card shown.
    derived: Option<(Card, Vec<Scalar>)>,
}

impl GrainscopeApp {
    /// The card: the monomer's controls and the numbers it sets.
    pub(super) fn monomer_card(&mut self, ui: &mut egui::Ui) {
        let Some(card) = self.params().monomer_card() else { return };
        let own = self.params().own_monomer();
        let sharing = self.scenes_sharing_monomer();
        let derived = match &self.monomer_link.derived {
            Some((c, values)) if *c == card => values.clone(),
            _ => {
                let values = monomer::scalars(&monomer::monomer_of(&card), true);
                self.monomer_link.derived = Some((card.clone(), values.clone()));
                values
            }
        };
        egui::Frame::group(ui.style()).show(ui, |ui| {
            let heading = if own {
                "Monomer · this scene's own".to_string()
            } else {
                format!("Monomer · shared by {sharing} scenes")
            };
            ui.label(egui::RichText::new(heading).strong()).on_hover_text(
                "The monomer every aggregate scene builds on: a change here is seen by every scene that shares it",
            );
            self.controls_of(ui, Select::Card);
            egui::Grid::new("monomer-derived").num_columns(2).spacing([10.0, 2.0]).show(ui, |ui| {
                for s in &derived {
                    let label = s.label.trim_start_matches("monomer: ");
                    ui.small(label);
                    let shown = ui.add(egui::Label::new(egui::RichText::new(value_text(s)).small()).wrap());
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

    /// How many scenes share the monomer (have a card and keep no own monomer).
    fn scenes_sharing_monomer(&self) -> usize {
        (0..SCENES.len())
            .filter(|&k| self.params_of(k).monomer_card().is_some() && !self.params_of(k).own_monomer())
            .count()
    }

    /// Shares an edit of the open scene's monomer with every linked scene.
    /// Called once a frame, after the controls were drawn.
    pub(super) fn link_monomer(&mut self) {
        let i = self.session.index();
        let card = self.params().monomer_card();
        let previous = self.monomer_link.seen.replace((i, card.clone()));
        let (Some(card), false) = (card, self.params().own_monomer()) else { return };
        if let Some((j, Some(before))) = previous
            && j == i
            && before != card
        {
            self.share_monomer(i, &card);
        }
    }

    /// Gives every other scene that shares the monomer the card `card`;
    /// returns how many changed.
    pub(super) fn share_monomer(&mut self, from: usize, card: &Card) -> usize {
        let mut changed = 0;
        for (k, info) in SCENES.iter().enumerate() {
            if k == from {
                continue;
            }
            let mut q = self.params_of(k).clone();
            if q.own_monomer() || q.monomer_card().is_none_or(|c| c == *card) {
                continue;
            }
            if q.set_monomer_card(card) {
                self.session.params.insert(info.id.to_string(), q);
                changed += 1;
            }
        }
        changed
    }
}

/// A derived value as text: SI with its unit, and erg for the energies.
fn value_text(s: &Scalar) -> String {
    if s.value.is_infinite() {
        return "none up to 10 km/s".into();
    }
    let unit = match s.unit {
        "m s^-1" => "m/s",
        u => u,
    };
    let main = format!("{} {unit}", figure::human(s.value));
    match s.unit {
        "J" => format!("{main} ({} erg)", figure::human(s.value * 1e7)),
        "m" => format!("{} nm", figure::human(s.value * 1e9)),
        _ => main,
    }
}
