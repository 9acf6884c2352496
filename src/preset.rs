//! Presets: RON files holding a scene and its parameters.
//!
//! ```ron
//! (
//!     title: "Ice spheres bouncing at 8 m/s",
//!     description: "Reference set of the thesis, Fig. 2.2",
//!     scene: Hysteresis((collision: (velocity: 8.0, t_vis: 1e-11))),
//! )
//! ```
//!
//! Every field has a default, so a preset names only what differs and old
//! presets keep loading when parameters are added. Unknown keys and bad values
//! are reported with their line and column. All values are SI.

use crate::files::{WriteError, write_atomically};
use crate::provenance::{ProvenanceError, Stamp};
use crate::scene::{ParamError, SceneParams};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// A saved scene with its parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Preset {
    /// Short title.
    #[serde(default)]
    pub title: String,
    /// What the preset shows.
    #[serde(default)]
    pub description: String,
    /// The scene and its parameters.
    pub scene: SceneParams,
    /// The sensitivity view the file was exported from, if any: opening
    /// the file reopens it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensitivity: Option<crate::sensitivity::View>,
}

/// Why a preset could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum PresetError {
    /// The file could not be read.
    #[error("cannot read {}: {cause}", path.display())]
    Read {
        /// File.
        path: PathBuf,
        /// What the operating system said.
        cause: std::io::Error,
    },
    /// The RON text is malformed or has unknown keys or wrong types.
    #[error("{origin}:{line}:{column}: {message}")]
    Syntax {
        /// File name or "<text>".
        origin: String,
        /// Line (1-based).
        line: usize,
        /// Column (1-based).
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// A value is outside its documented range.
    #[error("{origin}: {error}")]
    Invalid {
        /// File name or "<text>".
        origin: String,
        /// The range error.
        error: Box<ParamError>,
    },
    /// The file could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
    /// Serialisation failed.
    #[error("cannot serialise preset: {0}")]
    Serialise(String),
    /// An exported figure or data file carries no usable state.
    #[error(transparent)]
    Embedded(Box<ProvenanceError>),
    /// The state embedded in an exported file does not load.
    #[error("the state embedded in {origin} does not load: {error}")]
    EmbeddedInvalid {
        /// File.
        origin: String,
        /// Why.
        error: Box<PresetError>,
    },
}

impl Stamp {
    /// The stamp of a preset, with this program's version.
    pub fn of(preset: &Preset) -> Result<Stamp, PresetError> {
        let text = ron::ser::to_string_pretty(preset, ron::ser::PrettyConfig::default().struct_names(false))
            .map_err(|e| PresetError::Serialise(e.to_string()))?;
        Ok(Stamp { program: crate::provenance::program(), preset: text })
    }
}

/// The preset embedded in an exported PNG, SVG or CSV file (see
/// [`crate::provenance`]).
pub fn read_embedded(path: &Path) -> Result<Preset, PresetError> {
    let text = crate::provenance::read(path).map_err(|e| PresetError::Embedded(Box::new(e)))?;
    embedded(&text, &path.display().to_string())
}

/// The preset embedded in the bytes of an exported PNG, SVG or CSV file;
/// `name` (a file name or path) gives the kind by its extension and names
/// the file in errors.
pub fn from_embedded_bytes(bytes: &[u8], name: &str) -> Result<Preset, PresetError> {
    let text = crate::provenance::from_bytes(bytes, name).map_err(|e| PresetError::Embedded(Box::new(e)))?;
    embedded(&text, name)
}

fn embedded(text: &str, origin: &str) -> Result<Preset, PresetError> {
    Preset::from_ron(text, &format!("{origin} (embedded state)"))
        .map_err(|error| PresetError::EmbeddedInvalid { origin: origin.to_string(), error: Box::new(error) })
}

