//! Scene "Collision speeds" (thesis Fig. 4.2): the relative velocity of two
//! particles over both masses, and its dominant source.

use crate::scene::quantities;
use crate::scene::controls::Control;
use super::common::{DiskParams, radius_control};
use crate::scene::core::{Context, Progress, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace};
use crate::figure::{Axis, Figure, Heatmap, Scale, Series, Style};
use crate::physics::aggregate::{Aggregate, Particle, TurbulenceModel, relative_velocity, stopping_time};
use crate::physics::constants::AU;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The scene (see [`Scene`]).
pub struct CollisionSpeeds;

impl Scene for CollisionSpeeds {
    type Params = Params;
    const INFO: SceneInfo = SceneInfo {
        id: "collision-speeds",
        title: "Collision speeds",
        source: "Sect. 4.2.2, App. 5.B; Eqs. 4.11, 5.21–5.24; Fig. 4.2",
        explanation: "The relative velocity of two particles at the midplane adds Brownian motion \
    (8k_BT(m₁+m₂)/(πm₁m₂))^{1/2}, turbulence (the thesis's three regimes (4.11) or the full Ormel & Cuzzi \
form), differential settling, radial drift 2Ωt_s ηv_K/(1 + (Ωt_s)²) and azimuthal drift \
ηv_K/(1 + (Ωt_s)²) in quadrature (5.24). The first map shows log₁₀ Δv, the second the dominant source \
    (0 Brownian, 1 turbulence, 2 settling, 3 radial drift, 4 azimuthal drift). Brownian motion dominates \
for the smallest particles, turbulence for larger ones and drift near Ωt_s ~ 1; porosity shifts the \
transitions by orders of magnitude in mass.",
        heavy: true,
    };

    fn controls(p: &mut Params) -> Vec<Control<'_>> {
        p.controls()
    }

    fn compute(p: &Params, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        compute(p, ctx.progress)
    }
}

/// Parameters of the collision-speed scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// Disk and monomers.
    pub disk: DiskParams,
    /// Radius, AU (default 5).
    pub radius_au: f64,
    /// Filling factor of both particles (default 1; 10⁻⁴ for the porous map).
    pub filling: f64,
    /// Largest mass in monomer masses (default 10³²).
    pub max_monomers: f64,
    /// Grid points per axis (default 100).
    pub cells: usize,
    /// Use the full Ormel & Cuzzi turbulence form.
    pub ormel_cuzzi: bool,
    /// Dispersion ε of the mass-to-area ratio (default 0.1).
    pub epsilon: f64,
}

impl Default for Params {
    fn default() -> Self {
        Params {
            disk: DiskParams::default(),
            radius_au: 5.0,
            filling: 1.0,
            max_monomers: 1e32,
            cells: 100,
            ormel_cuzzi: false,
            epsilon: 0.1,
        }
    }
}

impl Params {
    /// The documented parameters.
    pub fn controls(&mut self) -> Vec<Control<'_>> {
        let d = Self::default();
        let mut c = self.disk.controls(&d.disk);
        c.push(radius_control(&mut self.radius_au, "where the particles are").default(d.radius_au));
        c.push(Control::number("filling", "filling factor φ", &mut self.filling).default(d.filling).range(1e-6, 1.0).log().doc("of both particles"));
        c.push(quantities::max_monomers(&mut self.max_monomers).default(d.max_monomers).doc("end of both mass axes"));
        c.push(Control::count("cells", "grid points", &mut self.cells).default(d.cells).range(10.0, 400.0).doc("per axis"));
        c.push(Control::toggle("ormel_cuzzi", "Ormel & Cuzzi form", &mut self.ormel_cuzzi).default(d.ormel_cuzzi).doc("full closed form instead of (4.11)"));
        c.push(Control::number("epsilon", "dispersion ε", &mut self.epsilon).default(d.epsilon).range(0.0, 1.0).doc("of the mass-to-area ratio"));
        c
    }
}

/// The collision-speed map: masses m/m₀ of both axes, log₁₀ Δv [m/s] and the
/// dominant source, row by row (m_j rows, m_i columns).
pub struct SpeedMap {
    /// m/m₀ along both axes.
    pub masses: Vec<f64>,
    /// log₁₀ of the relative velocity in m s⁻¹.
    pub log_speed: Vec<f64>,
    /// Index of the dominant source (see `physics::aggregate::SOURCES`).
    pub dominant: Vec<f64>,
}

