//! The registry of scenes: the one list below names every scene by its
//! chapter module and generates [`SceneParams`] (the preset format), the
//! dispatch from it to each scene's [`Scene`] impl, and [`SCENES`] (the scene
//! list's order). It sits on top of the scene modules, which never import it
//! except to open another scene from an inspected point ([`column_action`]).
//!
//! Adding a scene: declare its module in its chapter in [`crate::scene`] and
//! add the line `my_scene::MyScene,` (the module and the variant of
//! [`SceneParams`] for its `Params`) to its chapter in the list below.

use super::controls::short;
use super::controls::{Control, ControlKind, ParamError};
use super::core::{Caches, Censored, Context, Declared, Progress, Scene, SceneError, SceneInfo, SceneOutput, Seeds};
use super::schema::{ParamSet, Spec, SpecKind, Value};
use super::timeline::Cursor;
use super::{batches, collisions, debris, disk, inspect, monomer, monte_carlo, overview, rolling};
use crate::physics::fit::Measurement;
use serde::{Deserialize, Serialize};

/// Generates, from the scenes of each chapter, the enum of scene parameters
/// and the dispatch from it to each scene's [`Scene`] impl. A macro because
/// the dispatch is one `match` arm per scene in each of nine methods: written
/// out, adding a scene would mean editing every `match`; here it is one line
/// of the list (`module::Variant`, the scene's `Params` in `module`).
macro_rules! scenes {
    ($( $(#[$chapter_doc:meta])* $chapter:ident { $( $module:ident :: $scene:ident ),* $(,)? } )*) => {

        /// The parameters of one scene, tagged by scene: the `scene` of a preset.
        #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
        pub enum SceneParams {
            $($(
                #[doc = concat!("Parameters of [`", stringify!($chapter), "::", stringify!($module), "`].")]
                $scene($chapter::$module::Params),
            )*)*
        }

        /// All scenes, in the order of the scene list (by thesis chapter).
        pub const SCENES: &[SceneInfo] = &[$($(<$chapter::$module::Params as Scene>::INFO,)*)*];

        /// The chapter folder of every scene, in the order of [`SCENES`].
        const CHAPTER_OF: &[&str] = &[$($(first(stringify!($chapter), stringify!($module)),)*)*];

        impl SceneParams {
            /// Default parameters of the scene with identifier `id`.
            pub fn default_for(id: &str) -> Option<SceneParams> {
                $($(
                    if id == <$chapter::$module::Params as Scene>::INFO.id {
                        return Some(SceneParams::$scene(Default::default()));
                    }
                )*)*
                None
            }

            /// The scene's static description.
            pub fn info(&self) -> &'static SceneInfo {
                match self {
                    $($( SceneParams::$scene(_) => &<$chapter::$module::Params as Scene>::INFO, )*)*
                }
            }

            /// What the scene's non-finite scalars mean (see [`Scene::CENSORED`]).
            pub fn censored(&self) -> &'static [Censored] {
                match self {
                    $($( SceneParams::$scene(_) => <$chapter::$module::Params as Scene>::CENSORED, )*)*
                }
            }

            /// What the audit finds that is the scene's physics (see [`Scene::DECLARED`]).
            pub fn declared(&self) -> &'static [Declared] {
                match self {
                    $($( SceneParams::$scene(_) => <$chapter::$module::Params as Scene>::DECLARED, )*)*
                }
            }

            /// Whether the scene's computation can be paused.
            pub fn pausable(&self) -> bool {
                match self {
                    $($( SceneParams::$scene(_) => <$chapter::$module::Params as Scene>::PAUSABLE, )*)*
                }
            }

            /// The documented parameters, with mutable access for the UI and `--set`.
            pub fn controls(&mut self) -> Vec<Control<'_>> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as ParamSet>::controls(p), )*)*
                }
            }

            /// Every parameter's spec, in the order of the controls.
            pub fn specs(&self) -> &'static [Spec] {
                match self {
                    $($( SceneParams::$scene(_) => <$chapter::$module::Params as ParamSet>::specs(), )*)*
                }
            }

            /// The value of parameter `key`, read in place; None if the scene has no such parameter.
            pub fn get(&self, key: &str) -> Option<Value> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as ParamSet>::get(p, key), )*)*
                }
            }

            /// Sets parameter `key` to `value` (of its kind), checking its range; on error nothing changes.
            pub fn set_value(&mut self, key: &str, value: &Value) -> Result<(), ParamError> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as ParamSet>::set(p, key, value), )*)*
                }
            }

            /// Checks every parameter against its spec, in place.
            fn check_all(&self) -> Result<(), ParamError> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as ParamSet>::check_all(p), )*)*
                }
            }

            /// After a material was picked: re-derives what depends on it.
            pub fn material_changed(&mut self) {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::material_changed(p), )*)*
                }
            }

            /// The time cursor's value (fraction of the run, 0–1) of a scene
            /// whose result is a history, for playing it.
            pub fn cursor_mut(&mut self) -> Option<&mut f64> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::time_cursor(p), )*)*
                }
            }

            /// The seeds of a scene that averages random runs.
            pub fn seeds(&mut self) -> Option<Seeds<'_>> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::seeds(p), )*)*
                }
            }

            /// The scene's time cursor over `out`, if it has one.
            pub fn cursor(&self, out: &SceneOutput) -> Option<Cursor> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::cursor(p, out), )*)*
                }
            }

            /// What a click at `at` (axis units) on figure `figure` of `out` shows, if anything.
            pub fn inspect(&self, out: &SceneOutput, figure: &str, at: [f64; 2]) -> Option<inspect::Inspection> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::inspect(p, out, figure, at), )*)*
                }
            }

            /// The cheaper parameters of the scene's preview, if it has one.
            pub fn coarse(&self) -> Option<SceneParams> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::coarse(p).map(SceneParams::$scene), )*)*
                }
            }

            /// The parameters of the window's first picture, if the scene
            /// has a separate preview ([`Scene::preview`]).
            pub fn preview(&self) -> Option<SceneParams> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::preview(p).map(SceneParams::$scene), )*)*
                }
            }

            /// The imported measurements the scene works on, if it takes any.
            pub fn measurements(&mut self) -> Option<&mut Vec<Measurement>> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::measurements(p), )*)*
                }
            }

            /// The scene's own quick path to scalar `key`, if it has one
            /// (None: only the whole computation gives it). Its value equals
            /// the whole computation's; [`scalar`] uses it, and
            /// `tests/quick_paths.rs` holds it to that.
            pub fn quick_scalar(&self, key: &str, progress: &Progress) -> Option<Result<f64, SceneError>> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::scalar(p, key, progress), )*)*
                }
            }

            /// Computes the scene without validating first.
            fn dispatch(&self, ctx: &mut Context<'_>) -> Result<SceneOutput, SceneError> {
                match self {
                    $($( SceneParams::$scene(p) => <$chapter::$module::Params as Scene>::compute(p, ctx), )*)*
                }
            }
        }
    };
}

