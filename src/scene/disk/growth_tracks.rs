//! Scene "Growth and drift tracks" (thesis Figs. 4.13, 4.14): m(t) and a(t)
//! against R(t) from many starting radii.

use super::common::GrowthParams;
use crate::figure::{Axis, Figure, Series, Style};
use crate::parallel::prelude::*;
use crate::physics::constants::{AU, YEAR};
use crate::physics::growth::{Porosity, Stop, Track};
use crate::scene::controls::LogRange;
use crate::scene::core::{
    Censored, Context, Cursor, Declared, Extra, Irregularity, Progress, Scalar, Scene, SceneError, SceneInfo,
    SceneOutput, TimedPath, logspace,
};
use crate::scene::inspect::{self, Inspection};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use crate::scene::timeline;
use serde::{Deserialize, Serialize};

/// Parameters of the growth-track scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The growth model (its v_frag applies to porous tracks).
    #[param(flatten)]
    pub growth: GrowthParams,
    /// fragmentation velocity of compact grains
    #[param(
        figure_only,
        label = "compact v_frag",
        unit = "m s^-1",
        shown("m/s", 1.0),
        range(0.1, 1e3),
        log,
        default = 10.0
    )]
    pub v_frag_compact: f64,
    /// first starting radius
    #[param(label = "innermost start", unit = "AU", range(1.1, 300.0), log, default = 3.0)]
    pub r_min_au: f64,
    /// last starting radius
    #[param(label = "outermost start", unit = "AU", range(1.1, 1000.0), log, default = 300.0)]
    pub r_max_au: f64,
    /// starting radii, log-spaced
    #[param(numerical, label = "tracks", range(1.0, 200.0), default = 30)]
    pub tracks: usize,
    /// time followed
    #[param(quantity = quantities::duration, default = 1e6)]
    pub duration_yr: f64,
    /// also run compact growth
    #[param(figure_only, label = "compact tracks", default = true)]
    pub compact: bool,
    /// time at which every track is marked, as a fraction of the run in log time
    #[param(quantity = quantities::time_cursor, style_only, default = 0.0)]
    pub cursor: f64,
}

impl Params {
    /// All tracks: (compact, porous), computed in parallel.
    pub fn run(&self, progress: &Progress) -> Result<(Vec<Track>, Vec<Track>), SceneError> {
        let starts = if self.tracks <= 1 {
            vec![self.r_min_au]
        } else {
            logspace(self.r_min_au, self.r_max_au.max(self.r_min_au * 1.000001), self.tracks)
        };
        let porous = self.growth.model(Porosity::Full);
        let mut compact = self.growth.model(Porosity::Compact);
        compact.thresholds.v_frag = self.v_frag_compact;
        let t_end = self.duration_yr * YEAR;
        let run = |model: &crate::physics::growth::GrowthModel| -> Result<Vec<Track>, SceneError> {
            starts
                .par_iter()
                .map(|&r| {
                    progress.check()?;
                    Ok(model.run(r * AU, t_end))
                })
                .collect()
        };
        let c = if self.compact { run(&compact)? } else { Vec::new() };
        let p = run(&porous)?;
        Ok((c, p))
    }
}

