//! The monomer card: the monomer every aggregate scene shares (radius,
//! material, surface energy, rolling law) and what it sets at every scale.
//! Scenes hold the card's values in their [`DiskParams`]; the registry reads
//! and writes them by key ([`MONOMER_KEYS`]) so that the window can link the
//! card across scenes and the command line can set it with `--set`.

use super::controls::DefaultValue;
use super::core::Scalar;
use super::disk::common::DiskParams;
pub use super::disk::common::{MONOMER_KEYS, ROLLING_LAWS};
use crate::physics::monomer::Monomer;

/// The values of a scene's monomer card, in the order of [`MONOMER_KEYS`].
pub type Card = Vec<DefaultValue>;

/// The monomer the card describes.
pub fn monomer_of(card: &Card) -> Monomer {
    let mut disk = DiskParams::default();
    {
        let d = DiskParams::default();
        let mut controls = disk.controls(&d);
        for (key, value) in MONOMER_KEYS.iter().zip(card) {
            if let Some(c) = controls.iter_mut().find(|c| c.key == *key) {
                c.assign(value);
            }
        }
    }
    disk.monomer()
}

/// What the monomer sets, as scalars: the rolling energy and force, the
/// critical displacement, the energy to break a contact and the
/// fragmentation velocity of (4.12). With `sticking`, also the sticking
/// velocity of two monomers in the ch. 2 collision model (a few
/// milliseconds), else only the elastic JKR one (2.25).
pub fn scalars(m: &Monomer, sticking: bool) -> Vec<Scalar> {
    let mut s = vec![
        Scalar { key: "monomer_E_roll", label: "monomer: rolling energy E_roll", value: m.rolling_energy(), unit: "J" },
        Scalar { key: "monomer_F_roll", label: "monomer: rolling force F_roll", value: m.rolling_force(), unit: "N" },
        Scalar {
            key: "monomer_xi_crit",
            label: "monomer: critical rolling displacement ξ_crit",
            value: m.rolling_displacement(),
            unit: "m",
        },
        Scalar {
            key: "monomer_E_break",
            label: "monomer: energy to break a contact E_break",
            value: m.break_energy(),
            unit: "J",
        },
        Scalar {
            key: "monomer_v_frag",
            label: "monomer: fragmentation velocity (4.12)",
            value: m.fragmentation_velocity(),
            unit: "m s^-1",
        },
        Scalar {
            key: "monomer_v_stick_jkr",
            label: "monomer: JKR sticking velocity (2.25)",
            value: m.jkr_sticking_velocity(),
            unit: "m s^-1",
        },
    ];
    if sticking && let Ok(v) = m.sticking_velocity(1e-3) {
        s.push(Scalar {
            key: "monomer_v_stick",
            label: "monomer: sticking velocity (ch. 2 model)",
            value: v,
            unit: "m s^-1",
        });
    }
    s
}
