//! Scene "Collision speeds" (thesis Fig. 4.2): the relative velocity of two
//! particles over both masses, and its dominant source.

use super::common::DiskParams;
use crate::figure::{Axis, Figure, Heatmap, Scale, Series, Style};
use crate::parallel::prelude::*;
use crate::physics::aggregate::{
    Aggregate, Particle, R_CRIT, SOURCES, TurbulenceModel, relative_velocity, stopping_time,
};
use crate::physics::constants::AU;
use crate::physics::material::Material;
use crate::scene::SceneParams;
use crate::scene::collisions::common::CollisionParams;
use crate::scene::core::{
    Context, Declared, Irregularity, Progress, Scalar, Scene, SceneError, SceneInfo, SceneOutput, logspace,
};
use crate::scene::inspect::{self, Action, Inspection};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use serde::{Deserialize, Serialize};

/// What the collision of two particles of m_i and m_j monomer masses at the
/// scene's radius and filling factor comes to: sizes, Stokes numbers, each
/// source of Δv, and the outcome with the thresholds it was compared to.
pub fn cell(p: &Params, n_i: f64, n_j: f64) -> Inspection {
    let disk = p.disk.disk();
    let mono = p.disk.monomer();
    let env = disk.local(p.radius_au * AU);
    let m0 = mono.mass();
    let model = if p.ormel_cuzzi { TurbulenceModel::OrmelCuzzi } else { TurbulenceModel::Thesis };
    let body = |n: f64| {
        let agg = Aggregate { mass: n * m0, filling: if n <= 1.0 { 1.0 } else { p.filling } };
        let stop = stopping_time(&env, &mono, &agg, true);
        (agg, stop, Particle { mass: agg.mass, stokes: stop.time * env.omega })
    };
    let (ai, si, pi) = body(n_i);
    let (aj, sj, pj) = body(n_j);
    let v = relative_velocity(&env, &pi, &pj, model, p.epsilon);
    let dv = v.total();
    let mut rows = vec![
        inspect::row(
            "masses m_i, m_j",
            format!("{} g, {} g", crate::figure::human(ai.mass * 1e3), crate::figure::human(aj.mass * 1e3)),
        ),
        inspect::row("in monomers", format!("{}, {}", crate::figure::human(n_i), crate::figure::human(n_j))),
        inspect::row(
            "radii a_i, a_j",
            format!("{}, {}", inspect::length(ai.radius(&mono)), inspect::length(aj.radius(&mono))),
        ),
        inspect::row(
            "filling factors φ",
            format!("{}, {}", crate::figure::human(ai.filling), crate::figure::human(aj.filling)),
        ),
        inspect::row(
            "Stokes numbers Ωt_s",
            format!("{}, {}", crate::figure::human(pi.stokes), crate::figure::human(pj.stokes)),
        ),
        inspect::row("drag regimes", format!("{:?}, {:?}", si.regime, sj.regime)),
        inspect::row("relative velocity Δv", inspect::value(dv, "m/s")),
        inspect::row("dominant source", SOURCES[v.dominant()]),
    ];
    let bars = [v.brownian, v.turbulence, v.settling, v.radial, v.azimuthal]
        .iter()
        .zip(SOURCES)
        .map(|(x, name)| (name.to_string(), x.abs()))
        .collect();
    // The outcome, as the Monte Carlo column decides it (Sects. 4.2.3, 4.3),
    // and for two monomers or two compact spheres as the contact model does.
    let mu = ai.mass * aj.mass / (ai.mass + aj.mass);
    let e_imp = 0.5 * mu * dv * dv;
    let e_compact = mono.compaction_energy();
    let v_frag = mono.fragmentation_velocity();
    let ratio = ai.mass.min(aj.mass) / ai.mass.max(aj.mass);
    rows.push(inspect::row("impact energy ½μΔv²", inspect::value(e_imp, "J")));
    rows.push(inspect::row("3bE_roll (compaction onset)", inspect::value(e_compact, "J")));
    let spheres = ai.filling >= 1.0 && aj.filling >= 1.0;
    let pair = crate::physics::contact::Pair {
        radius: {
            let (ri, rj) = (ai.radius(&mono), aj.radius(&mono));
            ri * rj / (ri + rj)
        },
        mass: mu,
        ..mono.pair()
    };
    // The contact model decides for two single monomers; larger pairs
    // follow the aggregate thresholds of ch. 4.
    let outcome = if n_i <= 1.0 && n_j <= 1.0 {
        let v_stick = pair.jkr_sticking_velocity();
        rows.push(inspect::row("v_stick of the two spheres (2.25)", inspect::value(v_stick, "m/s")));
        if dv > v_stick {
            format!(
                "bounce: Δv = {} m/s exceeds v_stick = {} m/s of the two spheres (JKR, 2.25)",
                crate::figure::human(dv),
                crate::figure::human(v_stick)
            )
        } else {
            format!(
                "stick: Δv = {} m/s is below v_stick = {} m/s (JKR, 2.25)",
                crate::figure::human(dv),
                crate::figure::human(v_stick)
            )
        }
    } else if ratio < R_CRIT && dv > p.v_eros {
        format!(
            "erosion: mass ratio {} < R_crit = 10⁻² and Δv above v_eros = {} m/s",
            crate::figure::human(ratio),
            crate::figure::human(p.v_eros)
        )
    } else if dv > v_frag {
        format!("fragmentation: Δv above v_frag = {} m/s (4.12)", crate::figure::human(v_frag))
    } else if e_imp > e_compact {
        format!(
            "stick with compaction: ½μΔv² exceeds 3bE_roll = {} J (b = 0.15); below v_frag = {} m/s{}",
            crate::figure::human(e_compact),
            crate::figure::human(v_frag),
            if p.v_eros < 1e4 {
                format!(" and v_eros = {} m/s", crate::figure::human(p.v_eros))
            } else {
                String::new()
            }
        )
    } else {
        format!("hit-and-stick without compaction: ½μΔv² below 3bE_roll = {} J", crate::figure::human(e_compact))
    };
    let mut actions = Vec::new();
    let (ri, rj) = (ai.radius(&mono), aj.radius(&mono));
    let in_range = (2e-8..=2e-2).contains(&ri) && (2e-8..=2e-2).contains(&rj);
    if spheres && !in_range {
        rows.push(inspect::row("as a collision", "radii outside the contact scene's 20 nm – 2 cm"));
    }
    if spheres && in_range {
        let material = if mono.icy {
            Material::water_ice()
        } else {
            Material::named("silicate").cloned().unwrap_or_else(Material::water_ice)
        };
        let collision = CollisionParams {
            projectile: material.clone(),
            target: material,
            radius_1: ri,
            radius_2: rj,
            surface_energy: mono.surface_energy,
            velocity: dv.clamp(1e-3, 1e3),
            ..CollisionParams::default()
        };
        let what = if n_i <= 1.0 && n_j <= 1.0 { "two monomers" } else { "two compact spheres" };
        actions.push(Action {
            label: "Open as a collision".into(),
            hint: format!(
                "{what} of radii {} and {} meeting head-on at {} m/s in the ch. 2 contact model (Table 2.2 material)",
                inspect::length(ri),
                inspect::length(rj),
                crate::figure::human(dv.clamp(1e-3, 1e3))
            ),
            open: SceneParams::Hysteresis(crate::scene::collisions::hysteresis::Params {
                collision,
                ..Default::default()
            }),
        });
    }
    Inspection {
        title: format!(
            "m_i = {} m₀, m_j = {} m₀ at {} AU",
            crate::figure::human(n_i),
            crate::figure::human(n_j),
            crate::figure::human(p.radius_au)
        ),
        rows,
        bars: Some(("Δv by source [m/s]".into(), bars)),
        outcome: Some(outcome),
        actions,
        point: [n_i, n_j],
    }
}