scenes! {
    /// Collisions of adhesive viscoelastic spheres (thesis ch. 1–2).
    collisions {
        hysteresis::Hysteresis,
        restitution::Restitution,
        adhesion::Adhesion,
        experiments::Experiments,
        material_parameters::MaterialParameters,
        fit::Fit,
    }
    /// Rolling friction from adhesion hysteresis (thesis ch. 3).
    rolling {
        contact_torque::ContactTorque,
        rolling_force::RollingForce,
        critical_displacement::CriticalDisplacement,
        rocking::Rocking,
    }
    /// The smallest fragments of debris-disk collisions (thesis ch. 6).
    debris {
        smallest_fragment::SmallestFragment,
        critical_energies::CriticalEnergies,
        debris_disks::DebrisDisks,
        unequal_colliders::UnequalColliders,
    }
    /// Porous aggregates in a disk: drag, speeds, compaction, growth (thesis ch. 4).
    disk {
        stokes_number::StokesNumber,
        collision_speeds::CollisionSpeeds,
        porosity_track::PorosityTrack,
        timescales::Timescales,
        growth_tracks::GrowthTracks,
    }
    /// The Monte Carlo coagulation column (thesis Sects. 4.3–4.4).
    monte_carlo {
        mass_distribution::MassDistribution,
        families::Families,
        erosion_balance::ErosionBalance,
        analytic_kernels::KernelTests,
    }
    /// The global dust-batch model over a whole disk (thesis ch. 5).
    batches {
        surface_density::SurfaceDensity,
        batch_lifelines::BatchLifelines,
        disk_map::DiskMap,
        planetesimal_yield::PlanetesimalYield,
        formation_zone::FormationZone,
        midplane_loading::MidplaneLoading,
    }
    /// The argument across scales, on one screen.
    overview {
        scale_ladder::ScaleLadder,
    }
}

