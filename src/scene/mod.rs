//! Scenes: pure `compute(&Params) -> Result<Output, Error>` functions that the
//! window, the command line and the tests share.
//!
//! Adding a scene means adding one module with its `Params` (serde, with
//! `#[serde(default)]` so old presets keep loading), its `controls()` (the
//! documented, validated parameter list) and its `compute`, then registering
//! it in [`SceneParams`] and [`SCENES`].

pub mod adhesion;
pub mod batch_lifelines;
pub mod batch_params;
pub mod coagulation_params;
pub mod collision_params;
pub mod collision_speeds;
pub mod contact_torque;
pub mod controls;
pub mod critical_displacement;
pub mod critical_energies;
pub mod debris_disks;
pub mod debris_params;
pub mod disk_map;
pub mod disk_params;
pub mod erosion_balance;
pub mod experiments;
pub mod families;
pub mod fit;
pub mod formation_zone;
pub mod growth_params;
pub mod growth_tracks;
pub mod hysteresis;
pub mod kernel_tests;
pub mod mass_distribution;
pub mod material_parameters;
pub mod midplane_loading;
pub mod planetesimal_yield;
pub mod porosity_track;
pub mod restitution;
pub mod rocking;
pub mod rolling_force;
pub mod rolling_params;
pub mod smallest_fragment;
pub mod stokes_number;
pub mod surface_density;
pub mod timescales;
pub mod unequal_colliders;

pub use controls::{Control, ControlKind, ParamError};

use crate::figure::Figure;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};

/// Static description of a scene.
#[derive(Debug, Clone, Copy)]
pub struct SceneInfo {
    /// Identifier used on the command line and in presets.
    pub id: &'static str,
    /// Title shown in the scene list.
    pub title: &'static str,
    /// Thesis sections and figures it covers.
    pub source: &'static str,
    /// Explanation with the key equations, for teaching.
    pub explanation: &'static str,
    /// Whether a recompute is slow enough to need the worker thread.
    pub heavy: bool,
}

/// All scenes, in the order of the scene list.
pub const SCENES: [SceneInfo; 29] = [
    hysteresis::INFO,
    restitution::INFO,
    adhesion::INFO,
    experiments::INFO,
    material_parameters::INFO,
    fit::INFO,
    contact_torque::INFO,
    rolling_force::INFO,
    critical_displacement::INFO,
    rocking::INFO,
    smallest_fragment::INFO,
    critical_energies::INFO,
    debris_disks::INFO,
    unequal_colliders::INFO,
    stokes_number::INFO,
    collision_speeds::INFO,
    porosity_track::INFO,
    timescales::INFO,
    growth_tracks::INFO,
    mass_distribution::INFO,
    families::INFO,
    erosion_balance::INFO,
    kernel_tests::INFO,
    surface_density::INFO,
    batch_lifelines::INFO,
    disk_map::INFO,
    planetesimal_yield::INFO,
    formation_zone::INFO,
    midplane_loading::INFO,
];

/// Scenes whose computation honours [`Progress::set_paused`] (the Monte Carlo runs).
pub const PAUSABLE: [&str; 3] = [mass_distribution::INFO.id, families::INFO.id, erosion_balance::INFO.id];