/// Parameters of the collision-speed scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// Disk and monomers.
    #[param(flatten)]
    pub disk: DiskParams,
    /// where the particles are
    #[param(quantity = quantities::disk_radius, default = 5.0)]
    pub radius_au: f64,
    /// of both particles
    #[param(label = "filling factor φ", range(1e-6, 1.0), log, default = 1.0)]
    pub filling: f64,
    /// end of both mass axes
    #[param(quantity = quantities::max_monomers, default = 1e32)]
    pub max_monomers: f64,
    /// per axis
    #[param(numerical, label = "grid points", range(10.0, 400.0), default = 100)]
    pub cells: usize,
    /// full closed form instead of (4.11)
    #[param(label = "Ormel & Cuzzi form", default = false)]
    pub ormel_cuzzi: bool,
    /// of the mass-to-area ratio
    #[param(label = "dispersion ε", range(0.0, 1.0), default = 0.1)]
    pub epsilon: f64,
    /// erosion threshold a clicked cell's collision is compared with (1e4: none; the maps do not depend on it)
    ///
    /// Erosion threshold the inspected collisions are compared with, m s⁻¹
    /// (default 10⁴: none; it does not change the maps).
    #[param(quantity = quantities::v_eros, style_only, default = 1e4)]
    pub v_eros: f64,
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

