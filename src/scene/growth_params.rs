//! Parameters shared by the growth scenes: the semi-analytical model.

use super::controls::Control;
use super::disk_params::DiskParams;
use crate::physics::aggregate::{Thresholds, TurbulenceModel};
use crate::physics::constants::AU;
use crate::physics::growth::{GrowthModel, Porosity};
use serde::{Deserialize, Serialize};

/// The semi-analytical growth model. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct GrowthParams {
    /// Disk and monomers.
    pub disk: DiskParams,
    /// Fragmentation velocity, m s⁻¹ (default: (4.12) for ice, 10 for compact tracks).
    pub v_frag: f64,
    /// Erosion threshold, m s⁻¹ (default 10⁴: no erosion).
    pub v_eros: f64,
    /// Bouncing threshold of compact grains, m s⁻¹ (default 10⁴: none).
    pub v_bounce: f64,
    /// Use the full Ormel & Cuzzi turbulence form.
    pub ormel_cuzzi: bool,
    /// Include Newton drag.
    pub newton: bool,
    /// Growth per step, Δln m (default 0.1).
    pub dlnm: f64,
}

impl Default for GrowthParams {
    fn default() -> Self {
        GrowthParams {
            disk: DiskParams::default(),
            v_frag: 80.0,
            v_eros: 1e4,
            v_bounce: 1e4,
            ormel_cuzzi: false,
            newton: true,
            dlnm: 0.1,
        }
    }
}

impl GrowthParams {
    /// The documented parameters.
    pub fn controls(&mut self) -> Vec<Control<'_>> {
        let mut c = self.disk.controls();
        let v = ("m/s", 1.0);
        c.push(Control::number(
            "v_frag",
            "fragmentation velocity",
            &mut self.v_frag,
            "m s^-1",
            (0.1, 1e4),
            true,
            v,
            "same-size collisions above it fragment (80 m/s for 0.1 µm ice)",
        ));
        c.push(Control::number(
            "v_eros",
            "erosion threshold",
            &mut self.v_eros,
            "m s^-1",
            (0.1, 1e4),
            true,
            v,
            "collisions with monomers above it erode (1e4: none)",
        ));
        c.push(Control::number(
            "v_bounce",
            "bouncing threshold",
            &mut self.v_bounce,
            "m s^-1",
            (0.01, 1e4),
            true,
            v,
            "compact grains bounce above it (1e4: none)",
        ));
        c.push(Control::toggle(
            "ormel_cuzzi",
            "Ormel & Cuzzi form",
            &mut self.ormel_cuzzi,
            "full turbulence closed form",
        ));
        c.push(Control::toggle("newton", "Newton drag", &mut self.newton, "include Re_p > 1 drag"));
        c.push(Control::number(
            "dlnm",
            "step Δln m",
            &mut self.dlnm,
            "",
            (0.01, 1.0),
            true,
            ("", 1.0),
            "mass growth per step",
        ));
        c
    }

    /// The model with a given porosity treatment.
    pub fn model(&self, porosity: Porosity) -> GrowthModel {
        let mut m = GrowthModel::chapter4(porosity);
        m.disk = self.disk.disk();
        m.monomer = self.disk.monomer();
        m.thresholds = Thresholds { v_frag: self.v_frag, v_eros: self.v_eros, v_bounce: self.v_bounce, r_crit: 1e-2 };
        m.turbulence = if self.ormel_cuzzi { TurbulenceModel::OrmelCuzzi } else { TurbulenceModel::Thesis };
        m.newton = self.newton;
        m.dlnm = self.dlnm;
        m.inner_edge = AU;
        m
    }
}
