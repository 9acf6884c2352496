//! Scene "Formation zone" (thesis Figs. 5.9, 5.10): the outer edge of the
//! region where planetesimals form directly, against disk mass and metallicity.

use super::common::{BatchParams, log_grid, sweep_controls};
use crate::figure::{Axis, Figure, Scale, Series, Style};
use crate::physics::constants::AU;
use crate::scene::controls::Control;
use crate::scene::core::{Censored, Context, Scalar, Scene, SceneError, SceneInfo, SceneOutput};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Parameters of the formation-zone scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The base run (disk mass, metallicity and R_c are swept).
    pub run: BatchParams,
    /// Smallest disk mass, M☉.
    pub mass_min: f64,
    /// Largest disk mass, M☉.
    pub mass_max: f64,
    /// Disk masses.
    pub n_mass: usize,
    /// Metallicities to compare: smallest.
    pub z_min: f64,
    /// Largest metallicity.
    pub z_max: f64,
    /// Metallicities.
    pub n_z: usize,
    /// First characteristic radius, AU.
    pub r_c_1: f64,
    /// Second characteristic radius, AU.
    pub r_c_2: f64,
    /// What the dashed lines change: "r_c" (R_c = r_c_2), "cold" (temperature
    /// halved), "slope" (γ = 3/2) or "alpha" (α = 10⁻⁵); the last three keep
    /// R_c = r_c_1 (Fig. 5.10).
    pub contrast: String,
}