/// Computes the map on an n × n grid of m/m₀.
pub fn map(p: &Params, progress: &Progress) -> Result<SpeedMap, SceneError> {
    let disk = p.disk.disk();
    let mono = p.disk.monomer();
    let env = disk.local(p.radius_au * AU);
    let m0 = mono.mass();
    let ns = logspace(1.0, p.max_monomers, p.cells);
    let model = if p.ormel_cuzzi { TurbulenceModel::OrmelCuzzi } else { TurbulenceModel::Thesis };
    let particles: Vec<Particle> = ns
        .iter()
        .map(|&n| {
            let agg = Aggregate { mass: n * m0, filling: p.filling };
            Particle { mass: agg.mass, stokes: stopping_time(&env, &mono, &agg, true).time * env.omega }
        })
        .collect();
    progress.check()?;
    let rows: Vec<Vec<(f64, f64)>> = particles
        .par_iter()
        .map(|pj| {
            particles
                .iter()
                .map(|pi| {
                    let v = relative_velocity(&env, pi, pj, model, p.epsilon);
                    (v.total().max(1e-300).log10(), v.dominant() as f64)
                })
                .collect()
        })
        .collect();
    let (log_speed, dominant): (Vec<f64>, Vec<f64>) = rows.into_iter().flatten().unzip();
    Ok(SpeedMap { masses: ns, log_speed, dominant })
}

/// Computes the scene.
pub fn compute(p: &Params, progress: &Progress) -> Result<SceneOutput, SceneError> {
    let SpeedMap { masses: ns, log_speed: dv, dominant: dom } = map(p, progress)?;
    let axis = |s: &str| Axis::log(s, "");
    let mut fig_v = Figure::new(
        "collision-speed",
        "Relative velocity log₁₀ Δv [m/s] (Fig. 4.2)",
        axis("m_i / m₀"),
        axis("m_j / m₀"),
    )
    .square();
    fig_v.heatmap = Some(Heatmap::new(ns.clone(), ns.clone(), dv.clone(), "log₁₀ Δv", "m/s"));
    let mut fig_s = Figure::new(
        "dominant-source",
        "Dominant source of Δv (Fig. 4.2)",
        axis("m_i / m₀"),
        axis("m_j / m₀"),
    )
    .square();
    fig_s.heatmap = Some(Heatmap::categorical(
        ns.clone(),
        ns.clone(),
        dom.clone(),
        "dominant source",
        &crate::physics::aggregate::SOURCES,
    ));
    // Mark the equal-mass diagonal.
    let diag = vec![[ns[0], ns[0]], [ns[ns.len() - 1], ns[ns.len() - 1]]];
    fig_v = fig_v.with(Series::new("m_i = m_j", diag.clone(), Style::Dashed, 6));
    fig_s = fig_s.with(Series::new("m_i = m_j", diag, Style::Dashed, 6));
    // As in Fig. 4.2: contours of Δv over the dominant sources, one per
    // decade of speed.
    let decades: Vec<f64> = (-3..=2).map(f64::from).collect();
    let shown: Vec<String> = decades
        .iter()
        .filter(|&&l| dv.iter().any(|&v| v < l) && dv.iter().any(|&v| v > l))
        .map(|&l| crate::figure::human(10f64.powf(l)))
        .collect();
    let key = format!("Δv = {} m/s", shown.join(", "));
    for level in decades {
        let pts = crate::figure::contour::contour(&ns, &ns, &dv, level, (Scale::Log, Scale::Log));
        if !pts.is_empty() {
            let name = format!("Δv = {} m/s", crate::figure::human(10f64.powf(level)));
            fig_s = fig_s.with(Series::new(name, pts, Style::Line, 6).keyed(key.clone()));
        }
    }
    let max = dv.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mut counts = [0usize; 5];
    for d in &dom {
        counts[*d as usize] += 1;
    }
    let mut scalars =
        vec![Scalar { key: "max_dv", label: "largest Δv on the map", value: 10f64.powf(max), unit: "m s^-1" }];
    let keys = ["share_brownian", "share_turbulence", "share_settling", "share_radial", "share_azimuthal"];
    let labels = [
        "share dominated by Brownian motion",
        "share dominated by turbulence",
        "share dominated by settling",
        "share dominated by radial drift",
        "share dominated by azimuthal drift",
    ];
    for i in 0..5 {
        scalars.push(Scalar { key: keys[i], label: labels[i], value: counts[i] as f64 / dom.len() as f64, unit: "" });
    }
    Ok(SceneOutput { warnings: Vec::new(), scalars, figures: vec![fig_v, fig_s], notes: Vec::new(), extra: crate::scene::core::Extra::None })
}
