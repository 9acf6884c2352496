//! The headless harness: the same scenes as the window, from the command line.

use crate::export::write_outputs;
use crate::files::write_atomically;
use crate::preset::{Preset, SHIPPED, resolve};
use crate::scene::{self, Progress, SceneOutput};
use anyhow::{Context, Result, bail};
use clap::{Parser, Subcommand};
use std::io::Write;
use std::path::{Path, PathBuf};

/// grainscope: an explorer of dust microphysics. Without a command it opens the window.
#[derive(Debug, Parser)]
#[command(name = "grainscope", version = env!("GRAINSCOPE_BUILD"), about)]
pub struct Cli {
    /// What to do; omit to open the explorer.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// Commands of the harness.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Open the explorer window, optionally with presets, exported figures
    /// or a deck (presented at once).
    Gui {
        /// Preset files or shipped preset names, PNG/SVG/CSV files exported by
        /// grainscope (their embedded state), or a deck file or shipped deck name.
        files: Vec<String>,
    },
    /// Compute a preset's scene without a window.
    Run {
        /// Preset file, the name of a shipped preset (see `grainscope presets`),
        /// or a PNG, SVG or CSV file exported by grainscope (its embedded state).
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
        /// Print the preset (RON) after `--set`, without computing: the state
        /// a preset file or an exported figure opens.
        #[arg(long, conflicts_with_all = ["out", "json"])]
        preset_only: bool,
    },
    /// Compute a preset's scalars over a grid of parameter values: one tidy
    /// CSV (a row per point: the varied parameters, then the scalars; units in
    /// the header) and its figure. A failing point records its error in its
    /// row; a rerun into the same folder skips the points already done.
    Sweep {
        /// Preset file, shipped preset name or exported figure.
        preset: String,
        /// A varied parameter, `NAME=lin|log:FROM:TO:N` or the values
        /// themselves, `NAME=list:V1:V2:…` (SI units); repeat for a grid (the
        /// last one varies fastest).
        #[arg(long = "vary", value_name = "NAME=lin|log:FROM:TO:N|list:V1:V2:…", required_unless_present = "points")]
        vary: Vec<String>,
        /// The points themselves, from a CSV table instead of a grid: a header
        /// of parameter keys, a row of SI values per point.
        #[arg(long, value_name = "TABLE.csv", conflicts_with = "vary")]
        points: Option<PathBuf>,
        /// A parameter that takes another's value at every point, e.g.
        /// `--tie radius_2=radius_1` (equal spheres).
        #[arg(long = "tie", value_name = "TIED=SOURCE")]
        tie: Vec<String>,
        /// Override a parameter by its documented key, e.g. `--set velocity=4`.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Only these scalars (keys of `run --json`), comma-separated; all by default.
        #[arg(long, value_delimiter = ',', value_name = "A,B")]
        scalars: Vec<String>,
        /// Run one deterministic slice `K/N` of the points, or `auto` for the
        /// task of a Slurm job array; merge the slices with `sweep-merge`.
        #[arg(long, default_value = "1/1", value_name = "K/N|auto")]
        shard: String,
        /// Output folder (sweep.csv, sweep.ron, sweep.png, sweep.svg).
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
    },
    /// Global sensitivity of one scalar over parameter ranges: Morris's
    /// elementary effects (μ, μ*, σ) or Sobol' indices (S1, ST, with
    /// bootstrap intervals; S2 on request). The design's runs are a sweep
    /// (sweep.csv, sweep.ron: resumable, shardable, mergeable with
    /// `sweep-merge`); the analysis writes indices.csv, sensitivity.json and
    /// sensitivity.png/svg. With `--analyse`, analyses a merged folder.
    Sensitivity {
        /// Preset file, shipped preset name or exported figure (not with `--analyse`).
        #[arg(required_unless_present = "analyse")]
        preset: Option<String>,
        /// `morris` or `sobol`.
        #[arg(long, default_value = "morris", value_name = "morris|sobol")]
        method: String,
        /// A varied parameter and its range, `NAME=lin|log:FROM:TO` (SI units); repeat.
        #[arg(long = "vary", value_name = "NAME=lin|log:FROM:TO")]
        vary: Vec<String>,
        /// A parameter that takes another's value at every point, e.g.
        /// `--tie radius_2=radius_1` (equal spheres as one factor).
        #[arg(long = "tie", value_name = "TIED=SOURCE")]
        tie: Vec<String>,
        /// The scalar analysed (a key of `run --json`).
        #[arg(long, value_name = "KEY")]
        output: Option<String>,
        /// Morris: trajectories r (default 20); Sobol': base samples N, a power of two (default 256).
        #[arg(long)]
        samples: Option<usize>,
        /// Morris: grid levels p (even).
        #[arg(long, default_value_t = 4)]
        levels: usize,
        /// Sobol': second-order indices too (N(2d + 2) runs instead of N(d + 2)).
        #[arg(long)]
        second_order: bool,
        /// Seed of the design (trajectories or scramble) and the bootstrap.
        #[arg(long, default_value_t = 2015)]
        seed: u64,
        /// Override a parameter by its documented key, e.g. `--set velocity=4`.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Run one deterministic slice `K/N` of the runs, or `auto` for the
        /// task of a Slurm job array; merge with `sweep-merge`, then `--analyse`.
        #[arg(long, default_value = "1/1", value_name = "K/N|auto")]
        shard: String,
        /// Output folder.
        #[arg(long, value_name = "DIR", required_unless_present = "analyse")]
        out: Option<PathBuf>,
        /// Analyse the finished (or merged) folder DIR instead of running.
        #[arg(long, value_name = "DIR", conflicts_with_all = ["preset", "out"])]
        analyse: Option<PathBuf>,
        /// Analyse the natural logarithm of the output (effects become relative
        /// changes; a non-positive output counts as undefined).
        #[arg(long)]
        log_output: bool,
    },
    /// What matters for one scalar: every numeric parameter's elasticity
    /// ∂ln X/∂ln p at the preset's point and X over a factor around it, sorted.
    Matters {
        /// Preset file, shipped preset name or exported figure.
        preset: String,
        /// The scalar (a key of `run --json`).
        #[arg(long, value_name = "KEY")]
        output: String,
        /// Each parameter divided and multiplied by this factor (> 1).
        #[arg(long, default_value_t = 2.0)]
        factor: f64,
        /// Override a parameter by its documented key, e.g. `--set velocity=4`.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Print one JSON object instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// The continuity audit: sweep every parameter of each preset over its
    /// documented range (one at a time, around the preset's point) and report
    /// errors, undefined and missing values, steps in a scalar and parameters
    /// that change the figures but no scalar. Findings the scene declares as
    /// physics are listed with their reason; any other fails the audit
    /// (exit status 1).
    Audit {
        /// Preset files or shipped preset names; every shipped preset when none.
        presets: Vec<String>,
        /// Grid points along each numeric parameter's range.
        #[arg(long, default_value_t = 24, value_parser = clap::value_parser!(u32).range(3..=1000))]
        points: u32,
        /// Bisections of the interval of each step candidate.
        #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=40))]
        refine: u32,
        /// Only these parameters (keys, comma-separated); all by default.
        #[arg(long, value_delimiter = ',', value_name = "A,B")]
        only: Vec<String>,
        /// Override a parameter of every preset by its documented key, e.g. `--set crack_law=thesis`.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Audit heavy scenes at the cheaper setting of their preview (the numbers that setting
        /// lowers, such as the Monte Carlo groups per decade, are swept only up to it).
        #[arg(long)]
        coarse: bool,
        /// Leave heavy scenes out.
        #[arg(long, conflicts_with = "coarse")]
        light: bool,
        /// Print one JSON object per preset (a line each) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Merge the folders of a sharded sweep into the files of the whole run.
    SweepMerge {
        /// The shards' output folders.
        #[arg(required = true)]
        shards: Vec<PathBuf>,
        /// Output folder.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
    },
    /// Write a deck's handout: every slide's figures (PNG, SVG, CSV) in its
    /// own folder and an index.md with titles and speaker notes.
    Deck {
        /// Deck file, or the name of a shipped deck (see `grainscope decks`).
        deck: String,
        /// Output folder.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
    },
    /// List the shipped decks.
    Decks,
    /// Play a scene's history and write its frames: numbered PNGs per figure
    /// and an animated PNG (scenes with a time cursor).
    Movie {
        /// Preset file, shipped preset name or exported figure.
        preset: String,
        /// Override a parameter by its documented key, e.g. `--set velocity=4`.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Number of frames, from the start of the history to its end.
        #[arg(long, default_value_t = 48, value_parser = clap::value_parser!(u32).range(2..=2000))]
        frames: u32,
        /// Only this figure (by id, the file stem of `run --out`).
        #[arg(long, value_name = "ID")]
        figure: Option<String>,
        /// Frames per second of the animated PNG.
        #[arg(long, default_value_t = 12, value_parser = clap::value_parser!(u16).range(1..=60))]
        fps: u16,
        /// Write only the numbered frames, no animated PNG.
        #[arg(long)]
        no_animation: bool,
        /// Output folder.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
    },
    /// List the shipped presets.
    Presets,
    /// List a scene's parameters with units, ranges and meaning (every
    /// scene's, as Markdown, with --markdown).
    Params {
        /// Scene id (hysteresis, restitution, adhesion); omit it with --markdown.
        #[arg(required_unless_present = "markdown")]
        scene: Option<String>,
        /// Print every scene's parameter reference as Markdown (docs/parameters.md).
        #[arg(long)]
        markdown: bool,
    },
    /// Fit γ, T_vis and Y of the restitution model to measurements (CSV with
    /// 'velocity [m/s]', 'restitution' and optional 'uncertainty' columns).
    Fit {
        /// The measurements.
        data: PathBuf,
        /// Projectile and target material of Table 2.2, e.g. `AF,mica`.
        #[arg(long, value_delimiter = ',', num_args = 1..=2, required = true)]
        materials: Vec<String>,
        /// `wall` (sphere on a flat target) or `spheres` (two spheres).
        #[arg(long, value_enum)]
        geometry: Geometry,
        /// Projectile radius, m.
        #[arg(long)]
        radius: f64,
        /// Target sphere radius, m (default: equal to --radius).
        #[arg(long)]
        radius2: Option<f64>,
        /// Grid points per fitted parameter.
        #[arg(long, default_value_t = 16)]
        grid: usize,
        /// Override a fit parameter by its documented key (see `grainscope params fit`).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Write the fit figures (CSV, SVG, PNG) into this folder.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Print the result as one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// Regenerate the thesis figures covered here and the comparison table.
    Reproduce {
        /// Output folder.
        #[arg(long, value_name = "DIR", default_value = "reproduce")]
        out: PathBuf,
        /// Monte Carlo figures with fewer groups per decade, two runs each and
        /// capped events: minutes instead of an hour, looser agreement.
        #[arg(long)]
        quick: bool,
        /// Leave out the Monte Carlo runs (Figs. 4.4-4.12, 5.2 and the kernel
        /// tests): seconds instead of minutes, for a check of the other chapters.
        #[arg(long)]
        without_monte_carlo: bool,
        /// Only these chapters' rows and figures (2 to 6, e.g. `--chapters 2,3,6`;
        /// the Monte Carlo runs belong to 4 and 5). All chapters when not given.
        #[arg(long, value_delimiter = ',', value_name = "N,M", value_parser = clap::value_parser!(u8).range(2..=6))]
        chapters: Vec<u8>,
    },
}

/// Geometry of a fitted experiment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Geometry {
    /// A sphere on a flat target.
    Wall,
    /// Two spheres.
    Spheres,
}

/// Applies `key=value` overrides to a preset.
pub fn apply_sets(preset: &mut Preset, sets: &[String]) -> Result<()> {
    for s in sets {
        let (k, v) = s.split_once('=').with_context(|| format!("--set expects KEY=VALUE, got '{s}'"))?;
        preset.scene.set(k.trim(), v).with_context(|| format!("--set {s}"))?;
    }
    Ok(())
}

/// A check that ran and found what it checks for (the audit's undeclared
/// findings): the binary exits with status 1, not the 2 of bad input.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct CheckFailed(pub String);

/// Whether `error` comes from writing to a closed standard output (the
/// reader of a pipe went away, as in `grainscope presets | head -1`): the
/// command then ends quietly.
pub fn is_closed_pipe(error: &anyhow::Error) -> bool {
    error
        .chain()
        .any(|cause| cause.downcast_ref::<std::io::Error>().is_some_and(|e| e.kind() == std::io::ErrorKind::BrokenPipe))
}

/// Prints `text` and a newline on standard output, returning the error of a
/// closed pipe instead of panicking.
fn say(text: impl std::fmt::Display) -> Result<()> {
    let mut stdout = std::io::stdout().lock();
    writeln!(stdout, "{text}")?;
    Ok(())
}

/// Prints a message on standard error; a closed standard error is ignored.
fn tell(text: impl std::fmt::Display) {
    let _ = writeln!(std::io::stderr(), "{text}");
}

fn print_scalars(out: &SceneOutput, censored: &[scene::Censored]) -> Result<()> {
    for s in &out.scalars {
        match scene::status(censored, s.key, s.value) {
            scene::Status::Value => say(format_args!("{:<45} {:>12.6e} {}", s.label, s.value, s.unit))?,
            scene::Status::Above { bound, why } => {
                say(format_args!("{:<45} > {:>10.4e} {} (a lower bound: {why})", s.label, bound, s.unit))?
            }
            scene::Status::Undefined { why } => say(format_args!("{:<45} {:>12} ({why})", s.label, "undefined"))?,
        }
    }
    for n in &out.notes {
        say(format_args!("note: {n}"))?;
    }
    Ok(())
}

/// Runs a command of the harness. `Gui` is handled by the caller.
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Gui { .. } => bail!("the window is opened by the binary, not the harness"),
        Command::Run { preset, set, out, json, preset_only } => {
            let mut p = resolve(&preset)?;
            apply_sets(&mut p, &set)?;
            if preset_only {
                return say(p.to_ron()?);
            }
            let result = scene::compute(&p.scene, &Progress::default())?;
            for w in &result.warnings {
                tell(format_args!("warning: {w}"));
            }
            if let Some(dir) = &out {
                let files = write_outputs(&result, Some(&p), dir)?;
                if !json {
                    tell(format_args!("wrote {} files to {}", files.len(), dir.display()));
                }
            }
            let censored = p.scene.censored();
            if json {
                say(serde_json::to_string(&result.scalars_json(censored))?)
            } else {
                print_scalars(&result, censored)
            }
        }
        Command::Sweep { preset, vary, points, tie, set, scalars, shard, out } => {
            let mut p = resolve(&preset)?;
            apply_sets(&mut p, &set)?;
            let shard = crate::sweep::Shard::parse(&shard, |k| std::env::var(k).ok())?;
            let report = |done: usize, total: usize| {
                // About twenty progress lines per run.
                if done.is_multiple_of((total / 20).max(1)) || done == total {
                    tell(format_args!("{done}/{total} points"));
                }
            };
            let s = match points {
                Some(table) => {
                    let text =
                        std::fs::read_to_string(&table).with_context(|| format!("cannot read {}", table.display()))?;
                    let design = crate::global_sensitivity::Design::given(&text)
                        .map_err(|e| anyhow::anyhow!("{}: {e}", table.display()))?;
                    crate::sweep_files::run_design(p, design, &tie, &scalars, shard, &out, &report)?
                }
                None => crate::sweep_files::run(p, &vary, &tie, &scalars, shard, &out, &report)?,
            };
            say(format_args!(
                "{} points ({} already done, {} failed); wrote {}",
                s.points,
                s.reused,
                s.failed,
                s.files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>().join(", ")
            ))
        }
        Command::Matters { preset, output, factor, set, json } => {
            let mut p = resolve(&preset)?;
            apply_sets(&mut p, &set)?;
            if !(factor.is_finite() && factor > 1.0) {
                bail!("--factor {factor}: expected a number above 1");
            }
            let m = crate::sensitivity::what_matters(&p.scene, &output, factor, &Progress::default())?;
            if json {
                let rows: Vec<serde_json::Value> = m
                    .rows
                    .iter()
                    .map(|r| {
                        serde_json::json!({"key": r.key, "unit": r.unit, "value": r.value, "elasticity": r.elasticity,
                            "converged": r.converged, "low": r.range[0], "high": r.range[1],
                            "low_sd": r.range_sd[0], "high_sd": r.range_sd[1], "below_noise": r.below_noise,
                            "low_status": r.range_status[0], "high_status": r.range_status[1],
                            "numerical": r.numerical})
                    })
                    .collect();
                return say(serde_json::json!({"output": output, "value": m.here.mean, "sd": m.here.sd,
                    "seeds": m.here.runs, "factor": factor, "parameters": rows,
                    "program": crate::provenance::program(), "preset": p.to_ron()?}));
            }
            say(format_args!("{}", crate::sensitivity::matters_text(&m, &output, factor)))
        }
        Command::Audit { presets, points, refine, only, set, coarse, light, json } => {
            let names: Vec<String> = if presets.is_empty() {
                SHIPPED.iter().map(|(file, _)| file.trim_end_matches(".ron").to_string()).collect()
            } else {
                presets
            };
            let options =
                crate::audit::Options { points: points as usize, refine: refine as usize, only, ceilings: Vec::new() };
            let mut failing = Vec::new();
            for name in &names {
                let mut p = resolve(name)?;
                apply_sets(&mut p, &set)?;
                let heavy = p.scene.info().heavy;
                if heavy && light {
                    continue;
                }
                let (base, ceilings) = match p.scene.coarse() {
                    Some(c) if heavy && coarse => {
                        let ceilings = crate::audit::ceilings(&p.scene, &c);
                        (c, ceilings)
                    }
                    _ => (p.scene.clone(), Vec::new()),
                };
                let options = crate::audit::Options { ceilings, ..options.clone() };
                let started = std::time::Instant::now();
                let report = crate::audit::audit(&base, &options, &Progress::default())
                    .with_context(|| format!("auditing {name}"))?;
                if report.failures().next().is_some() {
                    failing.push(name.clone());
                }
                if json {
                    say(serde_json::json!({"preset": name, "coarse": heavy && coarse, "report": report,
                        "program": crate::provenance::program()}))?;
                } else {
                    let setting = if heavy && coarse { " (coarse)" } else { "" };
                    say(format_args!("{name}{setting} — {}", report.text().trim_end()))?;
                    tell(format_args!("{name}: {:.1} s", started.elapsed().as_secs_f64()));
                }
            }
            if !failing.is_empty() {
                return Err(CheckFailed(format!(
                    "the audit fails for {} of {} presets: {}",
                    failing.len(),
                    names.len(),
                    failing.join(", ")
                ))
                .into());
            }
            Ok(())
        }
        Command::Sensitivity {
            preset,
            method,
            vary,
            tie,
            output,
            samples,
            levels,
            second_order,
            seed,
            set,
            shard,
            out,
            analyse,
            log_output,
        } => {
            use crate::global_sensitivity::{Design, Method, parse_factor};
            let dir = match (analyse, preset, out) {
                (Some(dir), _, _) => dir,
                (None, Some(preset), Some(out)) => {
                    let mut p = resolve(&preset)?;
                    apply_sets(&mut p, &set)?;
                    let factors = vary
                        .iter()
                        .map(|v| parse_factor(v))
                        .collect::<Result<Vec<_>, _>>()
                        .map_err(|e| anyhow::anyhow!(e))?;
                    if factors.is_empty() {
                        bail!("nothing to vary: give --vary NAME=lin|log:FROM:TO (one per parameter)");
                    }
                    let Some(output) = output else { bail!("--output KEY: which scalar to analyse") };
                    let method = match method.as_str() {
                        "morris" => Method::Morris { trajectories: samples.unwrap_or(20), levels },
                        "sobol" => Method::Sobol { samples: samples.unwrap_or(256), second_order },
                        other => bail!("--method {other}: expected morris or sobol"),
                    };
                    let design = Design { method, factors, seed };
                    design.unit_points()?;
                    let shard = crate::sweep::Shard::parse(&shard, |k| std::env::var(k).ok())?;
                    let mine = (0..design.runs()).filter(|&i| shard.owns(i)).count();
                    // One run at the preset's point, timed, for the estimate.
                    let clock = std::time::Instant::now();
                    crate::scene::compute(&p.scene, &Progress::default())?;
                    let each = clock.elapsed().as_secs_f64();
                    let threads = rayon::current_num_threads().max(1) as f64;
                    tell(format_args!(
                        "{} runs ({} in this shard); about {} s on {threads} threads",
                        design.runs(),
                        mine,
                        crate::figure::human((each * mine as f64 / threads).max(0.1))
                    ));
                    let report = |done: usize, total: usize| {
                        if done.is_multiple_of((total / 20).max(1)) || done == total {
                            tell(format_args!("{done}/{total} runs"));
                        }
                    };
                    let s = crate::sweep_files::run_design(p, design, &tie, &[output], shard, &out, &report)?;
                    say(format_args!("{} runs ({} already done, {} failed)", s.points, s.reused, s.failed))?;
                    if shard != crate::sweep::Shard::ALL {
                        return say(format_args!(
                            "shard {}/{} written to {}; merge the shards with `grainscope sweep-merge`, then analyse \
                             with `grainscope sensitivity --analyse DIR`",
                            shard.k,
                            shard.n,
                            out.display()
                        ));
                    }
                    out
                }
                _ => bail!("give a preset and --out, or --analyse DIR"),
            };
            let (a, files) = crate::sweep_files::analyse(&dir, log_output)?;
            say(crate::sweep_files::indices_csv(&a).trim_end())?;
            say(format_args!(
                "{} runs; {} undefined ({}); {} bounds ({}); wrote {}",
                a.runs,
                a.undefined,
                crate::sweep_files::UNDEFINED_RULE,
                a.bounded,
                crate::sweep_files::BOUND_RULE,
                files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>().join(", ")
            ))
        }
        Command::SweepMerge { shards, out } => {
            let files = crate::sweep_files::merge(&shards, &out)?;
            say(format_args!("merged {} shards; wrote {} files to {}", shards.len(), files.len(), out.display()))
        }
        Command::Deck { deck, out } => {
            let loaded = crate::deck::resolve(&deck)?;
            let n = loaded.deck.slides.len();
            let files =
                crate::handout::deck(&loaded, &out, &|i, title| tell(format_args!("slide {}/{n}: {title}", i + 1)))?;
            say(format_args!(
                "wrote {} files to {} (index: {})",
                files.len(),
                out.display(),
                out.join("index.md").display()
            ))
        }
        Command::Decks => {
            for (file, text) in crate::deck::SHIPPED {
                let d = crate::deck::Deck::from_ron(text, file, None)?;
                say(format_args!("{:<30} {:>3} slides  {}", file, d.deck.slides.len(), d.deck.title))?;
            }
            Ok(())
        }
        Command::Movie { preset, set, frames, figure, fps, no_animation, out } => {
            let mut p = resolve(&preset)?;
            apply_sets(&mut p, &set)?;
            let files =
                crate::handout::movie(&p, frames as usize, figure.as_deref(), !no_animation, fps, &out, &|| false)?;
            say(format_args!("wrote {} files to {}", files.len(), out.display()))
        }
        Command::Presets => {
            for (file, text) in SHIPPED {
                let p = Preset::from_ron(text, file)?;
                say(format_args!("{:<30} {:<12} {}", file, p.scene.info().id, p.title))?;
            }
            Ok(())
        }
        Command::Params { markdown: true, .. } => {
            say(scene::parameter_reference().trim_end())?;
            Ok(())
        }
        Command::Params { scene, .. } => {
            let scene = scene.unwrap_or_default();
            let params = scene::SceneParams::default_for(&scene).with_context(|| {
                let ids: Vec<&str> = scene::SCENES.iter().map(|s| s.id).collect();
                let close = crate::scene::controls::did_you_mean(&scene, &ids);
                format!("unknown scene '{scene}'{close} (scenes: {})", ids.join(", "))
            })?;
            for s in params.specs() {
                say(s.doc_line())?;
            }
            Ok(())
        }
        Command::Fit { data, materials, geometry, radius, radius2, grid, set, out, json } => {
            fit_command(&data, &materials, geometry, radius, radius2, grid, &set, out.as_deref(), json)
        }
        Command::Reproduce { out, quick, without_monte_carlo, chapters } => {
            reproduce(&out, quick, !without_monte_carlo, &chapters)
        }
    }
}

