//! Scene "Surface density" (thesis Figs. 5.1, 5.3 top, 5.5 top, 5.11): gas,
//! dust and planetesimal surface densities of the batch model at chosen times.

use super::common::{BATCH_STEPS, BatchParams, RunCache, batch_quantised};
use crate::figure::{Axis, Figure, Scale, Series, Style};
use crate::physics::batches::{Fate, surface_density, surface_density_in};
use crate::physics::constants::{AU, YEAR};
use crate::scene::core::{
    Context, Cursor, Declared, Irregularity, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace,
};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use crate::scene::timeline;
use serde::{Deserialize, Serialize};

/// Parameters of the surface-density scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The run.
    #[param(flatten)]
    pub run: BatchParams,
    /// the dust snapshot to highlight, as a fraction of their span in log time
    ///
    /// Time cursor over the dust snapshots, as a fraction of their span in
    /// log time (styling only).
    #[param(quantity = quantities::time_cursor, style_only)]
    pub cursor: f64,
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "surface-density",
        title: "Surface density",
        source: "Sects. 5.2.2–5.3; Eqs. 5.1, 5.6–5.8; Figs. 5.1, 5.3, 5.5, 5.11",
        explanation: "Dust starts as monomers in batches between the inner and outer radius with Σ_d = Z₀Σ_g \
    (5.1). Each batch keeps its total mass; its particles grow by (5.10) and drift by (5.8). The dust \
surface density follows from the batch positions: Σ_d = (1/2πR) dM_C/dR (5.6)–(5.7), computed over each \
batch and two neighbours on either side so that a few batches in a depleted region do not make \
spikes. Batches whose particles reach 10¹⁶ g become planetesimals (Σ_p); batches inside 1 AU are no \
longer followed. Without coagulation (Fig. 5.1) the dust drifts and piles up inside; compact silicates \
with v_frag = 5 m/s empty the disk within 10⁶ yr (Fig. 5.3); porous ices form planetesimals in the \
inner disk (Fig. 5.5), unless erosion prevents it (Fig. 5.11).",
        heavy: true,
    };

    const DECLARED: &'static [Declared] = &[
        BATCH_STEPS,
        batch_quantised("cold"),
        Declared {
            scalar: "*",
            parameter: "surface_density",
            kind: Irregularity::Ignored,
            why: "the run's drift and growth use the gas, not the dust estimate; the estimate only draws Σ_d",
            resolution: None,
        },
        Declared {
            scalar: "*",
            parameter: "smoothing",
            kind: Irregularity::Ignored,
            why: "the run's drift and growth use the gas, not the dust estimate; the kernel only draws Σ_d",
            resolution: None,
        },
    ];

    fn coarse(&self) -> Option<Self> {
        Some(Params { run: self.run.coarse(), ..self.clone() })
    }

    fn time_cursor(&mut self) -> Option<&mut f64> {
        Some(&mut self.cursor)
    }

    fn cursor(&self, out: &SceneOutput) -> Option<Cursor> {
        let p = self;
        let fig = out.figures.iter().find(|f| f.id == "surface-density")?;
        let (lo, hi) = fig.family_range()?;
        let t = timeline::time_at((lo, hi), p.cursor, Scale::Log);
        let (mark, shown) = timeline::snapshot(out, "surface-density", t)?;
        let label = format!("t = {} yr (nearest snapshot)", crate::figure::human(shown));
        Some(Cursor { fraction: p.cursor, label, marks: vec![mark], optional: true })
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let cache: &mut RunCache = ctx.caches.get();
        let run = cache.get(&p.run, progress)?;
        let cfg = p.run.config();
        let (disk, smoothing) = (cfg.model.disk, cfg.density_smoothing());
        let rs = logspace(1.0, p.run.r_out_au * 1.5, 120);
        let mut fig = Figure::new(
            "surface-density",
            "Surface densities",
            Axis::log("radius R", "AU"),
            Axis::log("surface density", "g/cm²"),
        )
        .family("time of the dust curve", "yr", Scale::Log)
        .with(Series::new(
            "gas Σ_g",
            rs.iter().map(|&r| [r, disk.surface_density(r * AU) * 0.1]).collect(),
            Style::Dashed,
            6,
        ))
        .with(Series::new(
            "initial dust Z₀Σ_g",
            rs.iter().map(|&r| [r, disk.dust_surface_density(r * AU) * 0.1]).collect(),
            Style::Dashed,
            7,
        ));
        // Frames at roughly each decade of time.
        let mut shown = Vec::new();
        for (k, decade) in [1e3, 1e4, 1e5, 1e6, 1e7].iter().enumerate() {
            let Some(f) = run.frames.iter().rfind(|f| f.t <= decade * YEAR * 1.0001) else { continue };
            if shown.contains(&f.t) {
                continue;
            }
            shown.push(f.t);
            let dust: Vec<(f64, f64)> =
                f.batches.iter().zip(&run.masses).filter(|(b, _)| b.dust).map(|(b, m)| (b.r, *m)).collect();
            let sd = surface_density_in(&dust, smoothing, Some(cfg.domain()));
            let mut pts: Vec<[f64; 2]> = dust.iter().zip(&sd).map(|((r, _), s)| [r / AU, s * 0.1]).collect();
            crate::sorting::sort_by_key(&mut pts, |a| a[0]);
            let t = f.t / YEAR;
            fig = fig.with(Series::new(format!("dust, {} yr", crate::figure::human(t)), pts, Style::Line, k).at(t));
        }
        // Planetesimals where they formed.
        let formed: Vec<(f64, f64)> = run
            .fates
            .iter()
            .zip(&run.masses)
            .filter_map(|(f, m)| if let Fate::Planetesimals { r, .. } = f { Some((*r, *m)) } else { None })
            .collect();
        if !formed.is_empty() {
            let sp = surface_density(&formed, smoothing);
            let mut pts: Vec<[f64; 2]> = formed.iter().zip(&sp).map(|((r, _), s)| [r / AU, s * 0.1]).collect();
            crate::sorting::sort_by_key(&mut pts, |a| a[0]);
            fig = fig.with(Series::new("planetesimals Σ_p (end)", pts, Style::Points, 4));
        }
        let last = run.frames.last().map(|f| f.budget).unwrap_or([0.0; 3]);
        let scalars = vec![
            Scalar { key: "dust_fraction", label: "dust left at the end", value: last[0] / run.total_mass, unit: "" },
            Scalar {
                key: "planetesimal_fraction",
                label: "converted into planetesimals",
                value: last[1] / run.total_mass,
                unit: "",
            },
            Scalar {
                key: "lost_fraction",
                label: "drifted inside the inner edge",
                value: last[2] / run.total_mass,
                unit: "",
            },
            Scalar {
                key: "outermost_planetesimals",
                label: "outermost planetesimal formation",
                value: run.outermost_planetesimals() / AU,
                unit: "AU",
            },
            Scalar { key: "total_dust_mass", label: "initial dust mass", value: run.total_mass, unit: "kg" },
        ];
        Ok(SceneOutput { scalars, figures: vec![fig], ..Default::default() })
    }
}