/// The parameters of one scene, tagged by scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum SceneParams {
    /// Contact hysteresis of one collision.
    Hysteresis(hysteresis::Params),
    /// Restitution and sticking velocity.
    Restitution(restitution::Params),
    /// Adhesive contact basics.
    Adhesion(adhesion::Params),
    /// The collision experiments and their best fits.
    Experiments(experiments::Params),
    /// Fitted material parameters against size.
    MaterialParameters(material_parameters::Params),
    /// Fitting measured restitution.
    Fit(fit::Params),
    /// The asymmetric contact under torque.
    ContactTorque(contact_torque::Params),
    /// Rolling force against radius.
    RollingForce(rolling_force::Params),
    /// Critical rolling displacement against radius.
    CriticalDisplacement(critical_displacement::Params),
    /// A rocking sphere.
    Rocking(rocking::Params),
    /// Smallest fragment against collider size.
    SmallestFragment(smallest_fragment::Params),
    /// Splitting and disruption energies.
    CriticalEnergies(critical_energies::Params),
    /// Smallest fragment over blow-out size in debris disks.
    DebrisDisks(debris_disks::Params),
    /// Unequal colliders.
    UnequalColliders(unequal_colliders::Params),
    /// Stokes number against mass.
    StokesNumber(stokes_number::Params),
    /// Relative velocity map.
    CollisionSpeeds(collision_speeds::Params),
    /// Mass–porosity track.
    PorosityTrack(porosity_track::Params),
    /// Growth and drift timescales.
    Timescales(timescales::Params),
    /// Growth and drift tracks.
    GrowthTracks(growth_tracks::Params),
    /// Monte Carlo mass distribution.
    MassDistribution(mass_distribution::Params),
    /// Monte Carlo families.
    Families(families::Params),
    /// Erosion balance of the largest bodies.
    ErosionBalance(erosion_balance::Params),
    /// The Monte Carlo engine on analytic kernels.
    KernelTests(kernel_tests::Params),
    /// Surface densities of the batch model.
    SurfaceDensity(surface_density::Params),
    /// Batch lifelines.
    BatchLifelines(batch_lifelines::Params),
    /// Disk map.
    DiskMap(disk_map::Params),
    /// Planetesimal yield.
    PlanetesimalYield(planetesimal_yield::Params),
    /// Planetesimal formation zone.
    FormationZone(formation_zone::Params),
    /// Midplane loading.
    MidplaneLoading(midplane_loading::Params),
}

impl SceneParams {
    /// Default parameters of the scene with identifier `id`.
    pub fn default_for(id: &str) -> Option<SceneParams> {
        match id {
            "hysteresis" => Some(SceneParams::Hysteresis(Default::default())),
            "restitution" => Some(SceneParams::Restitution(Default::default())),
            "adhesion" => Some(SceneParams::Adhesion(Default::default())),
            "experiments" => Some(SceneParams::Experiments(Default::default())),
            "material-parameters" => Some(SceneParams::MaterialParameters(Default::default())),
            "fit" => Some(SceneParams::Fit(Default::default())),
            "contact-torque" => Some(SceneParams::ContactTorque(Default::default())),
            "rolling-force" => Some(SceneParams::RollingForce(Default::default())),
            "critical-displacement" => Some(SceneParams::CriticalDisplacement(Default::default())),
            "rocking" => Some(SceneParams::Rocking(Default::default())),
            "smallest-fragment" => Some(SceneParams::SmallestFragment(Default::default())),
            "critical-energies" => Some(SceneParams::CriticalEnergies(Default::default())),
            "debris-disks" => Some(SceneParams::DebrisDisks(Default::default())),
            "unequal-colliders" => Some(SceneParams::UnequalColliders(Default::default())),
            "stokes-number" => Some(SceneParams::StokesNumber(Default::default())),
            "collision-speeds" => Some(SceneParams::CollisionSpeeds(Default::default())),
            "porosity-track" => Some(SceneParams::PorosityTrack(Default::default())),
            "timescales" => Some(SceneParams::Timescales(Default::default())),
            "growth-tracks" => Some(SceneParams::GrowthTracks(Default::default())),
            "mass-distribution" => Some(SceneParams::MassDistribution(Default::default())),
            "families" => Some(SceneParams::Families(Default::default())),
            "erosion-balance" => Some(SceneParams::ErosionBalance(Default::default())),
            "kernel-tests" => Some(SceneParams::KernelTests(Default::default())),
            "surface-density" => Some(SceneParams::SurfaceDensity(Default::default())),
            "batch-lifelines" => Some(SceneParams::BatchLifelines(Default::default())),
            "disk-map" => Some(SceneParams::DiskMap(Default::default())),
            "planetesimal-yield" => Some(SceneParams::PlanetesimalYield(Default::default())),
            "formation-zone" => Some(SceneParams::FormationZone(Default::default())),
            "midplane-loading" => Some(SceneParams::MidplaneLoading(Default::default())),
            _ => None,
        }
    }

