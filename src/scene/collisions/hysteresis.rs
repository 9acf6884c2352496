//! Scene "Contact hysteresis" (thesis Figs. 2.2, 2.3, 2.9, 2.10): one
//! collision followed in time, its a(δ) and F_E(δ) loops against the Hertz and
//! JKR curves, and its energy budget.

use super::common::{CollisionParams, reference_curves};
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::collision::{Options, Outcome, collide};
use crate::physics::contact::e_independent;
use crate::physics::plasticity;
use crate::scene::core::{
    Censored, Context, Cursor, Declared, Extra, Irregularity, Scalar, Scene, SceneError, SceneInfo, SceneOutput,
    Trajectory,
};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use crate::scene::timeline::{self, Mark};
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// Parameters of the hysteresis scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The collision.
    #[param(flatten)]
    pub collision: CollisionParams,
    /// Hertz times to follow a sticking collision after sticking is certain
    ///
    /// For sticking collisions: how long to follow the spiral into the JKR
    /// equilibrium after sticking is certain, in Hertz times (default 6; 0–50).
    #[param(label = "follow sticking", unit = "t_H", range(0.0, 50.0), default = 6.0)]
    pub follow: f64,
    /// time of the sketch, as a fraction of the run
    #[param(quantity = quantities::time_cursor, style_only, default = 0.3)]
    pub cursor: f64,
}

