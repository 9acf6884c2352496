//! Scene "Families" (thesis Figs. 4.12, 5.2 bottom): every Monte Carlo
//! family as a dot in mass–filling-factor space at the snapshot times, with
//! the peak track φ_p(m_p) and the semi-analytical track for comparison.

use super::common::{ColumnCompaction, ColumnParams};
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::aggregate::Aggregate;
use crate::physics::coagulation::{FamilyPoint, Run};
use crate::physics::constants::{AU, YEAR};
use crate::physics::growth::{GrowthModel, Porosity};
use crate::scene::core::{Context, Scene, SceneError, SceneInfo, SceneOutput, Seeds};
use crate::scene::inspect::{self, Inspection};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The runs.
    #[param(flatten)]
    pub run: ColumnParams,
    /// the Sect. 4.5 model for comparison
    #[param(label = "semi-analytical track", default = true)]
    pub track: bool,
}

/// The semi-analytical track matching a column: (mass, φ) points.
pub fn semi_analytical(run: &ColumnParams) -> Vec<[f64; 2]> {
    let porosity = match run.compaction {
        ColumnCompaction::Full => Porosity::Full,
        ColumnCompaction::Collisional => Porosity::Collisional,
    };
    let mut model = GrowthModel::chapter4(porosity);
    model.disk = run.disk.disk();
    model.monomer = run.disk.monomer();
    model.newton = run.newton;
    model.drift = false;
    model.planetesimal_mass = run.stop_mass_g * 1e-3;
    let track = model.run(run.radius_au * AU, run.t_end_yr * YEAR * 10.0);
    track.points.iter().map(|q| [q.mass, q.filling]).collect()
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "families",
        title: "Monte Carlo families",
        source: "Sects. 4.3–4.4; Figs. 4.8, 4.12, 5.2 (bottom)",
        explanation: "Each dot is one family of identical aggregates (its mass and filling factor φ) at a snapshot \
time; a dot says nothing about how many particles the family holds. The line φ_p(m_p) follows the peak \
mass (4.29) over the run; the dashed line is the semi-analytical track of the mass-dominating particle \
    (Sect. 4.5) with the same compaction. Hit-and-stick growth keeps D_f ≈ 2 (φ ∝ m^{-1/2}); collisional \
compaction flattens the track; gas and self-gravity compress the largest bodies. With erosion, fragments \
inherit the fractal dimension of their target (4.14) and the distribution of φ turns bimodal.",
        heavy: true,
    };

    const DECLARED: &'static [crate::scene::core::Declared] = super::common::column_declared![
        super::common::FIRST_SNAPSHOT,
        crate::scene::core::Declared {
            scalar: "*",
            parameter: "track",
            kind: crate::scene::core::Irregularity::Ignored,
            why: "it only draws the semi-analytical track beside the runs",
            resolution: None,
        },
    ];
    const PAUSABLE: bool = true;

    fn inspect(&self, out: &SceneOutput, figure: &str, at: [f64; 2]) -> Option<Inspection> {
        let p = self;
        let runs = out.extra.model::<Vec<Run>>()?;
        let first = runs.first()?;
        let fig = inspect::figure(&out.figures, figure)?;
        let dots: Vec<(f64, &FamilyPoint)> =
            first.snapshots.iter().flat_map(|s| s.families.iter().map(move |f| (s.t, f))).collect();
        let (k, _) = inspect::nearest(fig, dots.iter().map(|(_, f)| [f.mass * 1e3, f.filling]), at, 0.05)?;
        let (t, f) = dots[k];
        let total: f64 = first
            .snapshots
            .iter()
            .find(|s| s.t == t)
            .map_or(0.0, |s| s.families.iter().map(|g| g.mass * g.particles).sum());
        let mono = p.run.disk.monomer();
        let agg = Aggregate { mass: f.mass, filling: f.filling };
        let mut rows = vec![
            inspect::row("snapshot", inspect::value(t / YEAR, "yr")),
            inspect::row("mass m", inspect::value(f.mass * 1e3, "g")),
            inspect::row("in monomers", inspect::value(f.mass / mono.mass(), "")),
            inspect::row("filling factor φ", inspect::value(f.filling, "")),
            inspect::row("size a", inspect::length(agg.radius(&mono))),
            inspect::row("Stokes number Ωt_s", inspect::value(f.stokes, "")),
            inspect::row("particles (weight)", inspect::value(f.particles, "")),
            inspect::row("share of the column's mass", inspect::value(f.mass * f.particles / total.max(1e-300), "")),
        ];
        // Where the dot sits against the semi-analytical track at its mass.
        let track = semi_analytical(&p.run);
        let on_track = track.windows(2).find(|w| (w[0][0]..=w[1][0]).contains(&f.mass)).map(|w| {
            let x = (f.mass / w[0][0]).ln() / (w[1][0] / w[0][0]).ln().max(1e-300);
            (w[0][1].ln() + x * (w[1][1] / w[0][1]).ln()).exp()
        });
        let outcome = on_track.map(|phi| {
            rows.push(inspect::row("φ of the semi-analytical track", inspect::value(phi, "")));
            let ratio = f.filling / phi;
            if (0.5..=2.0).contains(&ratio) {
                format!("on the semi-analytical track (φ/φ_track = {})", crate::figure::human(ratio))
            } else if ratio > 1.0 {
                format!("{}× more compact than the semi-analytical track at this mass", crate::figure::human(ratio))
            } else {
                format!("{}× fluffier than the semi-analytical track at this mass", crate::figure::human(1.0 / ratio))
            }
        });
        Some(Inspection {
            title: format!("Family at {} yr", crate::figure::human(t / YEAR)),
            rows,
            bars: None,
            outcome,
            actions: Vec::new(),
            point: [f.mass * 1e3, f.filling],
        })
    }

    /// The runs at w* ≤ 10, at most two seeds and 0.2 million events a run.
    fn coarse(&self) -> Option<Self> {
        Some(Params { run: self.run.coarse()?, ..self.clone() })
    }

    fn seeds(&mut self) -> Option<Seeds<'_>> {
        Some(self.run.seeds())
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let p = self;
        let runs = super::common::runs_shown_live(&p.run, ctx, |runs| output(p, runs))?;
        let mut out = output(p, &runs);
        out.extra = crate::scene::core::Extra::Model(crate::scene::core::ModelData(runs));
        Ok(out)
    }
}