impl SceneParams {
    /// Checks every parameter against its documented range.
    pub fn validate(&self) -> Result<(), ParamError> {
        self.check_all()
    }

    /// Sets the numeric parameter `key` to `x` (a whole number for a count),
    /// checking its range: no text between the number and the field. On
    /// error nothing changes.
    pub fn set_number(&mut self, key: &str, x: f64) -> Result<(), ParamError> {
        let spec = self.spec(key).ok_or_else(|| ParamError::unknown(key, &self.keys()))?;
        let value = match spec.kind {
            SpecKind::Number { .. } => Value::Number(x),
            SpecKind::Count { .. } if x.is_finite() && x >= 0.0 && x.fract() == 0.0 => Value::Count(x as usize),
            SpecKind::Count { .. } => {
                return Err(ParamError::Parse { key: key.into(), value: short(x), expected: "a whole number" });
            }
            _ => {
                return Err(ParamError::Parse {
                    key: key.into(),
                    value: short(x),
                    expected: "a parameter that is a number",
                });
            }
        };
        self.set_value(key, &value)
    }

    /// The spec of parameter `key`.
    pub fn spec(&self, key: &str) -> Option<&'static Spec> {
        self.specs().iter().find(|s| s.key == key)
    }

    /// The keys of the scene's parameters.
    pub fn keys(&self) -> Vec<&'static str> {
        self.specs().iter().map(|s| s.key).collect()
    }

    /// Sets the parameter `key` from its textual value (as on the command
    /// line), checking its range. On error nothing changes.
    pub fn set(&mut self, key: &str, value: &str) -> Result<(), ParamError> {
        let spec = self.spec(key).ok_or_else(|| ParamError::unknown(key, &self.keys()))?;
        let mut trial = self.clone();
        trial.set_value(key, &spec.parse_checked(value)?)?;
        trial.validate()?;
        *self = trial;
        Ok(())
    }

    /// The figures of `out` as they are exported: with the time cursor's
    /// marks where the scene always shows them.
    pub fn exported_figures(&self, out: &SceneOutput) -> Vec<crate::figure::Figure> {
        let mut figures = out.figures.clone();
        if let Some(c) = self.cursor(out).filter(|c| !c.optional) {
            c.apply(&mut figures);
        }
        figures
    }

    /// The scene's monomer card (see [`monomer`]), if it builds aggregates.
    pub fn monomer_card(&self) -> Option<monomer::Card> {
        monomer::MONOMER_KEYS.iter().map(|k| self.get(k)).collect()
    }

    /// Gives the scene the monomer `card`. False, and nothing changes, if the
    /// scene has no card or a value is refused.
    pub fn set_monomer_card(&mut self, card: &monomer::Card) -> bool {
        let mut trial = self.clone();
        let taken = monomer::MONOMER_KEYS.iter().zip(card).all(|(key, value)| trial.set_value(key, value).is_ok());
        if !taken || trial.validate().is_err() {
            return false;
        }
        *self = trial;
        true
    }

    /// Whether the scene keeps its own monomer instead of the shared one.
    pub fn own_monomer(&self) -> bool {
        self.get("own_monomer") == Some(Value::Toggle(true))
    }

    /// The monomer of the scene's card, if it has one.
    pub fn monomer(&self) -> Option<crate::physics::monomer::Monomer> {
        self.monomer_card().map(|card| monomer::monomer_of(&card))
    }

    /// The parameters with every styling-only value reset: two parameter sets
    /// with equal keys give the same computed output.
    pub fn compute_key(&self) -> SceneParams {
        let mut key = self.clone();
        for c in key.controls() {
            if !c.style_only {
                continue;
            }
            match c.kind {
                ControlKind::Number { value, .. } => *value = 0.0,
                ControlKind::Toggle(value) => *value = false,
                _ => {}
            }
        }
        key
    }

    /// Keys whose values differ between `self` and `other` (same scene), with
    /// the values of `self` as text: used to label pinned curves.
    pub fn differences(&self, other: &SceneParams) -> Vec<String> {
        if self.info().id != other.info().id {
            return Vec::new();
        }
        self.specs()
            .iter()
            .filter(|s| !s.style_only)
            .filter_map(|s| {
                let (a, b) = (s.display(&self.get(s.key)?), s.display(&other.get(s.key)?));
                (a != b).then(|| format!("{} = {a}", s.label))
            })
            .collect()
    }
}

