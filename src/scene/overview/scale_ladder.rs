//! Scene "Scale ladder": one monomer, followed from its contact (ch. 2–3)
//! through the thresholds of its aggregates and their growth in a column
//! (ch. 4) to where in the disk they form planetesimals (ch. 5), every step
//! recomputed when the monomer changes.

use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::constants::{AU, YEAR};
use crate::physics::growth::{Porosity, Stop, Track};
use crate::physics::monomer::{GUNDLACH_RADIUS, GUNDLACH_ROLLING_ENERGY, Monomer, RollingLaw};
use crate::scene::batches::common::BatchParams;
use crate::scene::core::{Context, Extra, Rung, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace};
use crate::scene::disk::common::{DiskParams, GrowthParams, TrackParams};
use crate::scene::monomer::RollingEnergyLaw;
use crate::scene::schema::Choice;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// Parameters of the scale ladder. SI units except where stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
#[param(manual_default)]
pub struct Params {
    /// The disk, its monomer and the batch model (default: Fig. 5.9's
    /// 0.2 M☉, Z₀ = 0.05, R_c = 30 AU disk with 500 batches out to 300 AU).
    #[param(flatten)]
    pub run: BatchParams,
    /// where the local column grows
    #[param(quantity = crate::scene::quantities::disk_radius)]
    pub radius_au: f64,
}

impl Default for Params {
    fn default() -> Self {
        let mut run = BatchParams { r_out_au: 300.0, ..BatchParams::default() };
        run.disk.disk_mass = 0.2;
        run.disk.metallicity = 0.05;
        Params { run, radius_au: 5.0 }
    }
}

impl Params {
    /// The disk and monomer with the rolling-energy law `law`.
    fn with_law(&self, law: RollingEnergyLaw) -> DiskParams {
        DiskParams { rolling_law: law, ..self.run.disk.clone() }
    }

    /// Local growth at the column's radius (no drift, no fragmentation).
    fn local(&self, disk: DiskParams) -> Track {
        let growth = GrowthParams { disk, v_frag: 1e4, ..GrowthParams::default() };
        TrackParams { growth, radius_au: self.radius_au }.track(Porosity::Full)
    }
}