impl Preset {
    /// Parses and validates a preset from RON text; `origin` names it in errors.
    pub fn from_ron(text: &str, origin: &str) -> Result<Preset, PresetError> {
        let preset: Preset = ron::from_str(text).map_err(|e| PresetError::Syntax {
            origin: origin.into(),
            line: e.span.start.line,
            column: e.span.start.col,
            message: e.code.to_string(),
        })?;
        preset.scene.validate().map_err(|e| {
            let (origin, error) = match e {
                ParamError::OutOfRange { key, value, min, max, unit } => {
                    // Name the value as written in the file, with its line and column.
                    let (place, value) = match find_number(text, &key, &value) {
                        Some((line, column, written)) => (format!("{origin}:{line}:{column}"), written),
                        None => (origin.to_string(), value),
                    };
                    (place, ParamError::OutOfRange { key, value, min, max, unit })
                }
                other => (origin.to_string(), other),
            };
            PresetError::Invalid { origin, error: Box::new(error) }
        })?;
        Ok(preset)
    }

    /// Reads a preset file.
    pub fn load(path: &Path) -> Result<Preset, PresetError> {
        let text = std::fs::read_to_string(path).map_err(|cause| PresetError::Read { path: path.into(), cause })?;
        Preset::from_ron(&text, &path.display().to_string())
    }

    /// The preset as RON text, preceded by comments documenting every key
    /// with its unit and range.
    pub fn to_ron(&self) -> Result<String, PresetError> {
        let body = ron::ser::to_string_pretty(self, ron::ser::PrettyConfig::default().struct_names(false))
            .map_err(|e| PresetError::Serialise(e.to_string()))?;
        let mut out = format!("// grainscope preset, scene '{}'. All values in SI units.\n", self.scene.info().id);
        for s in self.scene.specs() {
            out.push_str("//   ");
            out.push_str(&s.doc_line());
            out.push('\n');
        }
        out.push_str(&body);
        out.push('\n');
        Ok(out)
    }

    /// Writes the preset atomically (an existing file stays intact on error).
    pub fn save(&self, path: &Path) -> Result<(), PresetError> {
        write_atomically(path, self.to_ron()?.as_bytes())?;
        Ok(())
    }
}

/// Finds `key: NUMBER` in RON text whose number reads as `value` (the
/// value as printed by the range check): the line and column (1-based) of the
/// number and the number as written.
fn find_number(text: &str, key: &str, value: &str) -> Option<(usize, usize, String)> {
    // The message carries the value to six digits (`controls::short`).
    let same = |x: f64| crate::scene::controls::short(x) == value;
    let mut from = 0;
    while let Some(found) = text[from..].find(key) {
        let start = from + found;
        from = start + key.len();
        let before_ok = text[..start].chars().next_back().is_none_or(|c| !(c.is_alphanumeric() || c == '_'));
        let rest = &text[from..];
        let after_colon = rest.trim_start().strip_prefix(':');
        let (true, Some(after)) = (before_ok, after_colon) else { continue };
        let number = after.trim_start();
        let written: String =
            number.chars().take_while(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '+' | '_')).collect();
        if written.parse::<f64>().is_ok_and(same) {
            let offset = text.len() - number.len();
            let line = text[..offset].matches('\n').count() + 1;
            let column = text[..offset].rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
            return Some((line, column, written));
        }
    }
    None
}

