//! Scenes: pure `compute(&Params) -> Result<Output, Error>` functions that the
//! window, the command line and the tests share.
//!
//! Each scene lives in its own file under the folder of its thesis chapter and
//! implements [`Scene`]; what a chapter's scenes share sits in the chapter's
//! `common.rs`, and what all scenes share in [`core`] (which imports no scene),
//! [`controls`], [`grid`] and [`monomer`]. The [`registry`] on top lists the
//! scenes and generates [`SceneParams`] (the preset format) and [`SCENES`]
//! (the scene list's order).
//!
//! Adding a scene: write `src/scene/CHAPTER/my_scene.rs` with its `Params`
//! (serde, `#[serde(default)]` so old presets keep loading) implementing
//! [`Scene`], declare `pub mod my_scene;` in its chapter below, and add it to
//! its chapter in the registry's list.

pub mod controls;
pub mod core;
pub mod grid;
pub mod inspect;
pub mod monomer;
pub mod parts;
pub mod quantities;
pub mod registry;
pub mod schema;
pub mod spec;
pub mod timeline;

pub use controls::{Control, ControlKind, DefaultValue, LogRange, ParamError};
pub use core::{
    Caches, Censored, Context, Declared, Extra, Irregularity, NOT_FINITE, Progress, Report, Rung, Scalar, Scene,
    SceneError, SceneInfo, SceneOutput, Seeds, Status, TimedPath, Trajectory, Watcher, logspace, status,
};
pub use parts::{Parts, Share};
pub use registry::{
    Chapter, SCENES, SceneParams, chapter, compute, compute_cached, figures_of, parameter_reference, scalar,
    scenes_by_chapter,
};
pub use timeline::{Cursor, Mark};

/// Collisions of adhesive viscoelastic spheres (thesis ch. 1–2).
pub mod collisions {
    pub mod adhesion;
    pub mod common;
    pub mod experiments;
    pub mod fit;
    pub mod hysteresis;
    pub mod material_parameters;
    pub mod restitution;
}

/// Rolling friction from adhesion hysteresis (thesis ch. 3).
pub mod rolling {
    pub mod common;
    pub mod contact_torque;
    pub mod critical_displacement;
    pub mod rocking;
    pub mod rolling_force;
}

/// The smallest fragments of debris-disk collisions (thesis ch. 6).
pub mod debris {
    pub mod common;
    pub mod critical_energies;
    pub mod debris_disks;
    pub mod smallest_fragment;
    pub mod unequal_colliders;
}

/// Porous aggregates in a disk: drag, speeds, compaction, growth (thesis ch. 4).
pub mod disk {
    pub mod collision_speeds;
    pub mod common;
    pub mod growth_tracks;
    pub mod porosity_track;
    pub mod stokes_number;
    pub mod timescales;
}

/// The Monte Carlo coagulation column (thesis Sects. 4.3–4.4).
pub mod monte_carlo {
    pub mod analytic_kernels;
    pub mod common;
    pub mod erosion_balance;
    pub mod families;
    pub mod mass_distribution;
}

/// The global dust-batch model over a whole disk (thesis ch. 5).
pub mod batches {
    pub mod batch_lifelines;
    pub mod common;
    pub mod disk_map;
    pub mod formation_zone;
    pub mod midplane_loading;
    pub mod planetesimal_yield;
    pub mod surface_density;
}

/// The argument across scales, on one screen.
pub mod overview {
    pub mod common;
    pub mod scale_ladder;
}