/// Why the shares of the dominant sources step.
const DOMINANT: &str = "the dominant source is the largest of five: where two sources scale alike with mass over a \
     region, the whole region changes hands at one parameter value; and a share counts map cells, in steps of one cell";

impl Scene for Params {
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

    const DECLARED: &'static [Declared] = &[
        Declared {
            scalar: "share_brownian",
            parameter: "*",
            kind: Irregularity::Step,
            why: DOMINANT,
            resolution: None,
        },
        Declared {
            scalar: "share_turbulence",
            parameter: "*",
            kind: Irregularity::Step,
            why: DOMINANT,
            resolution: None,
        },
        Declared {
            scalar: "share_settling",
            parameter: "*",
            kind: Irregularity::Step,
            why: DOMINANT,
            resolution: None,
        },
        Declared { scalar: "share_radial", parameter: "*", kind: Irregularity::Step, why: DOMINANT, resolution: None },
        Declared {
            scalar: "share_azimuthal",
            parameter: "*",
            kind: Irregularity::Step,
            why: DOMINANT,
            resolution: None,
        },
    ];

    fn inspect(&self, out: &SceneOutput, figure: &str, at: [f64; 2]) -> Option<Inspection> {
        let p = self;
        let fig = inspect::figure(&out.figures, figure)?;
        let grid = &fig.heatmap.as_ref()?.x;
        // The grid cell under the click.
        let snap = |v: f64| grid.iter().copied().min_by(|a, b| (a / v).ln().abs().total_cmp(&(b / v).ln().abs()));
        Some(cell(p, snap(at[0])?, snap(at[1])?))
    }

    /// Computes the scene.
    fn compute(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
        let (p, progress) = (self, ctx.progress);
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
        let mut fig_s =
            Figure::new("dominant-source", "Dominant source of Δv (Fig. 4.2)", axis("m_i / m₀"), axis("m_j / m₀"))
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
                let value = crate::figure::human(10f64.powf(level));
                let at = crate::figure::contour::label_point(&pts, &ns, &ns, (Scale::Log, Scale::Log));
                fig_s = fig_s.with(Series::new(format!("Δv = {value} m/s"), pts, Style::Line, 6).keyed(key.clone()));
                if let Some(at) = at {
                    fig_s = fig_s.label(at, format!("{value} m/s"), None, crate::figure::Anchor::Center);
                }
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
            scalars.push(Scalar {
                key: keys[i],
                label: labels[i],
                value: counts[i] as f64 / dom.len() as f64,
                unit: "",
            });
        }
        Ok(SceneOutput {
            warnings: Vec::new(),
            scalars,
            figures: vec![fig_v, fig_s],
            notes: Vec::new(),
            extra: crate::scene::core::Extra::None,
        })
    }
}