    /// The scene's static description.
    pub fn info(&self) -> &'static SceneInfo {
        match self {
            SceneParams::Hysteresis(_) => &hysteresis::INFO,
            SceneParams::Restitution(_) => &restitution::INFO,
            SceneParams::Adhesion(_) => &adhesion::INFO,
            SceneParams::Experiments(_) => &experiments::INFO,
            SceneParams::MaterialParameters(_) => &material_parameters::INFO,
            SceneParams::Fit(_) => &fit::INFO,
            SceneParams::ContactTorque(_) => &contact_torque::INFO,
            SceneParams::RollingForce(_) => &rolling_force::INFO,
            SceneParams::CriticalDisplacement(_) => &critical_displacement::INFO,
            SceneParams::Rocking(_) => &rocking::INFO,
            SceneParams::SmallestFragment(_) => &smallest_fragment::INFO,
            SceneParams::CriticalEnergies(_) => &critical_energies::INFO,
            SceneParams::DebrisDisks(_) => &debris_disks::INFO,
            SceneParams::UnequalColliders(_) => &unequal_colliders::INFO,
            SceneParams::StokesNumber(_) => &stokes_number::INFO,
            SceneParams::CollisionSpeeds(_) => &collision_speeds::INFO,
            SceneParams::PorosityTrack(_) => &porosity_track::INFO,
            SceneParams::Timescales(_) => &timescales::INFO,
            SceneParams::GrowthTracks(_) => &growth_tracks::INFO,
            SceneParams::MassDistribution(_) => &mass_distribution::INFO,
            SceneParams::Families(_) => &families::INFO,
            SceneParams::ErosionBalance(_) => &erosion_balance::INFO,
            SceneParams::KernelTests(_) => &kernel_tests::INFO,
            SceneParams::SurfaceDensity(_) => &surface_density::INFO,
            SceneParams::BatchLifelines(_) => &batch_lifelines::INFO,
            SceneParams::DiskMap(_) => &disk_map::INFO,
            SceneParams::PlanetesimalYield(_) => &planetesimal_yield::INFO,
            SceneParams::FormationZone(_) => &formation_zone::INFO,
            SceneParams::MidplaneLoading(_) => &midplane_loading::INFO,
        }
    }

    /// The documented parameters, with mutable access for the UI and `--set`.
    pub fn controls(&mut self) -> Vec<Control<'_>> {
        match self {
            SceneParams::Hysteresis(p) => p.controls(),
            SceneParams::Restitution(p) => p.controls(),
            SceneParams::Adhesion(p) => p.controls(),
            SceneParams::Experiments(p) => p.controls(),
            SceneParams::MaterialParameters(p) => p.controls(),
            SceneParams::Fit(p) => p.controls(),
            SceneParams::ContactTorque(p) => p.controls(),
            SceneParams::RollingForce(p) => p.controls(),
            SceneParams::CriticalDisplacement(p) => p.controls(),
            SceneParams::Rocking(p) => p.controls(),
            SceneParams::SmallestFragment(p) => p.controls(),
            SceneParams::CriticalEnergies(p) => p.controls(),
            SceneParams::DebrisDisks(p) => p.controls(),
            SceneParams::UnequalColliders(p) => p.controls(),
            SceneParams::StokesNumber(p) => p.controls(),
            SceneParams::CollisionSpeeds(p) => p.controls(),
            SceneParams::PorosityTrack(p) => p.controls(),
            SceneParams::Timescales(p) => p.controls(),
            SceneParams::GrowthTracks(p) => p.controls(),
            SceneParams::MassDistribution(p) => p.controls(),
            SceneParams::Families(p) => p.controls(),
            SceneParams::ErosionBalance(p) => p.controls(),
            SceneParams::KernelTests(p) => p.controls(),
            SceneParams::SurfaceDensity(p) => p.controls(),
            SceneParams::BatchLifelines(p) => p.controls(),
            SceneParams::DiskMap(p) => p.controls(),
            SceneParams::PlanetesimalYield(p) => p.controls(),
            SceneParams::FormationZone(p) => p.controls(),
            SceneParams::MidplaneLoading(p) => p.controls(),
        }
    }

    /// Checks every parameter against its documented range.
    pub fn validate(&self) -> Result<(), ParamError> {
        let mut copy = self.clone();
        for c in copy.controls() {
            c.check()?;
        }
        Ok(())
    }

    /// Sets the parameter `key` from its textual value (as on the command
    /// line), checking its range. On error nothing changes.
    pub fn set(&mut self, key: &str, value: &str) -> Result<(), ParamError> {
        let mut trial = self.clone();
        {
            let mut controls = trial.controls();
            let known: Vec<&'static str> = controls.iter().map(|c| c.key).collect();
            let c = controls
                .iter_mut()
                .find(|c| c.key == key)
                .ok_or_else(|| ParamError::UnknownKey { key: key.into(), known: known.join(", ") })?;
            c.set_text(value)?;
        }
        trial.validate()?;
        *self = trial;
        Ok(())
    }

    /// The parameters with every styling-only value reset: two parameter sets
    /// with equal keys give the same computed output.
    pub fn compute_key(&self) -> SceneParams {
        let mut key = self.clone();
        for c in key.controls() {
            if c.style_only
                && let ControlKind::Number { value, .. } = c.kind
            {
                *value = 0.0;
            }
        }
        key
    }

    /// After a material changed: sets the combined surface energy to
    /// 2(γ₁γ₂)^{1/2} of the chosen materials.
    pub fn material_changed(&mut self) {
        use crate::physics::material::combined_surface_energy;
        match self {
            SceneParams::Hysteresis(p) => {
                p.collision.surface_energy = combined_surface_energy(&p.collision.projectile, &p.collision.target)
            }
            SceneParams::Restitution(p) => {
                p.collision.surface_energy = combined_surface_energy(&p.collision.projectile, &p.collision.target)
            }
            SceneParams::Adhesion(p) => p.surface_energy = combined_surface_energy(&p.material, &p.material),
            SceneParams::ContactTorque(p) => p.contact.material_changed(),
            SceneParams::RollingForce(p) => p.contact.material_changed(),
            SceneParams::CriticalDisplacement(p) => p.contact.material_changed(),
            SceneParams::Rocking(p) => p.contact.material_changed(),
            // Fitted, not derived from the materials.
            SceneParams::Experiments(_)
            | SceneParams::MaterialParameters(_)
            | SceneParams::Fit(_)
            | SceneParams::SmallestFragment(_)
            | SceneParams::CriticalEnergies(_)
            | SceneParams::DebrisDisks(_)
            | SceneParams::UnequalColliders(_)
            | SceneParams::StokesNumber(_)
            | SceneParams::CollisionSpeeds(_)
            | SceneParams::PorosityTrack(_)
            | SceneParams::Timescales(_)
            | SceneParams::GrowthTracks(_)
            | SceneParams::MassDistribution(_)
            | SceneParams::Families(_)
            | SceneParams::ErosionBalance(_)
            | SceneParams::KernelTests(_)
            | SceneParams::SurfaceDensity(_)
            | SceneParams::BatchLifelines(_)
            | SceneParams::DiskMap(_)
            | SceneParams::PlanetesimalYield(_)
            | SceneParams::FormationZone(_)
            | SceneParams::MidplaneLoading(_) => {}
        }
    }

    /// Keys whose values differ between `self` and `other` (same scene), with
    /// the values of `self` as text: used to label pinned curves.
    pub fn differences(&self, other: &SceneParams) -> Vec<String> {
        let mut a = self.clone();
        let mut b = other.clone();
        let ca = a.controls();
        let cb = b.controls();
        if ca.len() != cb.len() {
            return Vec::new();
        }
        ca.iter()
            .zip(cb.iter())
            .filter(|(x, y)| x.key == y.key && x.display_value() != y.display_value() && !x.style_only)
            .map(|(x, _)| format!("{} = {}", x.label, x.display_value()))
            .collect()
    }
}