/// Computes a scene. Pure: the same parameters give the same output.
pub fn compute(params: &SceneParams, progress: &Progress) -> Result<SceneOutput, SceneError> {
    compute_cached(params, progress, &mut Caches::default())
}

/// Computes a scene, reusing parts of earlier results held in `caches`.
pub fn compute_cached(
    params: &SceneParams,
    progress: &Progress,
    caches: &mut Caches,
) -> Result<SceneOutput, SceneError> {
    params.validate()?;
    let mut out = params.dispatch(&mut Context { progress, caches })?;
    // What the monomer sets, for every scene that builds aggregates of it.
    if let Some(m) = params.monomer() {
        out.scalars.extend(monomer::scalars(&m, false));
    }
    Ok(out)
}

/// Scalar `key` of the scene at `params` (None where the scene reports no
/// such scalar), through the scene's quick path where it has one (the same
/// value, without the figures), else from the whole computation.
pub fn scalar(params: &SceneParams, key: &str, progress: &Progress) -> Result<Option<f64>, SceneError> {
    params.validate()?;
    match params.quick_scalar(key, progress) {
        Some(value) => value.map(Some),
        None => Ok(compute(params, progress)?.scalar(key)),
    }
}

/// The parameter reference of every scene as Markdown, generated from the
/// schema (`docs/parameters.md`; `grainscope params --markdown`): per scene
/// a table of key, label, SI unit, valid values, default and meaning.
pub fn parameter_reference() -> String {
    let cell = |s: &str| s.replace('|', "\\|");
    let mut out = String::from(
        "# Parameters\n\nEvery scene's parameters as the schema declares them (generated by \
`grainscope params --markdown`; a test keeps this file current). Values are stored in the units \
of the \"SI unit\" column; the window shows them in the unit of the default.\n",
    );
    for (chapter, scenes) in scenes_by_chapter() {
        out.push_str(&format!("\n## {}\n", chapter.heading));
        for i in scenes {
            let info = &SCENES[i];
            let Some(p) = SceneParams::default_for(info.id) else { continue };
            out.push_str(&format!("\n### `{}` — {}\n\n", info.id, info.title));
            out.push_str("| key | label | SI unit | valid values | default | meaning |\n|---|---|---|---|---|---|\n");
            for s in p.specs() {
                let values = match &s.kind {
                    SpecKind::Number { min, max, log, .. } => {
                        format!("{min:e} … {max:e}{}", if *log { " (log)" } else { "" })
                    }
                    SpecKind::Count { min, max } => format!("{min} … {max}"),
                    SpecKind::Toggle => "true, false".into(),
                    SpecKind::Material => "a material of Table 2.2".into(),
                    SpecKind::Choice { options } => {
                        options.iter().map(|(k, _)| format!("`{k}`")).collect::<Vec<_>>().join(", ")
                    }
                };
                let style = if s.style_only {
                    " (display only)"
                } else if s.figure_only {
                    " (sets only what a figure shows)"
                } else if s.numerical {
                    " (numerical resolution)"
                } else {
                    ""
                };
                out.push_str(&format!(
                    "| `{}` | {} | {} | {} | {} | {}{style} |\n",
                    s.key,
                    cell(s.label),
                    cell(s.si_unit),
                    cell(&values),
                    cell(&s.default_text().unwrap_or_default()),
                    cell(s.doc)
                ));
            }
        }
    }
    out
}