/// Why the energy fractions of a sticking collision step (an audit finding
/// declared as physics).
const TWO_STICKING_REGIMES: &str = "sticking has two regimes: where the contact breaks but the spheres cannot \
     escape, the run and its losses end at the break; where it never breaks, the run follows the spiral into \
     equilibrium, which dissipates the rest";

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "hysteresis",
        title: "Contact hysteresis",
        source: "Sects. 2.2–2.3, App. 2.C; Figs. 2.2, 2.3, 2.9, 2.10",
        explanation: "Two adhesive viscoelastic spheres collide head-on. The contact radius a and the \
mutual approach δ evolve separately: m*d²δ/dt² = −(F_E + F_D) with the elastic force \
F_E = 2E*/(3R)·(3aδR − a³) (2.2) and the bulk drag F_D = 2AE*a·dδ/dt, A = T_vis/ν² (2.19). \
The contact edge is a crack: G_eff = E*(a² − δR)²/(2πaR²) (2.14) sets β = G_eff/γ, and \
Greenwood's law gives the crack speed ȧ(β) (2.16, 2.17) — growing contacts have β < 1, \
shrinking ones β > 1, so the loop a(δ) lies below JKR on loading and above it on unloading. \
Contact ends when β reaches 1/k. Energy: U_K + U_E + U_S + U_CD + U_BD is conserved, with \
U_S = −πa²γ and U_CD, U_BD the energy lost at the crack tip and in the bulk (App. 2.C).",
        heavy: false,
    };

    const CENSORED: &'static [Censored] =
        &[Censored { key: "t_c", above: None, undefined: Some("the spheres stick: the contact never ends") }];

    const DECLARED: &'static [Declared] = &[
        Declared {
            scalar: "*",
            parameter: "rtol",
            kind: Irregularity::Step,
            why: "the integrator's tolerance: results move by about its size, in steps where the sequence of steps changes",
            resolution: None,
        },
        Declared {
            scalar: "sticks",
            parameter: "*",
            kind: Irregularity::Step,
            why: "a threshold: the spheres stick below v_stick and bounce above it",
            resolution: None,
        },
        Declared {
            scalar: "steps",
            parameter: "*",
            kind: Irregularity::Step,
            why: "a diagnostic, the integrator's accepted steps: whole numbers, and a longer run where the contact never breaks",
            resolution: None,
        },
        Declared {
            scalar: "energy_error",
            parameter: "*",
            kind: Irregularity::Step,
            why: "a diagnostic at the level of the tolerance rtol (below 10⁻⁴ of the energy), not a result",
            resolution: None,
        },
        Declared {
            scalar: "crack_fraction",
            parameter: "*",
            kind: Irregularity::Step,
            why: TWO_STICKING_REGIMES,
            resolution: None,
        },
        Declared {
            scalar: "bulk_fraction",
            parameter: "*",
            kind: Irregularity::Step,
            why: TWO_STICKING_REGIMES,
            resolution: None,
        },
    ];

    fn material_changed(&mut self) {
        self.collision.material_changed();
    }

    fn time_cursor(&mut self) -> Option<&mut f64> {
        Some(&mut self.cursor)
    }

    fn cursor(&self, out: &SceneOutput) -> Option<Cursor> {
        let p = self;
        let Extra::Collision(t) = &out.extra else { return None };
        let s = t.sample_at(p.cursor)?;
        let mut marks = vec![
            ("contact-radius".to_string(), Mark::Point([s[1] * 1e9, s[2] * 1e9], None)),
            ("elastic-force".to_string(), Mark::Point([s[1] * 1e9, s[3] * 1e6], None)),
        ];
        marks.extend(timeline::along_x(out, "energy-budget", s[0] * 1e9));
        Some(Cursor {
            fraction: p.cursor,
            label: format!("t = {} ns", crate::figure::human(s[0] * 1e9)),
            marks,
            optional: false,
        })
    }

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let c = &p.collision;
        let setup = c.setup();
        let pair = setup.pair;
        let v = c.velocity;
        let run = collide(
            &setup,
            v,
            &Options { rtol: c.rtol, record: true, follow_after_stick: p.follow, ..Options::default() },
        )?;
        let ke0 = run.initial_kinetic;

        let a_max = run.samples.iter().map(|s| s.radius).fold(pair.jkr_equilibrium_radius(), f64::max) * 1.05;
        let [hertz_a, jkr_a, hertz_f, jkr_f] = reference_curves(&pair, a_max);
        let a_eq = pair.jkr_equilibrium_radius();
        let d_eq = pair.jkr_equilibrium_approach();
        let a_snap = pair.snap_on_radius();
        let f_snap = pair.jkr_force(a_snap);

        let model_a: Vec<[f64; 2]> = run.samples.iter().map(|s| [s.delta * 1e9, s.radius * 1e9]).collect();
        let model_f: Vec<[f64; 2]> = run.samples.iter().map(|s| [s.delta * 1e9, s.elastic_force * 1e6]).collect();
        let label = format!("model, {}", if run.outcome == Outcome::Bounce { "bounce" } else { "stick" });

        let fig_a = Figure::new(
            "contact-radius",
            "Contact radius",
            Axis::linear("mutual approach δ", "nm"),
            Axis::linear("contact radius a", "nm"),
        )
        .with(Series::new(label.clone(), model_a, Style::Line, 0))
        .with(hertz_a)
        .with(jkr_a)
        .with(Series::new("JKR snap-on", vec![[0.0, 0.0], [0.0, a_snap * 1e9]], Style::Dashed, 4))
        .with(Series::new("JKR equilibrium", vec![[d_eq * 1e9, a_eq * 1e9]], Style::Marker, 3));
        let fig_f = Figure::new(
            "elastic-force",
            "Elastic force",
            Axis::linear("mutual approach δ", "nm"),
            Axis::linear("elastic force F_E", "µN"),
        )
        .with(Series::new(label, model_f, Style::Line, 0))
        .with(hertz_f)
        .with(jkr_f)
        .with(Series::new("JKR snap-on", vec![[0.0, 0.0], [0.0, f_snap * 1e6]], Style::Dashed, 4))
        .with(Series::new("JKR equilibrium", vec![[d_eq * 1e9, 0.0]], Style::Marker, 3));

        let energy = |name: &str, f: &dyn Fn(&crate::physics::collision::Sample) -> f64, style, color| {
            Series::new(name, run.samples.iter().map(|s| [s.t * 1e9, f(s) / ke0]).collect(), style, color)
        };
        let fig_e = Figure::new(
            "energy-budget",
            "Energy budget",
            Axis::linear("time t", "ns"),
            Axis::linear("energy / U_K(0)", ""),
        )
        .with(energy("U_K kinetic", &|s| s.kinetic, Style::Line, 0))
        .with(energy("U_E elastic", &|s| s.elastic, Style::Line, 1))
        .with(energy("U_S surface", &|s| s.surface, Style::Line, 2))
        .with(energy("U_CD crack", &|s| s.crack_dissipated, Style::Line, 3))
        .with(energy("U_BD bulk", &|s| s.bulk_dissipated, Style::Line, 4))
        .with(energy("sum", &|s| s.total_energy(), Style::Dashed, 6));

        let e_jkr = pair.e_jkr(v);
        let e_d = pair.e_viscous(setup.dissipation_time(), v);
        let e_p = plasticity::e_plastic(v, setup.yield_velocity());
        let e = if run.e_adhesive > 0.0 { plasticity::e_combined(run.e_adhesive, e_p) } else { 0.0 };
        let scalars = vec![
            // With plastic yield a collision whose combined e (2.30) is zero
            // sticks although adhesion and viscosity alone would let it go.
            Scalar {
                key: "sticks",
                label: "sticks (1) / bounces (0)",
                value: f64::from(u8::from(run.outcome == Outcome::Stick || e == 0.0)),
                unit: "",
            },
            Scalar { key: "e_A", label: "restitution e_A (adhesion + viscosity)", value: run.e_adhesive, unit: "" },
            Scalar { key: "e_P", label: "plastic restitution e_P", value: e_p, unit: "" },
            Scalar { key: "e", label: "restitution e", value: e, unit: "" },
            Scalar {
                key: "t_c",
                label: "contact time t_c",
                value: if run.outcome == Outcome::Stick { f64::NAN } else { run.contact_time },
                unit: "s",
            },
            Scalar { key: "t_H", label: "Hertz time t_H", value: run.hertz_time, unit: "s" },
            Scalar {
                key: "crack_fraction",
                label: "dissipated at the crack U_CD/U_K(0)",
                value: run.crack_fraction(),
                unit: "",
            },
            Scalar {
                key: "bulk_fraction",
                label: "dissipated in the bulk U_BD/U_K(0)",
                value: run.bulk_fraction(),
                unit: "",
            },
            Scalar { key: "e_JKR", label: "elastic JKR e_JKR (2.24)", value: e_jkr, unit: "" },
            Scalar { key: "e_D", label: "viscous e_D (γ → 0 limit of the model)", value: e_d, unit: "" },
            Scalar { key: "e_I", label: "independent e_I (2.27)", value: e_independent(e_jkr, e_d), unit: "" },
            Scalar {
                key: "v_c",
                label: "JKR sticking velocity v_c (2.25)",
                value: pair.jkr_sticking_velocity(),
                unit: "m s^-1",
            },
            Scalar { key: "a_eq", label: "JKR equilibrium radius a_eq", value: a_eq, unit: "m" },
            Scalar {
                key: "energy_error",
                label: "energy bookkeeping error / U_K(0)",
                value: run.energy_error,
                unit: "",
            },
            Scalar { key: "steps", label: "integrator steps", value: run.stats.accepted as f64, unit: "" },
        ];
        let mut notes = Vec::new();
        if !run.resolved {
            notes.push("The spheres were still in contact at the time limit; counted as sticking.".into());
        }
        if run.outcome != Outcome::Stick && e == 0.0 {
            notes.push(format!(
                "With plastic yield e = (e_A² + e_P² − 1)^{{1/2}} (2.30) is zero: the spheres stick. The contact drawn is that of adhesion and viscosity alone (e_A = {:.3}, e_P = {:.3}).",
                run.e_adhesive, e_p
            ));
        }
        if (c.k - 0.02).abs() > 1e-12 && c.crack_law == super::common::CrackLawChoice::Thesis {
            notes.push(
                "Greenwood's low-speed fits (2.17) were made for k = 0.02; at this k the thesis's law is (2.16) alone."
                    .into(),
            );
        }
        let trajectory = Trajectory {
            radius_1: c.radius_1,
            radius_2: if c.wall { f64::INFINITY } else { c.radius_2 },
            samples: run.samples.iter().map(|s| [s.t, s.delta, s.radius, s.elastic_force]).collect(),
        };
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig_a, fig_f, fig_e],
            notes,
            extra: Extra::Collision(Arc::new(trajectory)),
        })
    }
}
