//! Scene "Mass–porosity track" (thesis Figs. 4.8, 5.2): the filling factor of
//! the mass-dominating particle against its mass.

use super::common::TrackParams;
use crate::figure::{Axis, Figure, Fill, Series, Shape, Style};
use crate::physics::growth::{Porosity, Stop, Track};
use crate::scene::core::{
    Censored, Context, Declared, Irregularity, Scalar, Scene, SceneError, SceneInfo, SceneOutput,
};

/// The scene's parameters: the disk, the growth model and the radius of the track.
pub type Params = TrackParams;

impl Scene for TrackParams {
    const INFO: SceneInfo = SceneInfo {
        id: "porosity-track",
        title: "Mass–porosity track",
        source: "Sects. 4.2.4, 4.5, App. 5.C; Figs. 4.8, 5.2",
        explanation: "Aggregates start as monomers and grow by hit-and-stick collisions with D_f ≈ 2, \
φ ≈ (m/m₀)^{-1/2} (5.25, with the sign the text drops). Collisional compaction starts when same-size \
impacts exceed 3bE_roll (b = 0.15, E_roll from (5.26)); from there φ follows Suyama et al.'s law for \
equal-mass compressive collisions (this project's reconstruction of Okuzumi et al. 2012, see the \
model notes), which keeps φ roughly constant. The compressive strength P_c = E_roll φ³/a₀³ (4.15) \
against the gas ram pressure and self-gravity (4.16) sets the other two limits; φ is the largest of \
the three. Markers: a = λ_mfp, t_s = t_η, Ωt_s = α, Ωt_s = 1 (open in the thesis) and the first \
collisional, gas and self-gravity compaction. Local growth at fixed R (no drift), perfect sticking.",
        heavy: false,
    };

    const CENSORED: &'static [Censored] = &[
        Censored {
            key: "mass_st1",
            above: None,
            undefined: Some("the track ends before Ωt_s = 1 (growth halted, or the time limit)"),
        },
        Censored {
            key: "mass_gravity",
            above: None,
            undefined: Some("self-gravity never sets the filling factor along the track"),
        },
        Censored {
            key: "phi_final",
            above: None,
            undefined: Some("the track does not reach the planetesimal mass (growth halted, or the time limit)"),
        },
        Censored {
            key: "time_final",
            above: None,
            undefined: Some("the track does not reach the planetesimal mass (growth halted, or the time limit)"),
        },
    ];

    const DECLARED: &'static [Declared] = &[
        super::common::TRACK_STEP,
        Declared {
            scalar: "phi_min_collisional",
            parameter: "v_frag",
            kind: Irregularity::Step,
            why: "a threshold: below it growth halts at the fragmentation barrier, before φ reaches its lowest value",
            resolution: None,
        },
        Declared {
            scalar: "phi_min_collisional",
            parameter: "v_eros",
            kind: Irregularity::Step,
            why: "a threshold: below it growth halts at the erosion barrier, before φ reaches its lowest value",
            resolution: None,
        },
    ];

    /// Computes the scene.
    fn compute(&self, _ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let full = p.track(Porosity::Full);
        let coll = p.track(Porosity::Collisional);
        let line = |t: &Track| t.points.iter().map(|q| [q.mass * 1e3, q.filling]).collect::<Vec<_>>();
        let mut fig = Figure::new(
            "porosity-track",
            "Filling factor of the mass-dominating particle (Fig. 4.8)",
            Axis::log("mass", "g"),
            Axis::log("filling factor φ", ""),
        )
        .with(Series::new("collisional compaction only", line(&coll), Style::Dashed, 1))
        .with(Series::new("collisional + gas + self-gravity", line(&full), Style::Line, 0));
        let mut scalars = Vec::new();
        // The thesis's symbols: open for the crossings (○ a = λ_mfp, ◇ t_s = t_η,
        // ▽ Ωt_s = α, □ Ωt_s = 1), filled at the first compaction of each kind;
        // each symbol takes the colour of its track and is listed once.
        for (tag, t, color) in [("full", &full, 0), ("collisional", &coll, 1)] {
            let m = &t.markers;
            let marks = [
                ("a = λ_mfp", m.radius_mfp, Shape::Circle, Fill::Open),
                ("t_s = t_η", m.kolmogorov, Shape::Diamond, Fill::Open),
                ("Ωt_s = α", m.settling, Shape::TriangleDown, Fill::Open),
                ("Ωt_s = 1", m.stokes_one, Shape::Square, Fill::Open),
                ("first collisional compaction", m.collisional, Shape::Asterisk, Fill::Filled),
                ("first gas compaction", m.gas, Shape::Circle, Fill::Filled),
                ("first self-gravity compaction", m.gravity, Shape::Diamond, Fill::Filled),
            ];
            for (name, at, shape, fill) in marks {
                if let Some([mass, phi]) = at {
                    fig = fig.with(
                        Series::new(
                            format!("{name} ({tag})"),
                            vec![[mass * 1e3, phi]],
                            Style::Symbol(shape, fill),
                            color,
                        )
                        .keyed(name),
                    );
                }
            }
        }
        let phi_min_coll = coll.points.iter().map(|q| q.filling).fold(1.0, f64::min);
        scalars.push(Scalar {
            key: "phi_min_collisional",
            label: "lowest φ, collisional compaction only",
            value: phi_min_coll,
            unit: "",
        });
        let mass = |at: Option<[f64; 2]>| at.map_or(f64::NAN, |[m, _]| m);
        scalars.push(Scalar {
            key: "mass_st1",
            label: "mass at Ωt_s = 1 (full)",
            value: mass(full.markers.stokes_one),
            unit: "kg",
        });
        scalars.push(Scalar {
            key: "mass_gravity",
            label: "mass at first self-gravity compaction",
            value: mass(full.markers.gravity),
            unit: "kg",
        });
        // Values at the planetesimal mass exist only where the track reaches it.
        let end = full.points.last().filter(|_| full.stop == Stop::Planetesimal);
        scalars.push(Scalar {
            key: "phi_final",
            label: "φ at the planetesimal mass (full)",
            value: end.map_or(f64::NAN, |q| q.filling),
            unit: "",
        });
        scalars.push(Scalar {
            key: "time_final",
            label: "time to the planetesimal mass (full)",
            value: end.map_or(f64::NAN, |q| q.t),
            unit: "s",
        });
        Ok(SceneOutput { scalars, figures: vec![fig], ..Default::default() })
    }
}