#[allow(clippy::too_many_arguments)]
fn fit_command(
    data: &Path,
    materials: &[String],
    geometry: Geometry,
    radius: f64,
    radius2: Option<f64>,
    grid: usize,
    sets: &[String],
    out: Option<&Path>,
    json: bool,
) -> Result<()> {
    use crate::physics::experiments::Bounded;
    use crate::physics::material::Material;
    let measurements = crate::measurements::load(data)?;
    let material = |name: &str| {
        Material::named(name).cloned().with_context(|| {
            let names: Vec<&str> = crate::physics::material::materials().iter().map(|m| m.name.as_str()).collect();
            format!("unknown material '{name}' (Table 2.2: {})", names.join(", "))
        })
    };
    let projectile = material(&materials[0])?;
    let target = material(materials.get(1).unwrap_or(&materials[0]))?;
    let mut preset = Preset {
        title: "fit".into(),
        description: String::new(),
        scene: scene::SceneParams::Fit(scene::collisions::fit::Params {
            data: measurements.clone(),
            projectile,
            target,
            wall: geometry == Geometry::Wall,
            ..Default::default()
        }),
        sensitivity: None,
    };
    let mut overrides = vec![
        format!("radius_1={radius}"),
        format!("radius_2={}", radius2.unwrap_or(radius)),
        format!("n_gamma={grid}"),
        format!("n_t_vis={grid}"),
        format!("n_y={grid}"),
    ];
    overrides.extend(sets.iter().cloned());
    apply_sets(&mut preset, &overrides)?;
    preset.scene.validate()?;
    let scene::SceneParams::Fit(params) = &preset.scene else { bail!("internal: not a fit scene") };
    let progress = Progress::default();
    let fit = scene::collisions::fit::run_fit(params, &measurements, &progress)?;
    let describe = |b: &Bounded, best: f64| match *b {
        Bounded::Value { best, plus, minus } => {
            serde_json::json!({"best": best, "low": best - minus, "high": best + plus, "kind": "value"})
        }
        Bounded::Above(x) => serde_json::json!({"best": best, "low": x, "high": null, "kind": "lower limit"}),
        Bounded::Below(x) => serde_json::json!({"best": best, "low": null, "high": x, "kind": "upper limit"}),
        Bounded::Fixed(x) => serde_json::json!({"best": x, "low": null, "high": null, "kind": "held fixed"}),
        Bounded::Undetermined { best } => {
            serde_json::json!({"best": best, "low": null, "high": null, "kind": "undetermined"})
        }
    };
    let warning = fit.warning();
    if let Some(w) = &warning {
        tell(format_args!("warning: {w}"));
    }
    let result = serde_json::json!({
        "gamma": describe(&fit.ranges[0], fit.best[0]),
        "t_vis": describe(&fit.ranges[1], fit.best[1]),
        "yield_strength": describe(&fit.ranges[2], fit.best[2]),
        "chi2": fit.chi2_min,
        "collisions": fit.collisions,
        "points": measurements.len(),
        "warning": warning,
        "units": {"gamma": "J m^-2", "t_vis": "s", "yield_strength": "Pa"},
    });
    if let Some(dir) = out {
        let output = scene::collisions::fit::output(params, &measurements, &fit)?;
        write_outputs(&output, Some(&preset), dir)?;
    }
    if json { say(serde_json::to_string(&result)?) } else { say(serde_json::to_string_pretty(&result)?) }
}

