//! Scene "Mass distribution" (thesis Figs. 4.4–4.7, 4.9): the Monte Carlo
//! mass distribution m²f(m)/ρ_d of a disk column at chosen times, mean ± 1σ
//! over runs, with the growth and drift timescales of the peak mass.

use super::common::{ColumnParams, endings, summary};
use crate::figure::{Axis, Figure, Scale, Series, Style};
use crate::physics::coagulation::{Run, Sample, mass_distribution};
use crate::physics::constants::YEAR;
use crate::scene::core::{Context, Cursor, Scene, SceneError, SceneInfo, SceneOutput, Seeds};
use crate::scene::quantities;
use crate::scene::schema::ParamSet;
use crate::scene::timeline;
use serde::{Deserialize, Serialize};

/// Parameters of the scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ParamSet)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// The runs.
    #[param(flatten)]
    pub run: ColumnParams,
    /// histogram
    #[param(figure_only, label = "bins per decade", range(1.0, 10.0), default = 2)]
    pub bins_per_decade: usize,
    /// time marked on the peak mass and the nearest snapshot, as a fraction of the run in log time
    #[param(quantity = quantities::time_cursor, style_only, default = 0.0)]
    pub cursor: f64,
}

/// Growth time t_grow = m_p/(dm_p/dt) (4.30) from the history, over steps in
/// which m_p grew by at least a factor 10^{1/8} (the peak mass is noisy
/// between samples): (m_p at the step's midpoint, t_grow, t_drift), s.
pub fn growth_times(history: &[Sample]) -> Vec<(f64, f64, f64)> {
    let step = 10f64.powf(0.125);
    let mut out = Vec::new();
    let Some(mut anchor) = history.first() else { return out };
    for s in &history[1..] {
        if s.m_p < anchor.m_p {
            // Shrinking (erosion): restart from here.
            anchor = s;
        } else if s.m_p >= anchor.m_p * step && s.t > anchor.t {
            let rate = (s.m_p / anchor.m_p).ln() / (s.t - anchor.t);
            out.push(((anchor.m_p * s.m_p).sqrt(), 1.0 / rate, (anchor.t_drift * s.t_drift).sqrt()));
            anchor = s;
        }
    }
    out
}

impl Scene for Params {
    const INFO: SceneInfo = SceneInfo {
        id: "mass-distribution",
        title: "Monte Carlo mass distribution",
        source: "Sects. 4.3–4.4; Figs. 4.4–4.7, 4.9",
        explanation: "A vertical column of the disk followed with the distribution method of Ormel & Spaans (2008): \
families of identical aggregates (mass m, filling factor φ), w groups of 2^z particles each, collide as \
groups at the rates λ_ij = w_i w_j 2^{z_i+N_ε} K_ij/V (4.25) with the column kernel \
K = σ h_{d,ij}/((2π)^{1/2} h_i h_j) v_rel (4.19). N_ε (4.22)–(4.24) limits how much a large particle changes \
in one group event; zoom factors z* = [log₂(N₁₀/w*)] (4.26) keep about w* groups in every mass decade, so \
the distribution is resolved many decades below its peak. Shown: m²f(m)/ρ_d, the mass fraction per ln m, \
at the snapshot times (mean of the runs, dashed ±1σ), and t_grow = m_p/ṁ_p (4.30) against \
t_drift = R/v_drift (4.31) of the peak mass m_p = ⟨m²⟩/⟨m⟩ (4.29). Perfect sticking grows through the \
drift barrier (t_grow ≪ t_drift); with erosion (v_eros) the largest bodies stall near Ωt_s ~ 1.",
        heavy: true,
    };

    const DECLARED: &'static [crate::scene::core::Declared] =
        super::common::column_declared![super::common::FIRST_SNAPSHOT];
    const PAUSABLE: bool = true;

    fn time_cursor(&mut self) -> Option<&mut f64> {
        Some(&mut self.cursor)
    }

    fn cursor(&self, out: &SceneOutput) -> Option<Cursor> {
        let p = self;
        let range = timeline::x_range(out, "peak-mass-history")?;
        let t = timeline::time_at(range, p.cursor, Scale::Log);
        let mut marks = timeline::along_x(out, "peak-mass-history", t);
        let mut label = format!("t = {} yr", crate::figure::human(t));
        if let Some((mark, shown)) = timeline::snapshot(out, "mass-distribution", t) {
            marks.push(mark);
            label.push_str(&format!(" (snapshot {} yr)", crate::figure::human(shown)));
        }
        Some(Cursor { fraction: p.cursor, label, marks, optional: true })
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
        Ok(output(p, &runs))
    }
}