impl Default for Params {
    fn default() -> Self {
        Params {
            run: BatchParams::default(),
            mass_min: 0.01,
            mass_max: 0.2,
            n_mass: 5,
            z_min: 0.01,
            z_max: 0.05,
            n_z: 3,
            r_c_1: 30.0,
            r_c_2: 100.0,
            contrast: "r_c".into(),
        }
    }
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "formation-zone",
        title: "Formation zone",
        source: "Sect. 5.3.2; Figs. 5.9, 5.10",
        explanation: "The outermost radius at which batches become planetesimals within the run, against \
disk mass, for several metallicities. Solid lines use R_c; the dashed set changes one thing: a second \
R_c (Fig. 5.9), a cold disk with the temperature halved, the slope 3/2 or α = 1e-5 (Fig. 5.10). \
Massive, dust-rich disks form planetesimals further out; a cold disk nearly doubles the zone. All \
disks run in parallel, each also with half the batches: the change estimates the edges' resolution error.",
        heavy: true,
    };

    const CENSORED: &'static [Censored] = &[
        Censored { key: "widest_zone", above: None, undefined: Some("no disk of the grid forms planetesimals") },
        Censored { key: "widest_zone_error", above: None, undefined: Some("no disk of the grid forms planetesimals") },
    ];

    /// The documented parameters.
    fn controls(&mut self) -> Vec<Control<'_>> {
        let d = Self::default();
        let mut c = self.run.controls(&d.run);
        // The sweep sets these for every disk.
        c.retain(|c| !["profile", "disk_mass", "metallicity", "r_c"].contains(&c.key));
        c.extend(sweep_controls(
            (&mut self.mass_min, &mut self.mass_max, &mut self.n_mass),
            (&mut self.z_min, &mut self.z_max, &mut self.n_z),
            [(d.mass_min, d.mass_max, d.n_mass), (d.z_min, d.z_max, d.n_z)],
        ));
        c.push(
            Control::number("r_c_1", "R_c (solid)", &mut self.r_c_1)
                .default(d.r_c_1)
                .unit("AU")
                .range(5.0, 300.0)
                .log()
                .doc("first characteristic radius"),
        );
        c.push(
            Control::number("r_c_2", "R_c (dashed)", &mut self.r_c_2)
                .default(d.r_c_2)
                .unit("AU")
                .range(5.0, 300.0)
                .log()
                .doc("second characteristic radius"),
        );
        c.push(
            Control::choice(
                "contrast",
                "dashed lines",
                &mut self.contrast,
                vec![("r_c", "second R_c"), ("cold", "cold disk (T/2)"), ("slope", "slope 3/2"), ("alpha", "α = 10⁻⁵")],
            )
            .default(d.contrast.clone())
            .doc("what the dashed lines change (Fig. 5.9: R_c; Fig. 5.10: cold, slope; or alpha)"),
        );
        c
    }

    fn coarse(&self) -> Option<Self> {
        let p = self;
        let n_mass = p.n_mass.min(3);
        Some(Params { run: p.run.coarse_over(2 * n_mass * p.n_z), n_mass, ..p.clone() })
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
        let masses = log_grid(p.mass_min, p.mass_max, p.n_mass);
        let zs = log_grid(p.z_min, p.z_max, p.n_z);
        let (nz, nm) = (zs.len(), masses.len());
        let combos: Vec<(usize, usize, usize)> =
            (0..2).flat_map(|c| (0..nz).flat_map(move |zi| (0..nm).map(move |mi| (c, zi, mi)))).collect();
        let done = std::sync::atomic::AtomicUsize::new(0);
        // Every disk also runs with half the batches: the change says how far
        // the edges are from converged (it can understate it where the edge
        // still drifts with the batch count, see the README).
        let half = (p.run.batches / 2).max(10);
        let runs: Vec<(usize, usize, usize, usize)> =
            [p.run.batches, half].iter().flat_map(|&n| combos.iter().map(move |&(c, zi, mi)| (c, zi, mi, n))).collect();
        let total = runs.len();
        let all: Vec<f64> = runs
            .par_iter()
            .map(|&(c, zi, mi, batches)| {
                let mut b = BatchParams { batches, ..p.run.clone() };
                b.disk.profile = "power-law".into();
                b.disk.disk_mass = masses[mi];
                b.disk.metallicity = zs[zi];
                b.disk.r_c = p.r_c_1;
                if c == 1 {
                    match p.contrast.as_str() {
                        "cold" => b.disk.cold = !b.disk.cold,
                        "slope" => b.disk.slope = 1.5,
                        "alpha" => b.disk.alpha = 1e-5,
                        _ => b.disk.r_c = p.r_c_2,
                    }
                }
                b.run_in_sweep(progress, &done, total).map(|r| r.outermost_planetesimals() / AU)
            })
            .collect::<Result<_, _>>()?;
        let (edges, coarser) = all.split_at(combos.len());
        let mut fig = Figure::new(
            "formation-zone",
            "Outer edge of planetesimal formation (Figs. 5.9, 5.10)",
            Axis::log("disk mass", "M☉"),
            Axis::linear("outer edge", "AU"),
        )
        // Metallicity is the colour (a colour bar), the disk set the line style.
        .family("metallicity Z₀", "", Scale::Log);
        let mut scalars = Vec::new();
        for c in 0..2 {
            for (zi, z) in zs.iter().enumerate() {
                let pts: Vec<[f64; 2]> = masses
                    .iter()
                    .enumerate()
                    .map(|(mi, m)| [*m, edges[(c * zs.len() + zi) * masses.len() + mi]])
                    .collect();
                let label = match (c, p.contrast.as_str()) {
                    (1, "cold") => format!("R_c = {} AU, cold", crate::figure::human(p.r_c_1)),
                    (1, "slope") => format!("R_c = {} AU, slope 3/2", crate::figure::human(p.r_c_1)),
                    (1, "alpha") => format!("R_c = {} AU, α = 10⁻⁵", crate::figure::human(p.r_c_1)),
                    (1, _) => format!("R_c = {} AU", crate::figure::human(p.r_c_2)),
                    _ => format!("R_c = {} AU", crate::figure::human(p.r_c_1)),
                };
                fig = fig.with(
                    Series::new(
                        format!("Z₀ = {}, {label}", crate::figure::human(*z)),
                        pts,
                        if c == 0 { Style::Line } else { Style::Dashed },
                        zi,
                    )
                    .at(*z)
                    .keyed(label),
                );
            }
        }
        // NaN (undefined) where no disk of the grid forms planetesimals.
        let widest_of =
            |e: &[f64]| Some(e.iter().copied().fold(0.0, f64::max)).filter(|&r| r > 0.0).unwrap_or(f64::NAN);
        let widest = widest_of(edges);
        let widest_error = (widest - widest_of(coarser)).abs();
        let largest_error = edges.iter().zip(coarser).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        scalars.push(Scalar { key: "widest_zone", label: "largest outer edge on the grid", value: widest, unit: "AU" });
        scalars.push(Scalar {
            key: "widest_zone_error",
            label: "its change with half the batches",
            value: if widest.is_nan() { f64::NAN } else { widest_error },
            unit: "AU",
        });
        scalars.push(Scalar {
            key: "edge_error",
            label: "largest change with half the batches",
            value: largest_error,
            unit: "AU",
        });
        scalars.push(Scalar { key: "disks", label: "disks run", value: edges.len() as f64, unit: "" });
        Ok(SceneOutput { scalars, figures: vec![fig], ..Default::default() })
    }
}