/// The first point of a track with Ωt_s ≥ 1: (mass kg, time s).
fn stokes_unity(t: &Track) -> Option<(f64, f64)> {
    t.points.iter().find(|q| q.stokes >= 1.0).map(|q| (q.mass, q.t))
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "scale-ladder",
        title: "Scale ladder",
        source: "Sects. 1.2, 3.2, 4.2.3–4.2.4, 4.5, 5.3, App. 5.C; Eqs. 1.24, 1.25, 2.25, 3.16, 4.12, 4.15, 5.26; Figs. 4.8, 5.9",
        explanation: "One monomer, four scales. The contact of two monomers (ch. 2) sets the energy to break it, \
E_break ∝ (γ⁵R⁴/E*²)^{1/3} (1.24), and their sticking velocity (2.25); its rolling energy E_roll = 6πγRξ_crit \
(1.25) depends on the critical displacement: (a_eq/12)Δγ/γ in ch. 3 (3.16), E_roll ∝ a₀^{5/3}, calibrated to \
Gundlach et al.'s measurement in (5.26), or a fixed 0.3 nm (Dominik & Tielens, E_roll ∝ a₀). The aggregates' \
thresholds follow: collisional compaction above 3bE_roll, the compressive strength E_roll φ³/a₀³ (4.15), \
v_frag = 20(E_break/m₀)^{1/2} (4.12). A lower E_roll makes compacter aggregates, which cross Ωt_s = 1 at a \
lower mass; over the whole disk (ch. 5) that moves the outer edge of the planetesimal formation zone \
(Fig. 5.9). Every number here is recomputed when the monomer changes; the disk step runs the batch model \
at the resolution set below.",
        heavy: true,
    };

    fn coarse(&self) -> Option<Self> {
        Some(Params { run: self.run.coarse(), ..self.clone() })
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let mono = p.run.disk.monomer();
        let pair = mono.pair();
        // 1. The contact of two monomers.
        let mut scalars = vec![
            Scalar {
                key: "a_eq",
                label: "contact: JKR equilibrium radius a_eq (2.10)",
                value: pair.jkr_equilibrium_radius(),
                unit: "m",
            },
            Scalar { key: "F_c", label: "contact: pull-off force F_c", value: pair.pull_off_force(), unit: "N" },
            Scalar {
                key: "E_break",
                label: "contact: energy to break E_break (1.24)",
                value: mono.break_energy(),
                unit: "J",
            },
            Scalar {
                key: "E_roll",
                label: "contact: rolling energy E_roll (1.25)",
                value: mono.rolling_energy(),
                unit: "J",
            },
            Scalar {
                key: "xi_crit",
                label: "contact: critical rolling displacement ξ_crit",
                value: mono.rolling_displacement(),
                unit: "m",
            },
            Scalar {
                key: "hysteresis_of_5_26",
                label: "contact: Δγ/γ that makes the ch. 3 law equal (5.26)",
                value: Monomer { rolling: RollingLaw::Calibrated, ..mono }.hysteresis_of_calibration(),
                unit: "",
            },
            Scalar {
                key: "v_stick_jkr",
                label: "contact: sticking velocity, JKR (2.25)",
                value: mono.jkr_sticking_velocity(),
                unit: "m s^-1",
            },
        ];
        ctx.progress.check()?;
        // 2. Aggregate thresholds.
        let v_frag = p.run.disk.fragmentation_velocity(p.run.v_frag, p.run.v_frag_from_monomer);
        scalars.extend([
            Scalar {
                key: "E_compaction",
                label: "aggregates: compaction onset 3bE_roll (b = 0.15)",
                value: mono.compaction_energy(),
                unit: "J",
            },
            Scalar {
                key: "v_frag_monomer",
                label: "aggregates: v_frag of the monomer (4.12)",
                value: mono.fragmentation_velocity(),
                unit: "m s^-1",
            },
            Scalar {
                key: "v_frag_used",
                label: "aggregates: fragmentation threshold used",
                value: v_frag,
                unit: "m s^-1",
            },
            Scalar {
                key: "v_eros",
                label: "aggregates: erosion threshold v_eros (as set)",
                value: p.run.v_eros,
                unit: "m s^-1",
            },
        ]);
        // 3. The local column: φ(m) for each law, and the crossing of Ωt_s = 1.
        let mut fig_phi = Figure::new(
            "ladder-porosity",
            &format!("φ(m) at {} AU for each E_roll law (Fig. 4.8)", crate::figure::human(p.radius_au)),
            Axis::log("mass", "g"),
            Axis::log("filling factor φ", ""),
        );
        let mut own: Option<Track> = None;
        for (k, (key, label)) in RollingEnergyLaw::OPTIONS.iter().enumerate() {
            let Some(law) = RollingEnergyLaw::from_key(key) else { continue };
            let track = p.local(p.with_law(law));
            let chosen = law == p.run.disk.rolling_law;
            let pts = track.points.iter().map(|q| [q.mass * 1e3, q.filling]).collect();
            let style = if chosen { Style::Line } else { [Style::Dashed, Style::Dotted, Style::Dashed][k] };
            fig_phi =
                fig_phi.with(Series::new(format!("{label}{}", if chosen { " (chosen)" } else { "" }), pts, style, k));
            if chosen {
                own = Some(track);
            }
        }
        let own = own.unwrap_or_else(|| p.local(p.run.disk.clone()));
        if let Some((m, t)) = stokes_unity(&own) {
            scalars.push(Scalar {
                key: "mass_st1",
                label: "column: mass at Ωt_s = 1 (drift barrier)",
                value: m,
                unit: "kg",
            });
            scalars.push(Scalar {
                key: "time_st1",
                label: "column: time to reach Ωt_s = 1",
                value: t / YEAR,
                unit: "yr",
            });
            if let Some(q) = own.points.iter().find(|q| q.stokes >= 1.0) {
                scalars.push(Scalar {
                    key: "phi_st1",
                    label: "column: filling factor at Ωt_s = 1",
                    value: q.filling,
                    unit: "",
                });
            }
        }
        if let Some(last) = own.points.last().filter(|_| own.stop == Stop::Planetesimal) {
            scalars.push(Scalar {
                key: "phi_planetesimal",
                label: "column: φ at 10¹⁶ g",
                value: last.filling,
                unit: "",
            });
        }
        ctx.progress.set(0.1);
        // 4. The disk: the batch model.
        let run = p.run.run(ctx.progress)?;
        let edge = run.outermost_planetesimals() / AU;
        scalars.push(Scalar {
            key: "formation_edge",
            label: "disk: outermost planetesimal formation",
            value: edge,
            unit: "AU",
        });
        scalars.push(Scalar {
            key: "converted",
            label: "disk: converted into planetesimals",
            value: run.converted_fraction(),
            unit: "",
        });
        let mut fig_disk = Figure::new(
            "ladder-disk",
            "Where each batch forms planetesimals (Fig. 5.9's disk)",
            Axis::log("initial radius", "AU"),
            Axis::log("formation radius", "AU"),
        );
        let formed: Vec<[f64; 2]> = run
            .fates
            .iter()
            .zip(&run.initial_radii)
            .filter_map(|(f, r0)| match f {
                crate::physics::batches::Fate::Planetesimals { r, .. } => Some([r0 / AU, r / AU]),
                _ => None,
            })
            .collect();
        if let (Some(first), Some(last)) = (run.initial_radii.first(), run.initial_radii.last()) {
            fig_disk = fig_disk.with(Series::new(
                "formed where it started",
                vec![[first / AU, first / AU], [last / AU, last / AU]],
                Style::Dotted,
                7,
            ));
        }
        fig_disk = fig_disk.with(Series::new("batches forming planetesimals", formed, Style::Points, 0));
        if edge > 0.0 {
            fig_disk = fig_disk.with(Series::new(
                format!("edge {} AU", crate::figure::human(edge)),
                vec![[p.run.r_in_au, edge], [p.run.r_out_au, edge]],
                Style::Dashed,
                3,
            ));
        }
        // The rolling energy of each law against the monomer radius.
        let radii = logspace(1e-8, 1e-5, 61);
        let mut fig_roll = Figure::new(
            "ladder-rolling",
            "Rolling energy against monomer radius (Sect. 4.2.4)",
            Axis::log("monomer radius a₀", "µm"),
            Axis::log("E_roll", "erg"),
        );
        for (k, (key, label)) in RollingEnergyLaw::OPTIONS.iter().enumerate() {
            let Some(chosen) = RollingEnergyLaw::from_key(key) else { continue };
            let law = p.with_law(chosen).monomer();
            let pts = radii.iter().map(|&a| [a * 1e6, Monomer { radius: a, ..law }.rolling_energy() * 1e7]).collect();
            let style = if chosen == p.run.disk.rolling_law {
                Style::Line
            } else {
                [Style::Dashed, Style::Dotted, Style::Dashed][k]
            };
            fig_roll = fig_roll.with(Series::new(*label, pts, style, k));
        }
        let measured = GUNDLACH_ROLLING_ENERGY * 1e7;
        fig_roll = fig_roll.with(Series::new(
            "∝ a₀ through the measurement",
            radii.iter().map(|&a| [a * 1e6, measured * a / GUNDLACH_RADIUS]).collect(),
            Style::Dotted,
            7,
        ));
        fig_roll = fig_roll.with(Series::new(
            "Gundlach et al. (2011)",
            vec![[GUNDLACH_RADIUS * 1e6, measured]],
            Style::Marker,
            4,
        ));
        fig_roll = fig_roll.with(Series::new(
            "this monomer",
            vec![[mono.radius * 1e6, mono.rolling_energy() * 1e7]],
            Style::Marker,
            6,
        ));
        let notes = vec![format!(
            "E_roll = {} erg → φ = {} at Ωt_s = 1 → planetesimals out to {} AU",
            crate::figure::human(mono.rolling_energy() * 1e7),
            own.points.iter().find(|q| q.stokes >= 1.0).map_or("–".into(), |q| crate::figure::human(q.filling)),
            crate::figure::human(edge)
        )];
        ctx.progress.set(1.0);
        let rungs = ladder(&scalars, &mono, p);
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig_roll, fig_phi, fig_disk],
            notes,
            extra: Extra::Ladder(Arc::new(rungs)),
        })
    }
}