/// The scene's figures from a set of runs.
fn output(p: &Params, runs: &[Run]) -> SceneOutput {
    let n_snap = runs.iter().map(|r| r.snapshots.len()).max().unwrap_or(0);
    let mut dist = Figure::new(
        "mass-distribution",
        "Mass distribution m²f(m)/ρ_d",
        Axis::log("mass m", "g"),
        Axis::log("m²f(m)/ρ_d", ""),
    )
    .family("time", "yr", crate::figure::Scale::Log)
    .y_decades(6.0);
    for k in 0..n_snap {
        let t = runs.iter().filter_map(|r| r.snapshots.get(k)).map(|s| s.t).fold(0.0, f64::max);
        let rows = mass_distribution(runs, k, p.bins_per_decade);
        let label = format!("{} yr", crate::figure::human(t / YEAR));
        let mean: Vec<[f64; 2]> = rows.iter().filter(|r| r.1 > 0.0).map(|r| [r.0 * 1e3, r.1]).collect();
        dist = dist.with(Series::new(label, mean, Style::Line, k).at(t / YEAR));
        if runs.len() > 1 {
            let hi: Vec<[f64; 2]> = rows.iter().filter(|r| r.1 > 0.0).map(|r| [r.0 * 1e3, r.1 + r.2]).collect();
            let lo: Vec<[f64; 2]> = rows.iter().filter(|r| r.1 - r.2 > 0.0).map(|r| [r.0 * 1e3, r.1 - r.2]).collect();
            dist = dist
                .with(Series::new("", hi, Style::Dashed, k).at(t / YEAR))
                .with(Series::new("", lo, Style::Dashed, k).at(t / YEAR));
        }
    }
    let mut times = Figure::new(
        "growth-drift-times",
        "Growth and drift times of the peak mass",
        Axis::log("peak mass m_p", "g"),
        Axis::log("time", "yr"),
    );
    for (k, r) in runs.iter().enumerate() {
        let g = growth_times(&r.history);
        let name = |what: &str| if k == 0 { what.to_string() } else { String::new() };
        times = times
            .with(Series::new(name("t_grow"), g.iter().map(|x| [x.0 * 1e3, x.1 / YEAR]).collect(), Style::Line, 0))
            .with(Series::new(name("t_drift"), g.iter().map(|x| [x.0 * 1e3, x.2 / YEAR]).collect(), Style::Line, 1))
            .with(Series::new(
                name("t_drift/30"),
                g.iter().map(|x| [x.0 * 1e3, x.2 / 30.0 / YEAR]).collect(),
                Style::Dashed,
                1,
            ));
    }
    let mut peak = Figure::new(
        "peak-mass-history",
        "Peak and largest mass over time",
        Axis::log("time", "yr"),
        Axis::log("mass", "g"),
    );
    for (k, r) in runs.iter().enumerate() {
        let name = |what: &str| if k == 0 { what.to_string() } else { String::new() };
        peak = peak
            .with(Series::new(
                name("m_p"),
                r.history.iter().map(|s| [s.t / YEAR, s.m_p * 1e3]).collect(),
                Style::Line,
                0,
            ))
            .with(Series::new(
                name("m_max"),
                r.history.iter().map(|s| [s.t / YEAR, s.m_max * 1e3]).collect(),
                Style::Dashed,
                1,
            ));
    }
    SceneOutput {
        warnings: Vec::new(),
        scalars: summary(runs),
        figures: vec![dist, times, peak],
        notes: endings(runs),
        extra: crate::scene::core::Extra::None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scene declares what every column declares, and the first
    /// snapshot's time, which only the figure shows.
    #[test]
    fn the_scene_declares_what_every_column_declares() {
        let own = super::super::common::declared_beyond_column(<Params as Scene>::DECLARED);
        assert_eq!(own, [super::super::common::FIRST_SNAPSHOT]);
    }

    /// A step of a column is first the event limit's, a real number of the
    /// scene that sets its resolution; where the limit does not explain it,
    /// a threshold of the physics may (the onset of erosion along v_eros),
    /// and along a parameter without one nothing does.
    #[test]
    fn a_step_is_the_event_limits_first_and_the_physics_only_after() {
        use super::super::common::{EROSION_ONSET, EVENT_LIMIT};
        use crate::scene::core::{Declared, Irregularity::Step};
        use crate::scene::schema::SpecKind;
        let declared = <Params as Scene>::DECLARED;
        let key = EVENT_LIMIT.resolution.expect("a resolution");
        let params = crate::scene::SceneParams::default_for("mass-distribution").expect("scene");
        let spec = params.spec(key).expect("the scene's parameter");
        assert!(spec.numerical && matches!(spec.kind, SpecKind::Number { .. }), "{key}");
        assert_eq!(Declared::find(declared, Step, "t_end", "v_eros"), Some(&EVENT_LIMIT));
        assert_eq!(Declared::find_physics(declared, Step, "t_end", "v_eros"), Some(&EROSION_ONSET));
        assert_eq!(Declared::find(declared, Step, "m_p", "alpha"), Some(&EVENT_LIMIT));
        assert_eq!(Declared::find_physics(declared, Step, "m_p", "alpha"), None);
    }
}