/// Why a formation radius has no value.
const NO_PLANETESIMAL: &str = "no porous track forms a planetesimal";

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "growth-tracks",
        title: "Growth and drift tracks",
        source: "Sect. 4.5; Eqs. 4.35, 4.36; Figs. 4.13, 4.14",
        explanation: "The semi-analytical model grows the mass-dominating particle by (4.35) while it drifts by \
    (4.36), from monomers at many starting radii, for a fixed time. Compact grains (φ = 1) are stopped by \
fragmentation (v_frag = 10 m/s here, as in Fig. 4.13 left) in the inner disk, by drift further out, and \
grow too slowly beyond ~100 AU. Porous aggregates (compaction by collisions, gas and self-gravity) \
outgrow the drift barrier in the inner disk unless erosion by small projectiles (v_eros) halts them \
near Ωt_s ~ 1. Second plot: the particle radius (Fig. 4.14).",
        heavy: true,
    };

    const CENSORED: &'static [Censored] = &[
        Censored { key: "outermost_planetesimal_formation", above: None, undefined: Some(NO_PLANETESIMAL) },
        Censored { key: "outermost_planetesimal_start", above: None, undefined: Some(NO_PLANETESIMAL) },
        Censored { key: "max_stokes_eroded", above: None, undefined: Some("erosion halts no porous track") },
    ];

    const DECLARED: &'static [Declared] = &[
        Declared {
            scalar: "porous_planetesimal_tracks",
            parameter: "*",
            kind: Irregularity::Step,
            why: "a count of tracks: a whole number",
            resolution: None,
        },
        Declared {
            scalar: "outermost_planetesimal_start",
            parameter: "*",
            kind: Irregularity::Step,
            why: "the start of one of the log-spaced tracks: it moves by whole spacings of the track grid (`tracks`)",
            resolution: None,
        },
        Declared {
            scalar: "outermost_planetesimal_formation",
            parameter: "*",
            kind: Irregularity::Step,
            why: "where the outermost forming track ends: it moves when another track of the grid becomes the outermost",
            resolution: None,
        },
        Declared {
            scalar: "max_stokes_eroded",
            parameter: "*",
            kind: Irregularity::Step,
            why: "the largest Ωt_s over the tracks halted by erosion: it steps where a track starts or stops being halted \
                  by erosion",
            resolution: None,
        },
        Declared {
            scalar: "*",
            parameter: "v_bounce",
            kind: Irregularity::Ignored,
            why: "the bouncing threshold halts compact growth only; compact tracks are drawn for comparison and have no \
                  scalar",
            resolution: None,
        },
    ];

    fn inspect(&self, out: &SceneOutput, figure: &str, at: [f64; 2]) -> Option<Inspection> {
        let p = self;
        let Extra::Paths(paths) = &out.extra else { return None };
        let fig = inspect::figure(&out.figures, figure)?;
        // The nearest point of any track on the clicked figure.
        let (k, i, _) = paths
            .iter()
            .enumerate()
            .filter(|(_, path)| path.figure == figure)
            .filter_map(|(k, path)| {
                inspect::nearest(fig, path.points.iter().copied(), at, 0.06).map(|(i, d)| (k, i, d))
            })
            .min_by(|a, b| a.2.total_cmp(&b.2))?;
        let path = &paths[k];
        let compact = path.color == Some(1);
        // The track again (one track takes milliseconds), for its full state.
        let mut model = p.growth.model(if compact { Porosity::Compact } else { Porosity::Full });
        if compact {
            model.thresholds.v_frag = p.v_frag_compact;
        }
        let r0 = path.points.first()?[0] * AU;
        let track = model.run(r0, p.duration_yr * YEAR);
        let q = track.points.get(i).or(track.points.last())?;
        let mut rows = vec![
            inspect::row(
                "track",
                format!(
                    "{} growth from {} AU",
                    if compact { "compact" } else { "porous" },
                    crate::figure::human(r0 / AU)
                ),
            ),
            inspect::row("time t", inspect::value(q.t / YEAR, "yr")),
        ];
        rows.extend(super::common::aggregate_rows(&p.growth.disk, q.r, q.mass, q.filling, q.t_grow));
        rows.push(inspect::row("same-size Δv", inspect::value(q.v_rel, "m/s")));
        let end = match track.stop {
            Stop::Planetesimal => format!(
                "this track forms a planetesimal (10¹⁶ g) at {} AU",
                crate::figure::human(track.points.last().map_or(0.0, |l| l.r / AU))
            ),
            Stop::InnerEdge => "this track drifts inside the inner edge (1 AU) without forming a planetesimal".into(),
            Stop::TimeLimit | Stop::Steps => format!(
                "no planetesimal within {} yr{}",
                crate::figure::human(p.duration_yr),
                track.halted_by.map_or(String::new(), |h| format!("; growth halted by {h}"))
            ),
        };
        Some(Inspection {
            title: format!("Growth track at t = {} yr", crate::figure::human(q.t / YEAR)),
            rows,
            bars: None,
            outcome: Some(end),
            actions: vec![crate::scene::registry::column_action(&p.growth.disk, q.r / AU)],
            point: path.points[i],
        })
    }

    fn time_cursor(&mut self) -> Option<&mut f64> {
        Some(&mut self.cursor)
    }

    fn cursor(&self, out: &SceneOutput) -> Option<Cursor> {
        let p = self;
        let Extra::Paths(paths) = &out.extra else { return None };
        let t = timeline::time_at(timeline::span(paths)?, p.cursor, crate::figure::Scale::Log);
        let marks = timeline::along_paths(paths, t);
        Some(Cursor { fraction: p.cursor, label: format!("t = {} yr", crate::figure::human(t)), marks, optional: true })
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        if p.tracks > 1 {
            LogRange::new("r_min_au/r_max_au", p.r_min_au, p.r_max_au, p.tracks)?;
        }
        let (compact, porous) = p.run(progress)?;
        let mut fig_m = Figure::new(
            "growth-tracks-mass",
            "Peak mass against radius (Fig. 4.13)",
            Axis::log("radius R", "AU"),
            Axis::log("mass m_p", "g"),
        );
        let mut fig_a = Figure::new(
            "growth-tracks-size",
            "Particle radius against radius (Fig. 4.14)",
            Axis::log("radius R", "AU"),
            Axis::log("particle radius a", "cm"),
        );
        let add = |fig: Figure,
                   tracks: &[Track],
                   name: &str,
                   color: usize,
                   f: &dyn Fn(&crate::physics::growth::TrackPoint) -> f64| {
            let mut fig = fig;
            for (i, t) in tracks.iter().enumerate() {
                let pts = t.points.iter().map(|q| [q.r / AU, f(q)]).collect();
                fig = fig.with(Series::new(
                    if i == 0 { name.to_string() } else { String::new() },
                    pts,
                    if color == 1 { Style::Dashed } else { Style::Line },
                    color,
                ));
            }
            fig
        };
        fig_m = add(fig_m, &compact, "compact", 1, &|q| q.mass * 1e3);
        fig_m = add(fig_m, &porous, "porous", 0, &|q| q.mass * 1e3);
        fig_a = add(fig_a, &compact, "compact", 1, &|q| q.radius * 1e2);
        fig_a = add(fig_a, &porous, "porous", 0, &|q| q.radius * 1e2);
        // Where planetesimals form (the last point of a track that reaches the
        // planetesimal mass) and where their material started.
        let formed: Vec<[f64; 3]> = porous
            .iter()
            .filter(|t| t.stop == Stop::Planetesimal)
            .filter_map(|t| {
                let end = t.points.last()?;
                Some([t.points.first()?.r / AU, end.r / AU, end.mass * 1e3])
            })
            .collect();
        // Undefined (NaN) where no track forms a planetesimal.
        let outermost = formed.iter().map(|f| f[0]).fold(f64::NAN, f64::max);
        let outermost_formation = formed.iter().map(|f| f[1]).fold(f64::NAN, f64::max);
        if !formed.is_empty() {
            let points = formed.iter().map(|f| [f[1], f[2]]).collect();
            fig_m = fig_m.with(Series::new("planetesimal formed", points, Style::Points, 3));
        }
        let max_st_eroded = porous
            .iter()
            .filter(|t| t.halted_by == Some("erosion"))
            .flat_map(|t| t.points.iter().map(|q| q.stokes))
            .fold(f64::NAN, f64::max);
        let scalars = vec![
            Scalar {
                key: "porous_planetesimal_tracks",
                label: "porous tracks reaching 10¹⁶ g",
                value: formed.len() as f64,
                unit: "",
            },
            Scalar {
                key: "outermost_planetesimal_formation",
                label: "outermost radius where a planetesimal forms",
                value: outermost_formation,
                unit: "AU",
            },
            Scalar {
                key: "outermost_planetesimal_start",
                label: "outermost start forming a planetesimal",
                value: outermost,
                unit: "AU",
            },
            Scalar {
                key: "max_stokes_eroded",
                label: "largest Ωt_s of tracks halted by erosion",
                value: max_st_eroded,
                unit: "",
            },
        ];
        // Every track with the time of each point, for the time cursor.
        let mut paths = Vec::new();
        for (t, color) in compact.iter().map(|t| (t, 1)).chain(porous.iter().map(|t| (t, 0))) {
            let color = Some(color);
            let times: Vec<f64> = t.points.iter().map(|q| q.t / YEAR).collect();
            paths.push(TimedPath {
                figure: "growth-tracks-mass".into(),
                color,
                times: times.clone(),
                points: t.points.iter().map(|q| [q.r / AU, q.mass * 1e3]).collect(),
            });
            paths.push(TimedPath {
                figure: "growth-tracks-size".into(),
                color,
                times,
                points: t.points.iter().map(|q| [q.r / AU, q.radius * 1e2]).collect(),
            });
        }
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig_m, fig_a],
            notes: Vec::new(),
            extra: Extra::Paths(std::sync::Arc::new(paths)),
        })
    }
}