/// A scalar result, e.g. the coefficient of restitution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scalar {
    /// Key in JSON output, e.g. "e".
    pub key: &'static str,
    /// Label as shown, e.g. "restitution e".
    pub label: &'static str,
    /// Value in SI units (or dimensionless).
    pub value: f64,
    /// Unit of `value`, empty for dimensionless quantities.
    pub unit: &'static str,
}

/// Extra, scene-specific data the window needs beyond figures.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Extra {
    /// Nothing beyond figures.
    #[default]
    None,
    /// A recorded collision, for the sketch of the two spheres.
    Collision(Arc<hysteresis::Trajectory>),
}

/// What a scene computes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SceneOutput {
    /// Scalar results.
    pub scalars: Vec<Scalar>,
    /// Figures, in display order.
    pub figures: Vec<Figure>,
    /// Remarks for the user (regime, discrepancies with the printed thesis).
    pub notes: Vec<String>,
    /// Scene-specific data for the window.
    pub extra: Extra,
}

impl SceneOutput {
    /// Scalars as one JSON object `{key: value}`.
    pub fn scalars_json(&self) -> serde_json::Value {
        let map: serde_json::Map<String, serde_json::Value> =
            self.scalars.iter().map(|s| (s.key.to_string(), serde_json::json!(s.value))).collect();
        serde_json::Value::Object(map)
    }

