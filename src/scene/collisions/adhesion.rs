//! Scene "Adhesive contact basics" (thesis Sect. 1.3.3, Table 1.1): the JKR
//! contact of two equal monomers, its characteristic energies, and the
//! collision regimes of aggregates.

use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::contact::Pair;
use crate::physics::material::combined_surface_energy;
use crate::physics::material::{Material, combined_modulus};
use crate::scene::core::{
    Context, Declared, Irregularity, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace,
};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the adhesion scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// monomer material (Table 2.2)
    #[param(label = "material", default = Material::water_ice())]
    pub material: Material,
    /// radius of one monomer
    #[param(label = "monomer radius r₀", unit = "m", shown("µm", 1e6), range(1e-8, 1e-2), log, default = 1e-7)]
    pub radius: f64,
    /// combined surface energy (2γ_L; default 0.74)
    #[param(quantity = quantities::surface_energy, default = 0.74)]
    pub surface_energy: f64,
    /// range of surface forces
    #[param(quantity = quantities::force_range, default = 3e-10)]
    pub z0: f64,
    /// critical rolling displacement
    #[param(label = "rolling displacement ξ", unit = "m", shown("nm", 1e9), range(1e-11, 1e-8), log, default = 1e-10)]
    pub xi: f64,
    /// monomers in each of two equal aggregates
    #[param(label = "monomers per aggregate N", range(1.0, 1e9), log, default = 100.0)]
    pub monomers: f64,
    /// contacts in the colliding pair
    #[param(label = "contacts n_c", range(1.0, 1e9), log, default = 100.0)]
    pub contacts: f64,
    /// relative velocity of the aggregates
    #[param(label = "aggregate velocity v", unit = "m s^-1", shown("m/s", 1.0), range(1e-4, 1e3), log, default = 1.0)]
    pub velocity: f64,
}

impl Params {
    /// The monomer pair (two equal spheres).
    pub fn pair(&self, radius: f64) -> Pair {
        let m = crate::physics::sphere_mass(self.material.density, radius);
        Pair {
            modulus: combined_modulus(&self.material, &self.material),
            radius: radius / 2.0,
            mass: m / 2.0,
            surface_energy: self.surface_energy,
        }
    }
}

