//! Writing a computed scene into a folder: every figure as CSV, SVG and PNG
//! (each carrying the preset that produced it, see [`crate::provenance`])
//! and the scalars as JSON. The command line and the handouts both write
//! through here, so a folder looks the same whoever wrote it.

use crate::files::FileSet;
use crate::preset::Preset;
use crate::provenance::{Stamp, stage_figures};
use crate::scene::SceneOutput;
use anyhow::{Context, Result};
use std::path::{Path, PathBuf};

/// Writes every figure of `out` as CSV, SVG and PNG into `dir`, plus the
/// scalars as JSON and, with the `preset`, `preset.ron` (its first line names
/// the build that computed the folder; `grainscope run DIR/preset.ron`
/// computes it again), all or nothing: every file is rendered and staged before
/// any is put in place, so a failure (a full disk, a read-only folder) leaves
/// the folder as it was and no temporary file behind. With the `preset` that
/// produced `out`, the figures show its time cursor and every file carries
/// the preset (see [`crate::provenance`]). Returns the files written.
pub fn write_outputs(out: &SceneOutput, preset: Option<&Preset>, dir: &Path) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create folder {}", dir.display()))?;
    let stamp = preset.map(Stamp::of).transpose()?;
    let figures = preset.map_or_else(|| out.figures.clone(), |p| p.scene.exported_figures(out));
    let mut set = FileSet::new();
    let staged = (|| -> Result<()> {
        stage_figures(&mut set, &figures, dir, "", stamp.as_ref())?;
        let censored = preset.map_or(&[][..], |p| p.scene.censored());
        let text = serde_json::to_string_pretty(&out.scalars_json(censored))?;
        set.stage(&dir.join("scalars.json"), text.as_bytes())?;
        if let Some(p) = preset {
            let ron = format!("// computed by {}\n{}", crate::provenance::program(), p.to_ron()?);
            set.stage(&dir.join("preset.ron"), ron.as_bytes())?;
        }
        Ok(())
    })();
    if let Err(e) = staged {
        drop(set);
        return Err(e.context(format!("nothing was written to {} (files already there are unchanged)", dir.display())));
    }
    Ok(set.commit()?)
}
