//! Scene "Midplane loading" (thesis Fig. 5.15): the largest midplane
//! dust-to-gas ratio allowed by the turbulence that settled dust drives itself.

use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::batches::{alpha_midplane, max_loading};
use crate::physics::constants::AU;
use crate::physics::disk::{GasDisk, Profile};
use crate::scene::core::{Context, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the midplane-loading scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// first metallicity of settled particles
    #[param(figure_only, label = "smallest Z* / solar", range(0.1, 20.0), log, default = 0.5)]
    pub z_min_solar: f64,
    /// last metallicity
    #[param(figure_only, label = "largest Z* / solar", range(0.1, 20.0), log, default = 5.0)]
    pub z_max_solar: f64,
    /// log-spaced
    #[param(figure_only, label = "metallicities", range(1.0, 8.0), default = 4)]
    pub n_z: usize,
    /// mass of the three disks
    #[param(quantity = quantities::disk_mass, default = 0.01)]
    pub disk_mass: f64,
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "midplane-loading",
        title: "Midplane loading",
        source: "Sect. 5.4.4; Eqs. 5.16, 5.17; Fig. 5.15",
        explanation: "Settled particles stir the midplane through Kelvin–Helmholtz and streaming \
instabilities, α_mp = [(C₁C_eff ηZ)^{-2/3} + (C₂C_eff η/Z)^{-2}]⁻¹ Ωt_s (5.16). With α ≥ α_mp the \
midplane dust-to-gas ratio of particles with 10⁻² ≤ Ωt_s ≤ 1 is at most Z*(Ωt_s/α_mp)^{1/2} (5.17), \
which no longer depends on Ωt_s: only on η and Z*. Three disks as in Fig. 5.15: an MMSN-like power \
law (γ = 3/2, R_c = 30 AU), a shallower extended one (γ = 1, R_c = 100 AU) and the same cold. Lines \
for Z* = 0.5–5 times solar (0.01); streaming instability needs a loading near 1 (dotted).",
        heavy: false,
    };

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let disks = [
            (
                "MMSN-like (γ = 3/2, R_c = 30 AU)",
                Profile::TruncatedPowerLaw { mass: p.disk_mass, r_c: 30.0, slope: 1.5 },
                false,
            ),
            (
                "extended (γ = 1, R_c = 100 AU)",
                Profile::TruncatedPowerLaw { mass: p.disk_mass, r_c: 100.0, slope: 1.0 },
                false,
            ),
            ("extended, cold", Profile::TruncatedPowerLaw { mass: p.disk_mass, r_c: 100.0, slope: 1.0 }, true),
        ];
        let zs: Vec<f64> = if p.n_z <= 1 {
            vec![p.z_min_solar]
        } else {
            logspace(p.z_min_solar, p.z_max_solar.max(p.z_min_solar * 1.000001), p.n_z)
        };
        let rs = logspace(1.0, 200.0, 80);
        let mut figures = Vec::new();
        let mut scalars = Vec::new();
        for (d, (name, profile, cold)) in disks.iter().enumerate() {
            let disk = GasDisk { profile: *profile, cold: *cold, alpha: 1e-3, metallicity: 0.01 };
            let mut fig = Figure::new(
                &format!("midplane-loading-{}", d + 1),
                &format!("Largest midplane ρ*/ρ_g: {name}"),
                Axis::log("radius R", "AU"),
                Axis::log("(ρ*_d/ρ_g) at z = 0", ""),
            );
            for (k, zsol) in zs.iter().enumerate() {
                let z = zsol * 0.01;
                let pts = rs.iter().map(|&r| [r, max_loading(disk.eta(r * AU), z)]).collect();
                fig = fig.with(Series::new(format!("Z* = {}", crate::figure::human(z)), pts, Style::Line, k));
            }
            fig = fig.with(Series::new("loading = 1", vec![[1.0, 1.0], [200.0, 1.0]], Style::Dashed, 6));
            figures.push(fig);
            if d == 0 {
                let eta = disk.eta(AU);
                scalars.push(Scalar {
                    key: "alpha_kh_st001",
                    label: "α_mp at 1 AU, Ωt_s = 0.01, Z = 0.01",
                    value: alpha_midplane(eta, 0.01, 1e-2),
                    unit: "",
                });
                scalars.push(Scalar {
                    key: "alpha_kh_st1",
                    label: "α_mp at 1 AU, Ωt_s = 1, Z = 0.01",
                    value: alpha_midplane(eta, 0.01, 1.0),
                    unit: "",
                });
            }
        }
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures,
            notes: Vec::new(),
            extra: crate::scene::core::Extra::None,
        })
    }
}
