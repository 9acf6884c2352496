//! grainscope: an explorer of dust microphysics after S. Krijt, *From grains
//! to planetesimals* (Leiden 2015).
//!
//! The crate is split so that the models never know about the window:
//! [`physics`] and [`solver`] hold the models, [`scene`] turns parameters into
//! results and figures through pure `compute` functions, [`figure`] describes
//! and writes figures, [`files`] writes files so that nothing is lost, and [`app`] is the eframe front end. The command line
//! ([`cli`]) and the tests call the same `compute` functions as the window.

#[cfg(feature = "gui")]
pub mod app;
pub mod audit;
pub mod cli;
pub mod deck;
pub mod export;
pub mod figure;
pub mod files;
pub mod global_sensitivity;
pub mod handout;
pub mod links;
pub mod measurements;
pub mod parallel;
pub mod physics;
pub mod preset;
pub mod provenance;
pub mod reproduce;
pub mod scene;
pub mod sensitivity;
pub mod session;
pub mod solver;
pub mod sorting;
pub mod statics;
pub mod sweep;
pub mod sweep_files;
pub mod units;