    /// Looks a scalar up by key.
    pub fn scalar(&self, key: &str) -> Option<f64> {
        self.scalars.iter().find(|s| s.key == key).map(|s| s.value)
    }
}

/// Why a scene could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SceneError {
    /// A parameter is out of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The model rejected its input or failed.
    #[error(transparent)]
    Physics(#[from] crate::physics::PhysicsError),
    /// The computation was cancelled.
    #[error("cancelled")]
    Cancelled,
}

/// Progress reporting and cancellation shared between a worker and the UI.
#[derive(Debug, Clone, Default)]
pub struct Progress {
    cancel: Arc<AtomicBool>,
    pause: Arc<AtomicBool>,
    permille: Arc<AtomicU32>,
    partial: Arc<std::sync::Mutex<Option<Arc<SceneOutput>>>>,
}

impl Progress {
    /// Requests cancellation.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }
    /// Whether cancellation was requested.
    pub fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }
    /// Pauses (true) or resumes (false) a computation that honours it.
    pub fn set_paused(&self, paused: bool) {
        self.pause.store(paused, Ordering::Relaxed);
    }
    /// Whether a pause was requested.
    pub fn paused(&self) -> bool {
        self.pause.load(Ordering::Relaxed)
    }
    /// Blocks while paused (and not cancelled).
    pub fn wait_while_paused(&self) {
        while self.paused() && !self.cancelled() {
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
    }
    /// Errors out if cancellation was requested.
    pub fn check(&self) -> Result<(), SceneError> {
        if self.cancelled() { Err(SceneError::Cancelled) } else { Ok(()) }
    }
    /// Sets the fraction done (0–1).
    pub fn set(&self, fraction: f64) {
        self.permille.store((fraction.clamp(0.0, 1.0) * 1000.0) as u32, Ordering::Relaxed);
    }
    /// The fraction done (0–1).
    pub fn fraction(&self) -> f64 {
        self.permille.load(Ordering::Relaxed) as f64 / 1000.0
    }
    /// Offers an intermediate result of a long computation for display.
    pub fn publish(&self, output: SceneOutput) {
        if let Ok(mut slot) = self.partial.lock() {
            *slot = Some(Arc::new(output));
        }
    }
    /// The newest intermediate result, if any.
    pub fn partial(&self) -> Option<Arc<SceneOutput>> {
        self.partial.lock().ok().and_then(|slot| slot.clone())
    }
}

