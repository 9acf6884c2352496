//! Scene "Disk map" (thesis Figs. 5.4, 5.6, 5.12–5.14): batch radius against
//! time with the Stokes-number window, planetesimal formation and the
//! midplane mass loading.

use super::common::{BATCH_STEPS, BatchParams, RunCache};
use crate::figure::{Axis, Figure, Scale, Series, Style};
use crate::physics::batches::Fate;
use crate::physics::constants::{AU, YEAR};
use crate::scene::core::{
    Censored, Context, Cursor, Declared, Irregularity, Scalar, Scene, SceneError, SceneInfo, SceneOutput,
};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use crate::scene::timeline;
use serde::{Deserialize, Serialize};

/// Parameters of the disk-map scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The run.
    #[param(flatten)]
    pub run: BatchParams,
    /// thins the paths
    #[param(figure_only, label = "draw every n-th batch", range(1.0, 100.0), default = 5)]
    pub every: usize,
    /// time marked on the batch paths, as a fraction of the run in log time
    #[param(quantity = quantities::time_cursor, style_only, default = 0.0)]
    pub cursor: f64,
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "disk-map",
        title: "Disk map",
        source: "Sects. 5.3–5.4; Eq. 5.13; Figs. 5.4, 5.6, 5.12–5.14",
        explanation: "Each batch's radius against time (grey paths). Along the drawn paths, green points: the mass-dominating \
particles have 10⁻³ ≤ Ωt_s ≤ 1. Yellow, vermilion, purple: the midplane dust-to-gas ratio of \
particles with 10⁻² ≤ Ωt_s ≤ 1, (ρ*_d/ρ_g) = Z* h_g/h_d (5.13), exceeds 0.1, 0.5 and 1. Light-blue \
diamonds: planetesimal formation. Streaming instability needs i) 10⁻² ≤ Ωt_s ≤ 1, ii) a loading near unity and iv) \
t_grow > Ω⁻¹ (Sect. 5.4.1); the count of batches meeting all three is reported. Labelled dashed lines \
mark the present orbits of Jupiter, Saturn, Uranus and Neptune.",
        heavy: true,
    };

    const DECLARED: &'static [Declared] = &[
        Declared {
            scalar: "max_loading",
            parameter: "*",
            kind: Irregularity::Step,
            why: "the largest loading over every batch and frame: a maximum that the one batch at the inner front of \
                  the 10⁻² ≤ Ωt_s ≤ 1 window sets, so it jumps where that batch changes, and it does not settle as the \
                  batches grow in number (batch-fig-5-4 at R_c = 205 AU: 0.09 with 40 batches, 0.2–0.8 with 160, \
                  0.17–0.63 with 640); read it as an order of magnitude, as the thesis does (~0.1)",
            resolution: None,
        },
        Declared {
            scalar: "loading_top_tenth",
            parameter: "dlnm",
            kind: Irregularity::Step,
            why: "the growth step moves each batch's path a little, and the frames catch its passage into the \
                  10⁻² ≤ Ωt_s ≤ 1 window (where its loading jumps from 0) a frame earlier or later: steps of 2–3 % along \
                  dlnm at every batch count (batch-fig-5-4: 0.0746–0.0770 at 40 batches, 0.0756–0.0788 at 160, \
                  0.0773–0.0800 at 640 for dlnm 0.185–0.189), the size of the scalar's own step error",
            resolution: None,
        },
        BATCH_STEPS,
    ];

    const CENSORED: &'static [Censored] =
        &[Censored { key: "outermost_planetesimals", above: None, undefined: Some("no planetesimals form") }];

    fn inspect(&self, out: &SceneOutput, figure: &str, at: [f64; 2]) -> Option<crate::scene::inspect::Inspection> {
        let p = self;
        let run = out.extra.model::<crate::physics::batches::BatchRun>()?;
        let fig = crate::scene::inspect::figure(&out.figures, figure)?;
        super::common::inspect_batch(&p.run, run, fig, at, &|t, s| [t / YEAR, s.r / AU])
    }

    fn coarse(&self) -> Option<Self> {
        Some(Params { run: self.run.coarse(), ..self.clone() })
    }

    fn time_cursor(&mut self) -> Option<&mut f64> {
        Some(&mut self.cursor)
    }

    fn cursor(&self, out: &SceneOutput) -> Option<Cursor> {
        let p = self;
        let range = timeline::x_range(out, "disk-map")?;
        let t = timeline::time_at(range, p.cursor, Scale::Log);
        let marks = timeline::along_x(out, "disk-map", t);
        Some(Cursor { fraction: p.cursor, label: format!("t = {} yr", crate::figure::human(t)), marks, optional: true })
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let cache: &mut RunCache = ctx.caches.get();
        let run = cache.get(&p.run, progress)?;
        let mut fig =
            Figure::new("disk-map", "Batch radius against time", Axis::log("time", "yr"), Axis::log("radius R", "AU"));
        let n = run.masses.len();
        for i in (0..n).step_by(p.every.max(1)) {
            let pts: Vec<[f64; 2]> =
                run.frames.iter().filter(|f| f.batches[i].dust).map(|f| [f.t / YEAR, f.batches[i].r / AU]).collect();
            fig = fig.with(Series::new("", pts, Style::Line, 6));
        }
        let mut window = Vec::new();
        let mut levels: [Vec<[f64; 2]>; 3] = [Vec::new(), Vec::new(), Vec::new()];
        let mut si = 0usize;
        let mut max_loading: f64 = 0.0;
        let every = p.every.max(1);
        for f in &run.frames {
            for (i, b) in f.batches.iter().enumerate().filter(|(_, b)| b.dust) {
                // Marked along the drawn paths; counted over every batch.
                let pt = [f.t / YEAR, b.r / AU];
                let drawn = i % every == 0;
                if drawn && (1e-3..=1.0).contains(&b.stokes) {
                    window.push(pt);
                }
                for (k, lvl) in [0.1, 0.5, 1.0].iter().enumerate() {
                    if drawn && b.loading >= *lvl {
                        levels[k].push(pt);
                    }
                }
                max_loading = max_loading.max(b.loading);
                si += usize::from(b.si);
            }
        }
        // Markers shrink as drawn paths crowd the radii.
        let size = super::common::marker_size(n, every);
        fig = fig.with(Series::new("10⁻³ ≤ Ωt_s ≤ 1", window, Style::Points, 2).sized(size));
        // Loading levels in colours apart in hue and lightness: dark yellow,
        // vermilion, reddish purple.
        for (k, (pts, name)) in levels.into_iter().zip(["ρ*/ρ_g ≥ 0.1", "ρ*/ρ_g ≥ 0.5", "ρ*/ρ_g ≥ 1"]).enumerate()
        {
            fig = fig.with(Series::new(name, pts, Style::Points, [7, 0, 4][k]).sized(size));
        }
        let formed: Vec<[f64; 2]> = run
            .fates
            .iter()
            .filter_map(|f| if let Fate::Planetesimals { t, r } = f { Some([t / YEAR, r / AU]) } else { None })
            .collect();
        fig = fig.with(Series::new("planetesimals form", formed, Style::Marker, 5));
        let t0 = run.frames.first().map_or(1.0, |f| f.t / YEAR);
        let t1 = p.run.duration_yr;
        for (name, a) in [("Jupiter", 5.2), ("Saturn", 9.5), ("Uranus", 19.2), ("Neptune", 30.1)] {
            // One legend entry for the four reference orbits.
            fig = fig
                .with(
                    Series::new(name, vec![[t0, a], [t1, a]], Style::Dashed, 1)
                        .keyed("Jupiter, Saturn, Uranus, Neptune"),
                )
                .label([t0, a], name, Some(1), crate::figure::Anchor::Left);
        }
        let scalars = vec![
            Scalar {
                key: "outermost_planetesimals",
                label: "outermost planetesimal formation",
                // NaN (undefined) where no batch forms planetesimals.
                value: Some(run.outermost_planetesimals() / AU).filter(|&r| r > 0.0).unwrap_or(f64::NAN),
                unit: "AU",
            },
            Scalar { key: "max_loading", label: "largest midplane ρ*_d/ρ_g", value: max_loading, unit: "" },
            Scalar {
                key: "loading_top_tenth",
                label: "midplane ρ*_d/ρ_g reached by a tenth of the dust",
                value: run.loading_reached_by(0.1),
                unit: "",
            },
            Scalar {
                key: "si_samples",
                label: "batch samples meeting SI conditions i, ii, iv",
                value: si as f64,
                unit: "",
            },
            Scalar {
                key: "converted",
                label: "converted into planetesimals",
                value: run.converted_fraction(),
                unit: "",
            },
        ];
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig],
            notes: Vec::new(),
            extra: crate::scene::core::Extra::Model(crate::scene::core::ModelData(run.clone())),
        })
    }
}