/// The presets shipped in `presets/`, compiled into the binary: (file name, text).
pub const SHIPPED: [(&str, &str); 53] = [
    ("ice-bounce-8ms.ron", include_str!("../presets/ice-bounce-8ms.ron")),
    ("ice-stick-2ms.ron", include_str!("../presets/ice-stick-2ms.ron")),
    ("ice-quasistatic.ron", include_str!("../presets/ice-quasistatic.ron")),
    ("restitution-ice.ron", include_str!("../presets/restitution-ice.ron")),
    ("sticking-velocity-ice.ron", include_str!("../presets/sticking-velocity-ice.ron")),
    ("adhesion-ice-monomers.ron", include_str!("../presets/adhesion-ice-monomers.ron")),
    ("experiments-fig-2-11.ron", include_str!("../presets/experiments-fig-2-11.ron")),
    ("material-parameters.ron", include_str!("../presets/material-parameters.ron")),
    ("fit-wall-mica-synthetic.ron", include_str!("../presets/fit-wall-mica-synthetic.ron")),
    ("rolling-contact-psl.ron", include_str!("../presets/rolling-contact-psl.ron")),
    ("rolling-silica-force.ron", include_str!("../presets/rolling-silica-force.ron")),
    ("rolling-psl-glass-force.ron", include_str!("../presets/rolling-psl-glass-force.ron")),
    ("rolling-ding-critical.ron", include_str!("../presets/rolling-ding-critical.ron")),
    ("rolling-psl-aluminium-rocking.ron", include_str!("../presets/rolling-psl-aluminium-rocking.ron")),
    ("debris-fig-6-1-top.ron", include_str!("../presets/debris-fig-6-1-top.ron")),
    ("debris-fig-6-1-bottom.ron", include_str!("../presets/debris-fig-6-1-bottom.ron")),
    ("debris-fig-6-2.ron", include_str!("../presets/debris-fig-6-2.ron")),
    ("debris-fig-6-3.ron", include_str!("../presets/debris-fig-6-3.ron")),
    ("disk-fig-4-1.ron", include_str!("../presets/disk-fig-4-1.ron")),
    ("disk-fig-4-2-compact.ron", include_str!("../presets/disk-fig-4-2-compact.ron")),
    ("disk-fig-4-2-porous.ron", include_str!("../presets/disk-fig-4-2-porous.ron")),
    ("disk-fig-4-5.ron", include_str!("../presets/disk-fig-4-5.ron")),
    ("disk-fig-4-7.ron", include_str!("../presets/disk-fig-4-7.ron")),
    ("disk-fig-4-8.ron", include_str!("../presets/disk-fig-4-8.ron")),
    ("disk-fig-4-13.ron", include_str!("../presets/disk-fig-4-13.ron")),
    ("disk-fig-4-13-erosion.ron", include_str!("../presets/disk-fig-4-13-erosion.ron")),
    ("batch-fig-5-1.ron", include_str!("../presets/batch-fig-5-1.ron")),
    ("batch-fig-5-3.ron", include_str!("../presets/batch-fig-5-3.ron")),
    ("batch-fig-5-4.ron", include_str!("../presets/batch-fig-5-4.ron")),
    ("batch-fig-5-5.ron", include_str!("../presets/batch-fig-5-5.ron")),
    ("batch-fig-5-6.ron", include_str!("../presets/batch-fig-5-6.ron")),
    ("batch-fig-5-7.ron", include_str!("../presets/batch-fig-5-7.ron")),
    ("batch-fig-5-8-extended.ron", include_str!("../presets/batch-fig-5-8-extended.ron")),
    ("batch-fig-5-8-weak.ron", include_str!("../presets/batch-fig-5-8-weak.ron")),
    ("batch-fig-5-9.ron", include_str!("../presets/batch-fig-5-9.ron")),
    ("batch-fig-5-10.ron", include_str!("../presets/batch-fig-5-10.ron")),
    ("batch-fig-5-11.ron", include_str!("../presets/batch-fig-5-11.ron")),
    ("batch-fig-5-12.ron", include_str!("../presets/batch-fig-5-12.ron")),
    ("batch-fig-5-13.ron", include_str!("../presets/batch-fig-5-13.ron")),
    ("batch-fig-5-14.ron", include_str!("../presets/batch-fig-5-14.ron")),
    ("batch-fig-5-15.ron", include_str!("../presets/batch-fig-5-15.ron")),
    ("mc-fig-4-4.ron", include_str!("../presets/mc-fig-4-4.ron")),
    ("mc-fig-4-6.ron", include_str!("../presets/mc-fig-4-6.ron")),
    ("mc-fig-4-9.ron", include_str!("../presets/mc-fig-4-9.ron")),
    ("mc-fig-4-10-4-11.ron", include_str!("../presets/mc-fig-4-10-4-11.ron")),
    ("mc-fig-4-12.ron", include_str!("../presets/mc-fig-4-12.ron")),
    ("mc-fig-5-2-porosity.ron", include_str!("../presets/mc-fig-5-2-porosity.ron")),
    ("mc-kernel-constant.ron", include_str!("../presets/mc-kernel-constant.ron")),
    ("mc-kernel-linear.ron", include_str!("../presets/mc-kernel-linear.ron")),
    ("mc-kernel-product.ron", include_str!("../presets/mc-kernel-product.ron")),
    ("mc-kernel-constant-capped.ron", include_str!("../presets/mc-kernel-constant-capped.ron")),
    ("mc-kernel-linear-capped.ron", include_str!("../presets/mc-kernel-linear-capped.ron")),
    ("mc-kernel-product-capped.ron", include_str!("../presets/mc-kernel-product-capped.ron")),
];

