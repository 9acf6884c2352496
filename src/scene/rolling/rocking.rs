//! Scene "Rocking" (thesis Sects. 3.2.5, 3.3.1, 3.4): a sphere kicked
//! sideways rocks on its pinned contact at f₀, rolls once ξ passes ξ_crit,
//! and is damped by the bulk loss of quality factor Q.

use super::common::RollingParams;
use crate::figure::{Axis, Figure, Scale, Series, Style};
use crate::physics::rolling::{Rocking as RockingModel, RockingSample, critical_displacement, small_asymmetry_torque};
use crate::scene::core::{Censored, Context, Cursor, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use crate::scene::timeline;
use serde::{Deserialize, Serialize};

/// Parameters of the rocking scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The contact (default: 21.4 µm PSL on aluminium, γ = 0.1 J m⁻²).
    #[param(flatten, default = RollingParams::of("PSL", "aluminium alloy", true, 10.7e-6, 0.1))]
    pub contact: RollingParams,
    /// sets ξ_crit (3.16)
    #[param(quantity = quantities::hysteresis, default = 1.0)]
    pub hysteresis: f64,
    /// bulk loss; 1e12 ≈ none
    #[param(quantity = quantities::quality_factor, default = 30.0)]
    pub q: f64,
    /// amplitude the kick gives an undamped pinned contact
    #[param(label = "kick (ξ_max/a_eq)", range(1e-4, 1.0), log, default = 0.08)]
    pub kick_amplitude: f64,
    /// length of the run
    #[param(label = "duration", unit = "periods", range(1.0, 200.0), log, default = 20.0)]
    pub periods: f64,
    /// Runge–Kutta steps per period
    #[param(numerical, label = "steps per period", range(20.0, 5000.0), default = 400)]
    pub steps_per_period: usize,
    /// time of the marker, fraction of the run
    #[param(quantity = quantities::time_cursor, style_only, default = 0.1)]
    pub cursor: f64,
}

impl Params {
    /// The rocking model.
    pub fn model(&self) -> RockingModel {
        let r = self.contact.radius;
        let pair = self.contact.pair(r);
        let inertia = self.contact.inertia(r);
        let kick =
            RockingModel::kick_for_amplitude(&pair, inertia, self.kick_amplitude * pair.jkr_equilibrium_radius());
        RockingModel { pair, inertia, hysteresis: self.hysteresis, q: self.q, kick }
    }
}

