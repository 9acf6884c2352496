//! Scene "Planetesimal yield" (thesis Figs. 5.7, 5.8): planetesimal mass and
//! converted fraction against time for a grid of disks.

use super::common::{BATCH_STEPS, BatchParams, batch_quantised, log_grid};
use crate::figure::{Axis, Figure, Scale, Series, Style};
use crate::parallel::prelude::*;
use crate::physics::constants::YEAR;
use crate::scene::core::{Context, Declared, Irregularity, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use crate::scene::disk::common::DiskProfile;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// Parameters of the yield scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The base run (its disk mass and metallicity are swept).
    #[param(flatten, except("profile", "disk_mass", "metallicity"), default = BatchParams { batches: 150, ..BatchParams::default() })]
    pub run: BatchParams,
    /// first disk mass
    #[param(label = "smallest disk mass", unit = "M_sun", range(1e-3, 0.5), log, default = 0.01)]
    pub mass_min: f64,
    /// last disk mass
    #[param(label = "largest disk mass", unit = "M_sun", range(1e-3, 0.5), log, default = 0.1)]
    pub mass_max: f64,
    /// log-spaced
    #[param(label = "disk masses", range(1, 12), default = 3)]
    pub n_mass: usize,
    /// first metallicity
    #[param(label = "smallest Z₀", range(1e-3, 0.1), log, default = 0.01)]
    pub z_min: f64,
    /// last metallicity
    #[param(label = "largest Z₀", range(1e-3, 0.1), log, default = 0.02)]
    pub z_max: f64,
    /// log-spaced
    #[param(label = "metallicities", range(1, 6), default = 2)]
    pub n_z: usize,
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "planetesimal-yield",
        title: "Planetesimal yield",
        source: "Sect. 5.3.2; Figs. 5.7, 5.8",
        explanation: "Total planetesimal mass and the fraction of the dust converted, against time, for \
disks of several masses and metallicities (porous perfect sticking unless set otherwise). The runs \
are independent and go in parallel.",
        heavy: true,
    };

    const DECLARED: &'static [Declared] = &[
        BATCH_STEPS,
        batch_quantised("dlnm"),
        batch_quantised("settling"),
        Declared {
            scalar: "min_converted",
            parameter: "z_max",
            kind: Irregularity::Ignored,
            why: "the least converted disk is the poorest in metals, at the smallest Z₀",
            resolution: None,
        },
    ];

    fn coarse(&self) -> Option<Self> {
        Some(Params { run: self.run.coarse_over(self.n_mass * self.n_z), ..self.clone() })
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let combos: Vec<(f64, f64)> = log_grid(p.mass_min, p.mass_max, p.n_mass)
            .into_iter()
            .flat_map(|m| log_grid(p.z_min, p.z_max, p.n_z).into_iter().map(move |z| (m, z)))
            .collect();
        if combos.is_empty() {
            return Err(crate::scene::controls::ParamError::Inconsistent("the sweep is empty".into()).into());
        }
        let done = std::sync::atomic::AtomicUsize::new(0);
        let total = combos.len();
        let runs: Vec<_> = combos
            .par_iter()
            .map(|&(m, z)| {
                let mut b = p.run.clone();
                b.disk.profile = DiskProfile::PowerLaw;
                b.disk.disk_mass = m;
                b.disk.metallicity = z;
                b.run_in_sweep(progress, &done, total).map(|r| (m, z, r))
            })
            .collect::<Result<_, _>>()?;
        let mut fig_m = Figure::new(
            "planetesimal-mass",
            "Planetesimal mass (Fig. 5.7)",
            Axis::log("time", "yr"),
            Axis::log("planetesimal mass", "M⊕"),
        );
        let mut fig_f = Figure::new(
            "converted-fraction",
            "Converted fraction (Fig. 5.8)",
            Axis::log("time", "yr"),
            Axis::linear("fraction of the dust in planetesimals", ""),
        );
        let mut scalars = Vec::new();
        let mut min_fraction: f64 = 1.0;
        // Up to three metallicities: the disk mass is the colour (a colour bar)
        // and the metallicity the line style (one legend row each); more are
        // told apart by colour alone.
        let zs = log_grid(p.z_min, p.z_max, p.n_z);
        let by_style = zs.len() <= 3 && p.n_mass > 1;
        if by_style {
            fig_m = fig_m.family("disk mass", "M☉", Scale::Log);
            fig_f = fig_f.family("disk mass", "M☉", Scale::Log);
        }
        for (k, (m, z, run)) in runs.iter().enumerate() {
            let name = format!("M_D = {} M☉, Z₀ = {}", crate::figure::human(*m), crate::figure::human(*z));
            let earth = 5.972e24;
            let series = |points: Vec<[f64; 2]>| {
                let zi = zs.iter().position(|x| x == z).unwrap_or(0);
                if by_style {
                    let style = [Style::Line, Style::Dashed, Style::Dotted][zi.min(2)];
                    Series::new(name.clone(), points, style, 0)
                        .at(*m)
                        .keyed(format!("Z₀ = {}", crate::figure::human(*z)))
                } else {
                    Series::new(name.clone(), points, Style::Line, k)
                }
            };
            fig_m = fig_m.with(series(run.frames.iter().map(|f| [f.t / YEAR, f.budget[1] / earth]).collect()));
            fig_f = fig_f.with(series(run.frames.iter().map(|f| [f.t / YEAR, f.budget[1] / run.total_mass]).collect()));
            min_fraction = min_fraction.min(run.converted_fraction());
        }
        scalars.push(Scalar {
            key: "min_converted",
            label: "smallest converted fraction at the end",
            value: min_fraction,
            unit: "",
        });
        scalars.push(Scalar { key: "runs", label: "disks run", value: runs.len() as f64, unit: "" });
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig_m, fig_f],
            notes: Vec::new(),
            extra: crate::scene::core::Extra::None,
        })
    }
}