/// Partial results kept between recomputations, so that a changed parameter
/// recomputes only what it touches. Results do not depend on the cache.
#[derive(Debug, Default)]
pub struct Caches {
    restitution: restitution::Cache,
    batches: batch_params::RunCache,
    coagulation: coagulation_params::RunCache,
}

impl Caches {
    /// The Monte Carlo runs for `p`, from the cache the Monte Carlo scenes share.
    pub fn coagulation_runs(
        &mut self,
        p: &coagulation_params::ColumnParams,
        progress: &Progress,
    ) -> Result<Arc<Vec<crate::physics::coagulation::Run>>, SceneError> {
        self.coagulation.get(p, progress)
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
    match params {
        SceneParams::Hysteresis(p) => hysteresis::compute(p),
        SceneParams::Restitution(p) => restitution::compute(p, progress, &mut caches.restitution),
        SceneParams::Adhesion(p) => adhesion::compute(p),
        SceneParams::Experiments(p) => experiments::compute(p, progress),
        SceneParams::MaterialParameters(p) => material_parameters::compute(p),
        SceneParams::Fit(p) => fit::compute(p, progress),
        SceneParams::ContactTorque(p) => contact_torque::compute(p),
        SceneParams::RollingForce(p) => rolling_force::compute(p),
        SceneParams::CriticalDisplacement(p) => critical_displacement::compute(p),
        SceneParams::Rocking(p) => rocking::compute(p),
        SceneParams::SmallestFragment(p) => smallest_fragment::compute(p),
        SceneParams::CriticalEnergies(p) => critical_energies::compute(p),
        SceneParams::DebrisDisks(p) => debris_disks::compute(p),
        SceneParams::UnequalColliders(p) => unequal_colliders::compute(p),
        SceneParams::StokesNumber(p) => stokes_number::compute(p),
        SceneParams::CollisionSpeeds(p) => collision_speeds::compute(p, progress),
        SceneParams::PorosityTrack(p) => porosity_track::compute(p),
        SceneParams::Timescales(p) => timescales::compute(p),
        SceneParams::GrowthTracks(p) => growth_tracks::compute(p, progress),
        SceneParams::MassDistribution(p) => mass_distribution::compute(p, progress, &mut caches.coagulation),
        SceneParams::Families(p) => families::compute(p, progress, &mut caches.coagulation),
        SceneParams::ErosionBalance(p) => erosion_balance::compute(p, progress, &mut caches.coagulation),
        SceneParams::KernelTests(p) => kernel_tests::compute(p, progress),
        SceneParams::SurfaceDensity(p) => surface_density::compute(p, progress, &mut caches.batches),
        SceneParams::BatchLifelines(p) => batch_lifelines::compute(p, progress, &mut caches.batches),
        SceneParams::DiskMap(p) => disk_map::compute(p, progress, &mut caches.batches),
        SceneParams::PlanetesimalYield(p) => planetesimal_yield::compute(p, progress),
        SceneParams::FormationZone(p) => formation_zone::compute(p, progress),
        SceneParams::MidplaneLoading(p) => midplane_loading::compute(p),
    }
}

/// Evenly spaced values in log space, `n ≥ 2` points from `lo` to `hi`.
pub fn logspace(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let n = n.max(2);
    let (a, b) = (lo.ln(), hi.ln());
    (0..n).map(|i| (a + (b - a) * i as f64 / (n - 1) as f64).exp()).collect()
}