/// The first of two names (lets the registry repeat a chapter per scene).
const fn first(a: &'static str, _b: &'static str) -> &'static str {
    a
}

/// A thesis chapter as the scene navigator and the presets menu group it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Chapter {
    /// Heading, e.g. "Ch. 2 · Sticking collisions of adhesive spheres".
    pub heading: &'static str,
    /// Order in the thesis.
    pub order: u8,
}

impl Chapter {
    /// The unit system the thesis writes this chapter's numbers in.
    pub fn units(&self) -> crate::units::System {
        match self.order {
            // The overview's ladder climbs to chapters 4–5, and its monomer
            // card feeds their aggregates: cgs, as those chapters write it.
            1 => crate::units::System::Cgs,
            n => crate::units::system_of_chapter(n),
        }
    }
}

/// The chapter of scene `i` of [`SCENES`].
pub fn chapter(i: usize) -> Chapter {
    let (order, heading) = match CHAPTER_OF.get(i).copied().unwrap_or("") {
        "overview" => (1, "Overview · From grains to planetesimals"),
        "collisions" => (2, "Ch. 2 · Collisions of adhesive spheres"),
        "rolling" => (3, "Ch. 3 · Rolling friction"),
        "disk" => (4, "Ch. 4 · Porous aggregates in a disk"),
        "monte_carlo" => (4, "Ch. 4 · Monte Carlo growth in a column"),
        "batches" => (5, "Ch. 5 · Dust batches and planetesimals"),
        "debris" => (6, "Ch. 6 · Smallest fragments in debris disks"),
        _ => (9, "Other"),
    };
    Chapter { heading, order }
}

/// The scenes in navigator order: by chapter as in the thesis, each chapter
/// in registry order.
pub fn scenes_by_chapter() -> Vec<(Chapter, Vec<usize>)> {
    let mut groups: Vec<(Chapter, Vec<usize>)> = Vec::new();
    for i in 0..SCENES.len() {
        let c = chapter(i);
        match groups.iter_mut().find(|(g, _)| *g == c) {
            Some((_, v)) => v.push(i),
            None => groups.push((c, vec![i])),
        }
    }
    groups.sort_by_key(|(c, _)| c.order);
    groups
}

/// The figures a scene reproduces, from its thesis reference ("Figs. 2.2,
/// 2.3"); empty if it reproduces none.
pub fn figures_of(info: &SceneInfo) -> &'static str {
    match info.source.find("Fig") {
        Some(k) => &info.source[k..],
        None => "",
    }
}

/// "Open the local column": the Monte Carlo column at radius `r_au` of the
/// same disk, with the same monomer.
pub fn column_action(disk: &disk::common::DiskParams, r_au: f64) -> inspect::Action {
    use monte_carlo::{common::ColumnParams, mass_distribution};
    // Three significant digits, as a user would type it.
    let step = 10f64.powi(r_au.log10().floor() as i32 - 2);
    let r = ((r_au / step).round() * step).clamp(0.5, 300.0);
    let run = ColumnParams { disk: disk.clone(), radius_au: r, ..ColumnParams::default() };
    let hint = format!(
        "the Monte Carlo column at {} AU of this disk, with the same monomer, from monomers to {} yr",
        crate::figure::human(r),
        crate::figure::human(run.t_end_yr)
    );
    inspect::Action {
        label: "Open the local column".into(),
        hint,
        open: SceneParams::MassDistribution(mass_distribution::Params { run, ..Default::default() }),
    }
}