/// Frequency from the upward zero crossings of ξ while pinned, Hz.
pub fn measured_frequency(samples: &[RockingSample]) -> Option<f64> {
    let mut crossings = Vec::new();
    for w in samples.windows(2) {
        if !w[0].rolling && !w[1].rolling && w[0].xi < 0.0 && w[1].xi >= 0.0 {
            let f = -w[0].xi / (w[1].xi - w[0].xi);
            crossings.push(w[0].t + f * (w[1].t - w[0].t));
        }
    }
    (crossings.len() >= 2).then(|| (crossings.len() - 1) as f64 / (crossings[crossings.len() - 1] - crossings[0]))
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "rocking",
        title: "Rocking",
        source: "Sects. 3.2.5, 3.3.1, 3.4; Eqs. 3.17–3.25",
        explanation: "A sphere on its JKR contact receives a sideways kick. While ξ < ξ_crit the contact is \
pinned (a₁ = a_eq − ξ, a₂ = a_eq + ξ, 3.18) and the torque 6πγRξ (3.14) pulls it back: \
I d²ξ/dt² = −R M (3.17) is a harmonic oscillator with f₀ = (3/4π)(5γ/(ρR³))^{1/2} (3.20), \
about 150 kHz for Peri & Cetinkaya's 21.4 µm PSL sphere on aluminium. The integration uses the \
full pinned torque of (3.13) at fixed δ, 6πγRξ[1 + (3/2)(ξ/a)²]. When a kick drives ξ to ξ_crit \
the trailing edge opens and the sphere rolls against the constant torque (R/2)π a_eq Δγ until it \
stops and pins again. The bulk loss is a linear damping that makes the rocking energy e-fold in \
Q/π periods (3.25): Peri & Cetinkaya's rocking dies out in ~10 periods, Q ~ 30.",
        heavy: false,
    };

    const CENSORED: &'static [Censored] = &[
        Censored {
            key: "f_measured",
            above: None,
            undefined: Some("too few upward zero crossings of ξ while pinned to measure a frequency"),
        },
        Censored {
            key: "efold_periods",
            above: None,
            undefined: Some("longer than the run: the energy stays above E(0)/e for the whole duration"),
        },
    ];

    fn material_changed(&mut self) {
        self.contact.material_changed();
    }

    fn time_cursor(&mut self) -> Option<&mut f64> {
        Some(&mut self.cursor)
    }

    fn cursor(&self, out: &SceneOutput) -> Option<Cursor> {
        let p = self;
        let range = timeline::x_range(out, "rocking-displacement")?;
        let t = timeline::time_at(range, p.cursor, Scale::Linear);
        let marks = ["rocking-displacement", "rocking-energy", "rocking-state"]
            .iter()
            .flat_map(|id| timeline::along_x(out, id, t))
            .collect();
        Some(Cursor {
            fraction: p.cursor,
            label: format!("t = {} µs", crate::figure::human(t)),
            marks,
            optional: false,
        })
    }

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let model = p.model();
        let samples = model.run(p.periods, p.steps_per_period);
        let f0 = model.frequency();
        let a_eq = model.pair.jkr_equilibrium_radius();
        let xi_crit = critical_displacement(&model.pair, p.hysteresis);
        let e0 = samples.first().map_or(1.0, |s| s.energy).max(f64::MIN_POSITIVE);
        let t_us = |s: &RockingSample| s.t * 1e6;
        let t_end = samples.last().map_or(0.0, t_us);

        let fig_xi = Figure::new(
            "rocking-displacement",
            "Rolling displacement ξ(t)",
            Axis::linear("time t", "µs"),
            Axis::linear("ξ", "nm"),
        )
        .with(Series::new("ξ", samples.iter().map(|s| [t_us(s), s.xi * 1e9]).collect(), Style::Line, 0))
        .with(Series::new("±ξ_crit (3.16)", vec![[0.0, xi_crit * 1e9], [t_end, xi_crit * 1e9]], Style::Dashed, 6))
        .with(Series::new("", vec![[0.0, -xi_crit * 1e9], [t_end, -xi_crit * 1e9]], Style::Dashed, 6));
        let fig_e =
            Figure::new("rocking-energy", "Rocking energy", Axis::linear("time t", "µs"), Axis::log("E / E(0)", ""))
                .with(Series::new("energy", samples.iter().map(|s| [t_us(s), s.energy / e0]).collect(), Style::Line, 2))
                .with(Series::new(
                    "exp(−π f₀ t / Q)",
                    samples
                        .iter()
                        .step_by(10)
                        .map(|s| [t_us(s), (-std::f64::consts::PI * f0 * s.t / p.q).exp()])
                        .collect(),
                    Style::Dashed,
                    6,
                ));
        let fig_r = Figure::new(
            "rocking-state",
            "Rolled distance and state",
            Axis::linear("time t", "µs"),
            Axis::linear("distance rolled", "nm"),
        )
        .with(Series::new("rolled", samples.iter().map(|s| [t_us(s), s.rolled * 1e9]).collect(), Style::Line, 3))
        .with(Series::new(
            "rolling (0 = pinned, 1 = rolling) × ξ_crit",
            samples.iter().map(|s| [t_us(s), if s.rolling { xi_crit * 1e9 } else { 0.0 }]).collect(),
            Style::Dashed,
            4,
        ));
        let max_xi = samples.iter().map(|s| s.xi.abs()).fold(0.0, f64::max);
        let rolled = samples.last().map_or(0.0, |s| s.rolled);
        let efold = samples.iter().find(|s| s.energy < e0 / std::f64::consts::E).map(|s| s.t * f0);
        let mut scalars = vec![
            Scalar { key: "f0", label: "rocking frequency f₀ (3.20)", value: f0, unit: "Hz" },
            Scalar { key: "a_eq", label: "JKR equilibrium radius a_eq", value: a_eq, unit: "m" },
            Scalar { key: "xi_crit", label: "critical displacement ξ_crit (3.16)", value: xi_crit, unit: "m" },
            Scalar { key: "xi_max", label: "largest |ξ|", value: max_xi, unit: "m" },
            Scalar {
                key: "torque_max",
                label: "largest torque 6πγRξ_max",
                value: small_asymmetry_torque(&model.pair, max_xi),
                unit: "N m",
            },
            Scalar { key: "rolled", label: "distance rolled", value: rolled, unit: "m" },
            Scalar {
                key: "angle_max_deg",
                label: "largest rocking angle ξ/R",
                value: (max_xi / model.pair.radius).to_degrees(),
                unit: "deg",
            },
        ];
        scalars.push(Scalar {
            key: "f_measured",
            label: "measured frequency (zero crossings)",
            value: measured_frequency(&samples).unwrap_or(f64::NAN),
            unit: "Hz",
        });
        scalars.push(Scalar {
            key: "efold_periods",
            label: "periods until E < E(0)/e",
            value: efold.unwrap_or(f64::NAN),
            unit: "",
        });
        let notes = vec![if rolled > 0.0 {
            format!("The kick pushed ξ past ξ_crit: the sphere rolled {:.1} nm before pinning again.", rolled * 1e9)
        } else {
            "The contact stayed pinned: the sphere rocks about its contact.".to_string()
        }];
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig_xi, fig_e, fig_r],
            notes,
            extra: crate::scene::core::Extra::None,
        })
    }
}