fn reproduce(dir: &Path, quick: bool, with_monte_carlo: bool, chapters: &[u8]) -> Result<()> {
    let wanted = |chapter: u8| chapters.is_empty() || chapters.contains(&chapter);
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create folder {}", dir.display()))?;
    let mut checks = Vec::new();
    if wanted(2) {
        checks.extend(crate::reproduce::chapter2()?);
    }
    if wanted(3) {
        checks.extend(crate::reproduce::chapter3());
    }
    if wanted(4) {
        checks.extend(crate::reproduce::chapter4());
    }
    if wanted(5) {
        checks.extend(crate::reproduce::chapter5()?);
    }
    if wanted(6) {
        checks.extend(crate::reproduce::chapter6()?);
    }
    let monte_carlo = if with_monte_carlo && (wanted(4) || wanted(5)) {
        crate::reproduce::monte_carlo(quick)?
    } else {
        crate::reproduce::MonteCarlo { checks: Vec::new(), figures: Vec::new() }
    };
    checks.extend(monte_carlo.checks);
    let md = crate::reproduce::markdown(&checks);
    write_atomically(&dir.join("reproduce.md"), md.as_bytes())?;
    write_atomically(&dir.join("reproduce.csv"), &crate::reproduce::csv(&checks)?)?;
    // The presets that draw each chapter's figures.
    let figures: [(u8, &[&str]); 5] = [
        (2, &["ice-bounce-8ms", "ice-stick-2ms", "restitution-ice", "experiments-fig-2-11", "material-parameters"]),
        (
            3,
            &[
                "rolling-contact-psl",
                "rolling-psl-glass-force",
                "rolling-silica-force",
                "rolling-ding-critical",
                "rolling-psl-aluminium-rocking",
            ],
        ),
        (6, &["debris-fig-6-1-top", "debris-fig-6-1-bottom", "debris-fig-6-2", "debris-fig-6-3"]),
        (
            4,
            &[
                "disk-fig-4-1",
                "disk-fig-4-2-compact",
                "disk-fig-4-2-porous",
                "disk-fig-4-5",
                "disk-fig-4-7",
                "disk-fig-4-8",
                "disk-fig-4-13",
                "disk-fig-4-13-erosion",
            ],
        ),
        (
            5,
            &[
                "batch-fig-5-1",
                "batch-fig-5-3",
                "batch-fig-5-4",
                "batch-fig-5-5",
                "batch-fig-5-6",
                "batch-fig-5-7",
                "batch-fig-5-8-extended",
                "batch-fig-5-8-weak",
                "batch-fig-5-9",
                "batch-fig-5-10",
                "batch-fig-5-11",
                "batch-fig-5-12",
                "batch-fig-5-13",
                "batch-fig-5-14",
                "batch-fig-5-15",
            ],
        ),
    ];
    for name in figures.iter().filter(|(c, _)| wanted(*c)).flat_map(|(_, names)| names.iter()) {
        let p = resolve(name)?;
        let out = scene::compute(&p.scene, &Progress::default())?;
        write_outputs(&out, Some(&p), &dir.join(name))?;
    }
    for (name, out) in &monte_carlo.figures {
        write_outputs(out, None, &dir.join(name))?;
    }
    let failures = checks.iter().filter(|c| c.fails()).count();
    // A reader that went away (`| head`) must not hide a failed comparison.
    match std::io::stdout().lock().write_all(md.as_bytes()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe && failures > 0 => {}
        other => other?,
    }
    if failures > 0 {
        bail!("{failures} published numbers are not reproduced");
    }
    Ok(())
}
