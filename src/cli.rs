//! The headless harness: the same scenes as the window, from the command line.

use crate::figure::{write_atomically, write_csv, write_png, write_svg};
use crate::preset::{Preset, SHIPPED, resolve};
use crate::scene::{self, Progress, SceneOutput};
use anyhow::{Context, Result, bail};
use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};

/// Size of exported figures, pixels.
pub const FIGURE_SIZE: (u32, u32) = (900, 620);

/// grainscope: an explorer of dust microphysics. Without a command it opens the window.
#[derive(Debug, Parser)]
#[command(name = "grainscope", version, about)]
pub struct Cli {
    /// What to do; omit to open the explorer.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// Commands of the harness.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Open the explorer window, optionally with a preset.
    Gui {
        /// Preset file or shipped preset name.
        preset: Option<String>,
    },
    /// Compute a preset's scene without a window.
    Run {
        /// Preset file, or the name of a shipped preset (see `grainscope presets`).
        preset: String,
        /// Override a parameter by its documented key (SI units), e.g. `--set velocity=4`.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Write the scene's CSV data and figures (SVG, PNG) into this folder.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Print the scalar results as one JSON object on stdout.
        #[arg(long)]
        json: bool,
    },
    /// List the shipped presets.
    Presets,
    /// List a scene's parameters with units, ranges and meaning.
    Params {
        /// Scene id (hysteresis, restitution, adhesion).
        scene: String,
    },
    /// Regenerate the thesis figures covered here and the comparison table.
    Reproduce {
        /// Output folder.
        #[arg(long, value_name = "DIR", default_value = "reproduce")]
        out: PathBuf,
    },
}

/// Applies `key=value` overrides to a preset.
pub fn apply_sets(preset: &mut Preset, sets: &[String]) -> Result<()> {
    for s in sets {
        let (k, v) = s
            .split_once('=')
            .with_context(|| format!("--set expects KEY=VALUE, got '{s}'"))?;
        preset
            .scene
            .set(k.trim(), v)
            .with_context(|| format!("--set {s}"))?;
    }
    Ok(())
}

/// Writes every figure of `out` as CSV, SVG and PNG into `dir`, plus the
/// scalars as JSON. Returns the files written.
pub fn write_outputs(out: &SceneOutput, dir: &Path) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)
        .with_context(|| format!("cannot create folder {}", dir.display()))?;
    let mut files = Vec::new();
    for fig in &out.figures {
        let csv = dir.join(format!("{}.csv", fig.id));
        write_csv(fig, &csv)?;
        let svg = dir.join(format!("{}.svg", fig.id));
        write_svg(fig, &svg, FIGURE_SIZE)?;
        let png = dir.join(format!("{}.png", fig.id));
        write_png(fig, &png, FIGURE_SIZE)?;
        files.extend([csv, svg, png]);
    }
    let json = dir.join("scalars.json");
    let text = serde_json::to_string_pretty(&out.scalars_json())?;
    write_atomically(&json, text.as_bytes())?;
    files.push(json);
    Ok(files)
}

fn print_scalars(out: &SceneOutput) {
    for s in &out.scalars {
        println!("{:<45} {:>12.6e} {}", s.label, s.value, s.unit);
    }
    for n in &out.notes {
        println!("note: {n}");
    }
}

/// Runs a command of the harness. `Gui` is handled by the caller.
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Gui { .. } => bail!("the window is opened by the binary, not the harness"),
        Command::Run {
            preset,
            set,
            out,
            json,
        } => {
            let mut p = resolve(&preset)?;
            apply_sets(&mut p, &set)?;
            let result = scene::compute(&p.scene, &Progress::default())?;
            if let Some(dir) = &out {
                let files = write_outputs(&result, dir)?;
                if !json {
                    eprintln!("wrote {} files to {}", files.len(), dir.display());
                }
            }
            if json {
                println!("{}", serde_json::to_string(&result.scalars_json())?);
            } else {
                print_scalars(&result);
            }
            Ok(())
        }
        Command::Presets => {
            for (file, text) in SHIPPED {
                let p = Preset::from_ron(text, file)?;
                println!("{:<30} {:<12} {}", file, p.scene.info().id, p.title);
            }
            Ok(())
        }
        Command::Params { scene } => {
            let mut params = scene::SceneParams::default_for(&scene).with_context(|| {
                let ids: Vec<&str> = scene::SCENES.iter().map(|s| s.id).collect();
                format!("unknown scene '{scene}' (scenes: {})", ids.join(", "))
            })?;
            for c in params.controls() {
                println!("{}", c.doc_line());
            }
            Ok(())
        }
        Command::Reproduce { out } => reproduce(&out),
    }
}

fn reproduce(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir)
        .with_context(|| format!("cannot create folder {}", dir.display()))?;
    let checks = crate::reproduce::chapter2()?;
    let md = crate::reproduce::markdown(&checks);
    write_atomically(&dir.join("reproduce.md"), md.as_bytes())?;
    write_atomically(&dir.join("reproduce.csv"), &crate::reproduce::csv(&checks)?)?;
    for name in ["ice-bounce-8ms", "ice-stick-2ms", "restitution-ice"] {
        let p = resolve(name)?;
        let out = scene::compute(&p.scene, &Progress::default())?;
        write_outputs(&out, &dir.join(name))?;
    }
    print!("{md}");
    let failures = checks.iter().filter(|c| !c.pass() && !c.slip).count();
    if failures > 0 {
        bail!("{failures} published numbers are not reproduced");
    }
    Ok(())
}
