//! Scene "Batch lifelines" (thesis Figs. 5.3, 5.5): particle mass against
//! radius for every batch, coloured by Stokes number.

use super::common::{BatchParams, RunCache};
use crate::figure::{Axis, Figure, Series, Style};
use crate::physics::constants::AU;
use crate::scene::core::{Context, Declared, Irregularity, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the lifeline scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The run.
    #[param(flatten)]
    pub run: BatchParams,
    /// else by Stokes number
    #[param(figure_only, label = "colour by φ", default = false)]
    pub colour_by_filling: bool,
    /// thins the paths
    #[param(figure_only, label = "draw every n-th batch", range(1.0, 100.0), default = 5)]
    pub every: usize,
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "batch-lifelines",
        title: "Batch lifelines",
        source: "Sect. 5.3; Figs. 5.3 (middle, bottom), 5.5",
        explanation: "Every batch's particle mass against its radius over the run: growth at fixed radius, \
then drift once Ωt_s approaches unity. Points are coloured by the decade of the Stokes number \
    (Ωt_s < 10⁻⁴, 10⁻⁴–10⁻³, …, > 1) or by the filling factor, along the paths drawn (every n-th batch).",
        heavy: true,
    };

    const DECLARED: &'static [Declared] = &[Declared {
        scalar: "*",
        parameter: "*",
        kind: Irregularity::Ignored,
        why: "a figure of the batches' paths: the scene reports only the monomer's scalars (the disk map reports the run's)",
        resolution: None,
    }];

    fn inspect(&self, out: &SceneOutput, figure: &str, at: [f64; 2]) -> Option<crate::scene::inspect::Inspection> {
        let p = self;
        let run = out.extra.model::<crate::physics::batches::BatchRun>()?;
        let fig = crate::scene::inspect::figure(&out.figures, figure)?;
        super::common::inspect_batch(&p.run, run, fig, at, &|_, s| [s.r / AU, s.mass * 1e3])
    }

    fn coarse(&self) -> Option<Self> {
        Some(Params { run: self.run.coarse(), ..self.clone() })
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let cache: &mut RunCache = ctx.caches.get();
        let run = cache.get(&p.run, progress)?;
        let mut fig = Figure::new(
            "batch-lifelines",
            "Particle mass against radius of the batches",
            Axis::log("radius R", "AU"),
            Axis::log("particle mass", "g"),
        );
        let n = run.masses.len();
        for i in (0..n).step_by(p.every.max(1)) {
            let pts: Vec<[f64; 2]> = run
                .frames
                .iter()
                .map(|f| &f.batches[i])
                .filter(|b| b.mass > 0.0)
                .map(|b| [b.r / AU, b.mass * 1e3])
                .collect();
            fig = fig.with(Series::new("", pts, Style::Line, 6));
        }
        let labels_st = ["Ωt_s < 10⁻⁴", "10⁻⁴ – 10⁻³", "10⁻³ – 10⁻²", "10⁻² – 10⁻¹", "10⁻¹ – 1", "Ωt_s > 1"];
        let labels_phi = ["φ < 10⁻⁵", "10⁻⁵ – 10⁻⁴", "10⁻⁴ – 10⁻³", "10⁻³ – 10⁻²", "10⁻² – 10⁻¹", "φ > 10⁻¹"];
        let mut bins: Vec<Vec<[f64; 2]>> = vec![Vec::new(); 6];
        // Marked along the drawn paths, with markers that shrink as paths crowd.
        let every = p.every.max(1);
        let size = super::common::marker_size(n, every);
        for f in &run.frames {
            for (_, b) in f.batches.iter().enumerate().filter(|(i, b)| i % every == 0 && b.dust && b.mass > 0.0) {
                let x = if p.colour_by_filling { b.filling.log10() + 5.0 } else { b.stokes.log10() + 4.0 };
                let k = (x.floor().max(-1.0) + 1.0).clamp(0.0, 5.0) as usize;
                bins[k].push([b.r / AU, b.mass * 1e3]);
            }
        }
        for (k, pts) in bins.into_iter().enumerate() {
            if !pts.is_empty() {
                let name = if p.colour_by_filling { labels_phi[k] } else { labels_st[k] };
                fig = fig.with(Series::new(name, pts, Style::Points, k).sized(size));
            }
        }
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars: vec![crate::scene::core::Scalar {
                key: "frames",
                label: "recorded frames",
                value: run.frames.len() as f64,
                unit: "",
            }],
            figures: vec![fig],
            notes: Vec::new(),
            extra: crate::scene::core::Extra::Model(crate::scene::core::ModelData(run.clone())),
        })
    }
}