/// Finds a preset by path, or by the name of a shipped preset (with or
/// without `.ron`). A PNG, SVG or CSV file exported by grainscope stands for
/// the preset embedded in it (see [`crate::provenance`]).
pub fn resolve(name: &str) -> Result<Preset, PresetError> {
    let path = Path::new(name);
    if path.exists() {
        if crate::provenance::may_carry_state(path) {
            return read_embedded(path);
        }
        return Preset::load(path);
    }
    let stem = name.trim_end_matches(".ron");
    let stem = stem.rsplit('/').next().unwrap_or(stem);
    match SHIPPED.iter().find(|(file, _)| file.trim_end_matches(".ron") == stem) {
        Some((file, text)) => Preset::from_ron(text, file),
        None => Err(PresetError::Read {
            path: path.into(),
            cause: std::io::Error::new(
                std::io::ErrorKind::NotFound,
                format!("no such file and no shipped preset of that name{}", {
                    let names: Vec<&str> = SHIPPED.iter().map(|(file, _)| file.trim_end_matches(".ron")).collect();
                    crate::scene::controls::did_you_mean(stem, &names)
                }),
            ),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn preset() -> Preset {
        resolve("ice-bounce-8ms").expect("shipped")
    }

    /// The embedded preset reads back equal from all three kinds of file.
    #[test]
    fn state_survives_every_export_format() {
        let preset = preset();
        let stamp = Stamp::of(&preset).expect("stamp");
        let dir = tempfile::tempdir().expect("tempdir");
        let out = crate::scene::compute(&preset.scene, &crate::scene::Progress::default()).expect("computes");
        let fig = &out.figures[0];
        let png = crate::figure::png_bytes_with_text(fig, (320, 240), &stamp.png_text()).expect("png");
        let svg = stamp.svg(&crate::figure::svg_string(fig, (320, 240)).expect("svg"));
        let csv = stamp.csv(&crate::figure::csv_bytes(fig).expect("csv"));
        for (name, bytes) in [("f.png", png), ("f.svg", svg.into_bytes()), ("f.csv", csv)] {
            let path = dir.path().join(name);
            std::fs::write(&path, bytes).expect("write");
            assert_eq!(read_embedded(&path).expect(name), preset, "{name}");
        }
    }

    /// A preset whose text contains the CDATA terminator still round-trips.
    #[test]
    fn cdata_terminators_are_split() {
        let mut preset = preset();
        preset.description = "a ]]> b".into();
        let stamp = Stamp::of(&preset).expect("stamp");
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("f.svg");
        std::fs::write(&path, stamp.svg("<svg width=\"1\">\n</svg>")).expect("write");
        assert_eq!(read_embedded(&path).expect("loads"), preset);
    }
}