/// The collision regime of Table 1.1 for collision energy `e_k` (J).
pub fn regime(e_k: f64, e_roll: f64, e_break: f64, n_c: f64) -> &'static str {
    if e_k > 10.0 * n_c * e_break {
        "catastrophic disruption"
    } else if e_k > n_c * e_break {
        "loss of some monomers"
    } else if e_k >= n_c * e_roll {
        "maximum compression"
    } else if e_k > 5.0 * e_roll {
        "onset of compaction"
    } else {
        "sticking without restructuring"
    }
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "adhesion",
        title: "Adhesive contact basics",
        source: "Sect. 1.3.3, Table 1.1",
        explanation: "Two equal monomers of radius r₀ (reduced radius R = r₀/2) in JKR contact: \
equilibrium radius a_eq = (9πγR²/(2E*))^{1/3}, pull-off force F_c = (3/2)πγR, the energy to break \
a contact E_break ~ (γ⁵R⁴/E*²)^{1/3} (the thesis prints E*³ in (1.24), which is not an energy) \
and to roll over 90°, E_roll = 6πγRξ (1.25). Head-on monomers stick when ½m*v² < E_break, so \
v_stick ~ R^{-5/6}; (2.25) gives the JKR sticking velocity with its prefactor. The Tabor \
parameter μ = (Rγ²/(E*²z₀³))^{1/3} > 5 puts the contact in the JKR limit. For aggregates with \
n_c contacts, Dominik & Tielens' regimes (Table 1.1) compare the collision energy with \
    5E_roll, n_cE_roll, n_cE_break and 10n_cE_break.",
        heavy: false,
    };

    const DECLARED: &'static [Declared] = &[Declared {
        scalar: "*",
        parameter: "contacts",
        kind: Irregularity::Ignored,
        why: "n_c sets the aggregates' energy drawn against velocity; the scalars are per monomer contact",
        resolution: None,
    }];

    fn material_changed(&mut self) {
        self.surface_energy = combined_surface_energy(&self.material, &self.material);
    }

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let pair = p.pair(p.radius);
        let e_break = pair.break_energy();
        let e_roll = pair.roll_energy(p.xi);
        let v_break = (2.0 * e_break / pair.mass).sqrt();
        let m0 = 2.0 * pair.mass;
        // Two equal aggregates of N monomers: reduced mass N m₀ / 2.
        let e_k = 0.5 * (p.monomers * m0 / 2.0) * p.velocity.powi(2);
        let regime = regime(e_k, e_roll, e_break, p.contacts);

        let radii = logspace(1e-8, 1e-2, 61);
        let fig_v = Figure::new(
            "monomer-sticking-velocity",
            "Monomer sticking velocity",
            Axis::log("monomer radius r₀", "µm"),
            Axis::log("sticking velocity", "m/s"),
        )
        .with(Series::new(
            "v_c, JKR (2.25)",
            radii.iter().map(|&r| [r * 1e6, p.pair(r).jkr_sticking_velocity()]).collect(),
            Style::Line,
            0,
        ))
        .with(Series::new(
            "√(2E_break/m*)",
            radii
                .iter()
                .map(|&r| {
                    let q = p.pair(r);
                    [r * 1e6, (2.0 * q.break_energy() / q.mass).sqrt()]
                })
                .collect(),
            Style::Dashed,
            1,
        ))
        .with(Series::new(
            "this monomer",
            vec![[p.radius * 1e6, pair.jkr_sticking_velocity()]],
            Style::Marker,
            3,
        ));

        let nc = logspace(1.0, 1e9, 73);
        let line = |name: &str, f: &dyn Fn(f64) -> f64, color| {
            Series::new(name, nc.iter().map(|&n| [n, f(n)]).collect(), Style::Line, color)
        };
        let fig_r = Figure::new(
            "collision-regimes",
            "Collision regimes (Table 1.1)",
            Axis::log("contacts n_c", ""),
            Axis::log("collision energy", "J"),
        )
        .with(line("5 E_roll: onset of compaction", &|_| 5.0 * e_roll, 2))
        .with(line("n_c E_roll: maximum compression", &|n| n * e_roll, 1))
        .with(line("n_c E_break: loss of monomers", &|n| n * e_break, 3))
        .with(line("10 n_c E_break: disruption", &|n| 10.0 * n * e_break, 0))
        .with(Series::new("this collision", vec![[p.contacts, e_k]], Style::Marker, 4));

        let a_max = 1.6 * pair.jkr_equilibrium_radius();
        let [_, _, hertz_f, jkr_f] = super::common::reference_curves(&pair, a_max);
        let fig_f = Figure::new(
            "jkr-force",
            "JKR and Hertz force",
            Axis::linear("mutual approach δ", "nm"),
            Axis::linear("force", "µN"),
        )
        .with(hertz_f)
        .with(jkr_f)
        .with(Series::new(
            "pull-off −F_c",
            vec![[pair.jkr_approach(pair.jkr_equilibrium_radius() / 4f64.cbrt()) * 1e9, -pair.pull_off_force() * 1e6]],
            Style::Marker,
            3,
        ));

        let scalars = vec![
            Scalar {
                key: "a_eq",
                label: "JKR equilibrium radius a_eq",
                value: pair.jkr_equilibrium_radius(),
                unit: "m",
            },
            Scalar { key: "F_c", label: "pull-off force F_c", value: pair.pull_off_force(), unit: "N" },
            Scalar { key: "E_break", label: "break energy E_break", value: e_break, unit: "J" },
            Scalar { key: "E_roll", label: "rolling energy E_roll", value: e_roll, unit: "J" },
            Scalar {
                key: "v_c",
                label: "JKR sticking velocity v_c (2.25)",
                value: pair.jkr_sticking_velocity(),
                unit: "m s^-1",
            },
            Scalar { key: "v_break", label: "√(2E_break/m*)", value: v_break, unit: "m s^-1" },
            Scalar { key: "tabor", label: "Tabor parameter μ", value: pair.tabor(p.z0), unit: "" },
            Scalar { key: "E_K", label: "aggregate collision energy", value: e_k, unit: "J" },
        ];
        let mut notes = vec![format!("Regime of this aggregate collision (Table 1.1): {regime}.")];
        let mu = pair.tabor(p.z0);
        if mu < 5.0 {
            notes.push(format!(
                "Tabor parameter μ = {mu:.2} < 5: JKR theory is not strictly valid (DMT/Maugis regime)."
            ));
        }
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig_v, fig_r, fig_f],
            notes,
            extra: crate::scene::core::Extra::None,
        })
    }
}