/// The scalars as four rungs, smallest scale first.
fn ladder(scalars: &[Scalar], mono: &Monomer, p: &Params) -> Vec<Rung> {
    let get = |key: &str| scalars.iter().find(|s| s.key == key).map(|s| s.value);
    let h = crate::figure::human;
    let text = |key: &str, f: &dyn Fn(f64) -> String| get(key).map_or_else(|| "–".to_string(), f);
    let item = |q: &str, v: String, src: &str| (q.to_string(), v, src.to_string());
    let law = p.run.disk.rolling_law.label();
    vec![
        Rung {
            figure: Some("ladder-rolling".into()),
            scale: format!("1 · Two monomers, a₀ = {}\u{a0}µm (ch.\u{a0}2–3)", h(mono.radius * 1e6)),
            items: vec![
                item(
                    "contact radius a_eq",
                    text("a_eq", &|v| format!("{} nm", h(v * 1e9))),
                    "JKR equilibrium, Eq. 2.10",
                ),
                item("pull-off force F_c", text("F_c", &|v| format!("{} N", h(v))), "(3/2)πγR, Sect. 1.2"),
                item("E_break", text("E_break", &|v| format!("{} erg", h(v * 1e7))), "Eq. 1.24 (with E*²)"),
                item("ξ_crit", text("xi_crit", &|v| format!("{} nm", h(v * 1e9))), "Eq. 3.16 or the law chosen"),
                item("E_roll", text("E_roll", &|v| format!("{} erg", h(v * 1e7))), law),
                item("v_stick (JKR)", text("v_stick_jkr", &|v| format!("{} m/s", h(v))), "Eq. 2.25"),
            ],
        },
        Rung {
            figure: None,
            scale: "2 · Aggregate thresholds (Sects. 4.2.3–4.2.4)".into(),
            items: vec![
                item(
                    "compaction above 3bE_roll",
                    text("E_compaction", &|v| format!("{} erg", h(v * 1e7))),
                    "b = 0.15, App. 5.C",
                ),
                item("v_frag of the monomer", text("v_frag_monomer", &|v| format!("{} m/s", h(v))), "Eq. 4.12"),
                item(
                    "v_frag used",
                    text("v_frag_used", &|v| if v >= 1e4 { "none".into() } else { format!("{} m/s", h(v)) }),
                    "the run's threshold",
                ),
                item(
                    "v_eros",
                    text("v_eros", &|v| if v >= 1e4 { "none".into() } else { format!("{} m/s", h(v)) }),
                    "as set, Sect. 4.2.3",
                ),
            ],
        },
        Rung {
            figure: Some("ladder-porosity".into()),
            scale: format!("3 · Growth in the column at {} AU (ch. 4)", h(p.radius_au)),
            items: vec![
                item(
                    "Ωt_s = 1 after",
                    text("time_st1", &|v| format!("{} yr", h(v))),
                    "local growth, no drift, Sect. 4.5",
                ),
                item("mass at Ωt_s = 1", text("mass_st1", &|v| format!("{} g", h(v * 1e3))), "the drift barrier"),
                item("φ at Ωt_s = 1", text("phi_st1", &|v| h(v)), "Eqs. 4.15–4.16"),
                item("φ at 10¹⁶ g", text("phi_planetesimal", &|v| h(v)), "self-gravity compaction, Fig. 4.8"),
            ],
        },
        Rung {
            figure: Some("ladder-disk".into()),
            scale: format!(
                "4 · The disk: {}\u{a0}M☉, Z₀ = {} (ch.\u{a0}5)",
                h(p.run.disk.disk_mass),
                h(p.run.disk.metallicity)
            ),
            items: vec![
                item("planetesimals form out to", text("formation_edge", &|v| format!("{} AU", h(v))), "Fig. 5.9"),
                item("dust converted (fraction)", text("converted", &|v| h(v)), "Sect. 5.3"),
            ],
        },
    ]
}