/// The scene's figures from a set of runs.
fn output(p: &Params, runs: &[Run]) -> SceneOutput {
    let mut fig = Figure::new(
        "families",
        "Families in mass and filling factor",
        Axis::log("mass m", "g"),
        Axis::log("filling factor φ", ""),
    )
    .family("time", "yr", crate::figure::Scale::Log);
    if let Some(first) = runs.first() {
        for (k, s) in first.snapshots.iter().enumerate() {
            let pts = s.families.iter().map(|f| [f.mass * 1e3, f.filling]).collect();
            let label = format!("{} yr", crate::figure::human(s.t / YEAR));
            fig = fig.with(Series::new(label, pts, Style::Points, k).at(s.t / YEAR));
        }
        let peak = first.history.iter().map(|s| [s.m_p * 1e3, s.phi_p]).collect();
        fig = fig.with(Series::new("φ_p(m_p)", peak, Style::Line, 6));
    }
    if p.track {
        let track = semi_analytical(&p.run).into_iter().map(|q| [q[0] * 1e3, q[1]]).collect();
        fig = fig.with(Series::new("semi-analytical", track, Style::Dashed, 7));
    }
    let mut notes = super::common::endings(runs);
    if runs.len() > 1 {
        notes.push(format!("dots show the first run (seed {}) only", p.run.seed));
    }
    SceneOutput {
        warnings: Vec::new(),
        scalars: super::common::summary(runs),
        figures: vec![fig],
        notes,
        extra: crate::scene::core::Extra::None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scene declares what every column declares, and its own two
    /// display parameters.
    #[test]
    fn the_scene_declares_what_every_column_declares() {
        let own = super::super::common::declared_beyond_column(<Params as Scene>::DECLARED);
        let parameters: Vec<&str> = own.iter().map(|d| d.parameter).collect();
        assert_eq!(parameters, ["t_first_yr", "track"]);
        assert_eq!(own[0], super::super::common::FIRST_SNAPSHOT);
    }
}
