//! A sweep's folder on disk, for the command line: `sweep.csv` (the table of
//! the points this run owns, in point order), `sweep.ron` (the plan, so the
//! folder reopens and merges without recomputing), `sweep.partial.csv`
//! (rows appended as they finish, so a rerun resumes) and the figure
//! (`sweep.png`, `sweep.svg`) once the table is complete.

use crate::figure::{self, Axis, Figure, Series, Style};
use crate::files::write_atomically;
use crate::preset::Preset;
use crate::scene::Progress;
use crate::sweep::{self, Columns, Plan, Row, Shard, Vary};
use anyhow::{Context, Result, bail};
use serde::{Deserialize, Serialize};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// What `sweep.ron` records: enough to rebuild the plan and its columns.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFile {
    /// The preset every point starts from (with `--set` applied).
    pub preset: Preset,
    /// The varied parameters, as `NAME=lin|log:FROM:TO:N`.
    pub vary: Vec<String>,
    /// Scalar keys of the table.
    pub scalars: Vec<String>,
    /// Their units.
    pub units: Vec<String>,
    /// This folder's shard, `K/N`.
    pub shard: String,
    /// The build that computed the rows (`grainscope --version`); several,
    /// separated by "; ", where a run was resumed or shards merged across
    /// builds. Empty in folders written before builds were recorded.
    #[serde(default)]
    pub program: String,
    /// Parameters tied to another's value, as `TIED=SOURCE`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub tie: Vec<String>,
    /// The sample design of a global sensitivity analysis, whose points the
    /// rows are (instead of the grid of `vary`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub design: Option<crate::global_sensitivity::Design>,
}

/// `earlier` and `now` as one record of builds: `now` alone where they agree.
fn builds(earlier: &str, now: &str) -> String {
    let mut all: Vec<&str> = earlier.split("; ").filter(|b| !b.is_empty()).collect();
    for b in now.split("; ").filter(|b| !b.is_empty()) {
        if !all.contains(&b) {
            all.push(b);
        }
    }
    all.join("; ")
}

impl SweepFile {
    /// The record of a sweep of `preset` over `vary` (or the points of
    /// `design`) with `tie`, shard `shard`, by this build; its scalars are
    /// filled in when the columns are known.
    fn new(
        preset: Preset,
        vary: Vec<String>,
        tie: &[String],
        design: Option<crate::global_sensitivity::Design>,
        shard: Shard,
    ) -> SweepFile {
        SweepFile {
            preset,
            vary,
            scalars: Vec::new(),
            units: Vec::new(),
            shard: format!("{}/{}", shard.k, shard.n),
            program: crate::provenance::program(),
            tie: tie.to_vec(),
            design,
        }
    }

    /// The plan the file describes, and its columns.
    pub fn plan(&self) -> Result<(Plan, Columns)> {
        let ties = self.tie.iter().map(|t| sweep::parse_tie(t)).collect::<Result<Vec<_>, _>>()?;
        let plan = match &self.design {
            Some(design) => Plan::of_points(self.preset.scene.clone(), design.vary(), design.points()?)?,
            None => {
                let vary = self.vary.iter().map(|v| Vary::parse(v)).collect::<Result<Vec<_>, _>>()?;
                Plan::new(self.preset.scene.clone(), vary)?
            }
        };
        let plan = plan.with_ties(ties)?;
        let columns = Columns::new(self.scalars.clone(), self.units.clone(), &plan.base);
        Ok((plan, columns))
    }

    /// Reads `sweep.ron` of folder `dir`.
    pub fn read(dir: &Path) -> Result<SweepFile> {
        let path = dir.join("sweep.ron");
        let text = std::fs::read_to_string(&path).with_context(|| format!("{} is no sweep folder", dir.display()))?;
        ron::from_str(&text).with_context(|| format!("{} is malformed", path.display()))
    }

    fn bytes(&self) -> Result<Vec<u8>> {
        Ok(ron::ser::to_string_pretty(self, ron::ser::PrettyConfig::default())?.into_bytes())
    }
}

/// What a sweep run did.
#[derive(Debug)]
pub struct Summary {
    /// Points of this shard.
    pub points: usize,
    /// Points already in the folder (resumed).
    pub reused: usize,
    /// Points that failed (their rows say why).
    pub failed: usize,
    /// Files written.
    pub files: Vec<PathBuf>,
}

/// Runs `preset` over `vary` with `tie` (`TIED=SOURCE`, none for a plain
/// grid; shard `shard`) into `out`, resuming from rows already there;
/// `report` hears each finished point (done, of total).
pub fn run(
    preset: Preset,
    vary: &[String],
    tie: &[String],
    scalars: &[String],
    shard: Shard,
    out: &Path,
    report: &(dyn Fn(usize, usize) + Sync),
) -> Result<Summary> {
    // Recorded in canonical form.
    let vary = vary.iter().map(|v| Vary::parse(v).map(|v| v.text())).collect::<Result<Vec<_>, _>>()?;
    run_plan(SweepFile::new(preset, vary, tie, None, shard), scalars, shard, out, report)
}

/// Runs the points of the sample design `design` over `preset` (shard
/// `shard`) into `out`, as [`run`] does a grid: resumable, shardable and
/// mergeable alike.
pub fn run_design(
    preset: Preset,
    design: crate::global_sensitivity::Design,
    tie: &[String],
    scalars: &[String],
    shard: Shard,
    out: &Path,
    report: &(dyn Fn(usize, usize) + Sync),
) -> Result<Summary> {
    run_plan(SweepFile::new(preset, Vec::new(), tie, Some(design), shard), scalars, shard, out, report)
}

/// Runs the points of `shard` of the plan `file` describes into `out`.
fn run_plan(
    mut file: SweepFile,
    scalars: &[String],
    shard: Shard,
    out: &Path,
    report: &(dyn Fn(usize, usize) + Sync),
) -> Result<Summary> {
    let (plan, _) = file.plan()?;
    let progress = Progress::default();
    let columns = Columns::of(&plan, scalars, &progress)?;
    file.scalars = columns.keys.clone();
    file.units = columns.units.clone();
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let ron_path = out.join("sweep.ron");
    if ron_path.exists() {
        let before = SweepFile::read(out)?;
        if (SweepFile { program: file.program.clone(), ..before.clone() }) != file {
            bail!(
                "{} holds another sweep (other preset, ranges, scalars or shard); choose another --out",
                out.display()
            );
        }
        // Rows resumed from another build: the folder names both.
        file.program = builds(&before.program, &file.program);
    }
    write_atomically(&ron_path, &file.bytes()?)?;
    // Rows already done: the finished table, and rows appended by a run cut short.
    let mut done: Vec<Row> = Vec::new();
    for name in ["sweep.csv", "sweep.partial.csv"] {
        if let Ok(text) = std::fs::read_to_string(out.join(name)) {
            done.extend(
                sweep::read_rows(&text, &plan, &columns).with_context(|| format!("{}", out.join(name).display()))?,
            );
        }
    }
    done.sort_by_key(|r| r.index);
    done.dedup_by_key(|r| r.index);
    done.retain(|r| shard.owns(r.index));
    let mine: Vec<usize> = (0..plan.len()).filter(|&i| shard.owns(i)).collect();
    let todo: Vec<usize> =
        mine.iter().copied().filter(|i| done.binary_search_by_key(i, |r| r.index).is_err()).collect();
    let reused = mine.len() - todo.len();
    // Append each finished row at once, so that a crash loses nothing done.
    let partial_path = out.join("sweep.partial.csv");
    let mut partial = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(&partial_path)
        .with_context(|| format!("cannot write {}", partial_path.display()))?;
    if partial.metadata().map(|m| m.len() == 0).unwrap_or(true) {
        writeln!(partial, "{}", sweep::header(&plan, &columns))?;
    }
    let partial = Mutex::new(partial);
    let count = std::sync::atomic::AtomicUsize::new(reused);
    let total = mine.len();
    let append = |row: &Row| {
        if let Ok(mut f) = partial.lock() {
            let _ = writeln!(f, "{}", sweep::line(row, &columns));
            let _ = f.flush();
        }
        report(count.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1, total);
    };
    let fresh = sweep::run(&plan, &columns, &todo, &progress, &append)?;
    done.extend(fresh);
    done.sort_by_key(|r| r.index);
    let failed = done.iter().filter(|r| r.error.is_some()).count();
    let files = finish(&plan, &columns, &done, out, shard == Shard::ALL)?;
    // Closed before it is removed (a WebAssembly build's file closes nothing).
    #[allow(clippy::drop_non_drop)]
    drop(partial);
    let _ = std::fs::remove_file(&partial_path);
    Ok(Summary { points: total, reused, failed, files })
}

/// The rows of a finished, whole sweep folder (one run unsharded, or merged).
pub fn read_whole(dir: &Path) -> Result<(SweepFile, Plan, Columns, Vec<Row>)> {
    let file = SweepFile::read(dir)?;
    let (plan, columns) = file.plan()?;
    let path = dir.join("sweep.csv");
    let text = std::fs::read_to_string(&path).with_context(|| format!("{} has no sweep.csv", dir.display()))?;
    let rows = sweep::read_rows(&text, &plan, &columns).with_context(|| format!("{}", path.display()))?;
    if rows.len() != plan.len() {
        bail!(
            "{} holds {} of the {} points: finish the run or merge its shards first",
            dir.display(),
            rows.len(),
            plan.len()
        );
    }
    Ok((file, plan, columns, rows))
}

/// A global sensitivity analysis of a finished design folder.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Analysis {
    /// The program that analysed it.
    pub program: String,
    /// The builds that computed the runs.
    pub computed_by: String,
    /// The preset's title.
    pub preset: String,
    /// The output analysed and its unit.
    pub output: String,
    /// Its SI unit (empty when its logarithm is analysed).
    pub unit: String,
    /// The natural logarithm of the output is analysed (its effects are
    /// relative changes).
    pub log_output: bool,
    /// The design.
    pub design: crate::global_sensitivity::Design,
    /// Parameters tied to others (`TIED=SOURCE`).
    pub tie: Vec<String>,
    /// Runs in the design.
    pub runs: usize,
    /// Runs whose output is undefined or whose computation failed: left out
    /// by [`UNDEFINED_RULE`].
    pub undefined: usize,
    /// Runs whose output is only a bound: they enter at the bound
    /// ([`BOUND_RULE`]).
    pub bounded: usize,
    /// Morris's measures, per factor.
    pub morris: Option<Vec<crate::global_sensitivity::MorrisIndex>>,
    /// Sobol' indices.
    pub sobol: Option<crate::global_sensitivity::SobolResult>,
}

/// How undefined outputs are handled (stated in every analysis).
pub const UNDEFINED_RULE: &str = "an undefined output (or a failed run) is left out: an elementary effect that needs it \
     is dropped; a Sobol' base sample with one among its runs is dropped whole";

/// How bounds are handled (stated in every analysis).
pub const BOUND_RULE: &str =
    "an output known only as a bound (\"> 10⁴ m/s\") enters at the bound, a conservative value, and is counted";

use crate::global_sensitivity::RESAMPLES;

/// Analyses the finished design folder `dir` (one run unsharded, or its
/// shards merged): the design's outputs by its method, into
/// `indices.csv` (and `second_order.csv`), `sensitivity.json` and a
/// figure (PNG, SVG). Returns the analysis and the files written.
pub fn analyse(dir: &Path, log_output: bool) -> Result<(Analysis, Vec<PathBuf>)> {
    use crate::global_sensitivity::{self as gsa, Method};
    let (file, _plan, columns, rows) = read_whole(dir)?;
    let Some(design) = file.design.clone() else {
        bail!("{} holds a grid sweep, not a sensitivity design", dir.display())
    };
    let (output, unit) = (columns.keys[0].clone(), columns.units[0].clone());
    let (mut undefined, mut bounded) = (0, 0);
    let y: Vec<f64> = rows
        .iter()
        .map(|r| match (&r.error, r.scalars[0]) {
            (None, Some(v)) if v.is_finite() && (v > 0.0 || !log_output) => {
                bounded += usize::from(r.status[0].starts_with("above"));
                if log_output { v.ln() } else { v }
            }
            _ => {
                undefined += 1;
                f64::NAN
            }
        })
        .collect();
    let d = design.factors.len();
    let unit_points = design.unit_points()?;
    let (morris, sobol) = match design.method {
        Method::Morris { .. } => (Some(gsa::morris(&unit_points, &y, d, RESAMPLES, design.seed)), None),
        Method::Sobol { second_order, .. } => (None, Some(gsa::sobol(&y, d, second_order, RESAMPLES, design.seed))),
        Method::Given { .. } => {
            bail!("{} holds points given by a table: there is no estimator to apply", dir.display())
        }
    };
    let analysis = Analysis {
        program: crate::provenance::program(),
        computed_by: file.program.clone(),
        preset: file.preset.title.clone(),
        output: if log_output { format!("ln {output}") } else { output },
        unit: if log_output { String::new() } else { unit },
        log_output,
        design,
        tie: file.tie.clone(),
        runs: rows.len(),
        undefined,
        bounded,
        morris,
        sobol,
    };
    let mut files = Vec::new();
    let mut write = |name: &str, bytes: &[u8]| -> Result<()> {
        let path = dir.join(name);
        write_atomically(&path, bytes)?;
        files.push(path);
        Ok(())
    };
    write("indices.csv", indices_csv(&analysis).as_bytes())?;
    if let Some(text) = second_order_csv(&analysis) {
        write("second_order.csv", text.as_bytes())?;
    }
    let json = serde_json::json!({
        "analysis": analysis,
        "rules": { "undefined": UNDEFINED_RULE, "bound": BOUND_RULE },
        "preset": file.preset,
    });
    write("sensitivity.json", serde_json::to_string_pretty(&json)?.as_bytes())?;
    let fig = analysis_figure(&analysis);
    for ext in ["png", "svg"] {
        let bytes = crate::provenance::figure_bytes(&fig, ext, figure::EXPORT_SIZE, None)?;
        write(&format!("sensitivity.{ext}"), &bytes)?;
    }
    Ok((analysis, files))
}

/// The indices as a table, a row per factor (SALib's `to_df()` columns).
pub fn indices_csv(a: &Analysis) -> String {
    let mut s = String::new();
    let u = |k: &str| if a.unit.is_empty() { k.to_string() } else { format!("{k} [{}]", a.unit) };
    if let Some(m) = &a.morris {
        s += &format!("parameter,{},{},{},{},effects,dropped\n", u("mu"), u("mu_star"), u("sigma"), u("mu_star_conf"));
        for (f, i) in a.design.factors.iter().zip(m) {
            s += &format!(
                "{},{},{},{},{},{},{}\n",
                f.key, i.mu, i.mu_star, i.sigma, i.mu_star_conf, i.effects, i.dropped
            );
        }
    }
    if let Some(r) = &a.sobol {
        s += "parameter,S1,S1_conf,ST,ST_conf\n";
        for (f, i) in a.design.factors.iter().zip(&r.indices) {
            s += &format!("{},{},{},{},{}\n", f.key, i.first, i.first_conf, i.total, i.total_conf);
        }
    }
    s
}

/// Second-order indices, a row per pair, when the design has them.
fn second_order_csv(a: &Analysis) -> Option<String> {
    let (s2, conf) = a.sobol.as_ref()?.second.as_ref()?;
    let mut s = "parameter 1,parameter 2,S2,S2_conf\n".to_string();
    let f = &a.design.factors;
    for j in 0..f.len() {
        for k in j + 1..f.len() {
            s += &format!("{},{},{},{}\n", f[j].key, f[k].key, s2[j][k], conf[j][k]);
        }
    }
    Some(s)
}

/// Morris: σ against μ* per factor. Sobol': S1 (filled) and ST (open) per
/// factor, at its number along the axis, with their intervals.
pub fn analysis_figure(a: &Analysis) -> Figure {
    use crate::figure::{Fill, Shape};
    let names: Vec<String> = a.design.factors.iter().enumerate().map(|(i, f)| format!("{} {}", i + 1, f.key)).collect();
    if let Some(m) = &a.morris {
        let mut fig = Figure::new(
            "sensitivity",
            &format!("Morris: σ against μ* of {} ({} trajectories)", a.output, a.runs / (names.len() + 1)),
            Axis::linear("μ*", &crate::units::pretty(&a.unit)),
            Axis::linear("σ", &crate::units::pretty(&a.unit)),
        );
        for (k, (i, name)) in m.iter().zip(&names).enumerate() {
            if i.mu_star.is_finite() && i.sigma.is_finite() {
                fig = fig.with(Series::new(
                    name,
                    vec![[i.mu_star, i.sigma]],
                    Style::Symbol(Shape::Circle, Fill::Filled),
                    k,
                ));
                let lo = (i.mu_star - i.mu_star_conf).max(0.0);
                fig = fig.with(Series::new(
                    "",
                    vec![[lo, i.sigma], [i.mu_star + i.mu_star_conf, i.sigma]],
                    Style::Line,
                    k,
                ));
            }
        }
        return fig;
    }
    let mut fig = Figure::new(
        "sensitivity",
        &format!("Sobol': S1 (filled) and ST (open) of {} ({} runs)", a.output, a.runs),
        Axis::linear("factor", ""),
        Axis::linear("index", ""),
    );
    if let Some(r) = &a.sobol {
        for (k, (i, name)) in r.indices.iter().zip(&names).enumerate() {
            let x = (k + 1) as f64;
            for (dx, v, c, fill, label) in [
                (-0.12, i.first, i.first_conf, Fill::Filled, name.as_str()),
                (0.12, i.total, i.total_conf, Fill::Open, ""),
            ] {
                if v.is_finite() {
                    fig = fig.with(Series::new(label, vec![[x + dx, v]], Style::Symbol(Shape::Circle, fill), k));
                    if c.is_finite() {
                        fig = fig.with(Series::new("", vec![[x + dx, v - c], [x + dx, v + c]], Style::Line, k));
                    }
                }
            }
        }
    }
    fig
}

/// Writes the table (and, for a whole plan, its figure).
fn finish(plan: &Plan, columns: &Columns, rows: &[Row], out: &Path, whole: bool) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let csv = out.join("sweep.csv");
    write_atomically(&csv, sweep::table(plan, columns, rows).as_bytes())?;
    files.push(csv);
    if whole && let Some(fig) = figure_of(plan, columns, rows) {
        for ext in ["png", "svg"] {
            let path = out.join(format!("sweep.{ext}"));
            let bytes = crate::provenance::figure_bytes(&fig, ext, figure::EXPORT_SIZE, None)?;
            write_atomically(&path, &bytes)?;
            files.push(path);
        }
    }
    Ok(files)
}

/// Merges shard folders into `out`: exactly the files of the unsharded run.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<Vec<PathBuf>> {
    let Some(first) = dirs.first() else { bail!("no shard folders given") };
    let mut head = SweepFile::read(first)?;
    let (plan, columns) = head.plan()?;
    let mut rows: Vec<Row> = Vec::new();
    let mut program = String::new();
    for dir in dirs {
        let f = SweepFile::read(dir)?;
        let same = SweepFile { shard: head.shard.clone(), program: head.program.clone(), ..f.clone() } == head;
        if !same {
            bail!("{} is a shard of another sweep than {}", dir.display(), first.display());
        }
        program = builds(&program, &f.program);
        let path = dir.join("sweep.csv");
        let text = std::fs::read_to_string(&path)
            .with_context(|| format!("{} has no sweep.csv: is that shard finished?", dir.display()))?;
        rows.extend(sweep::read_rows(&text, &plan, &columns).with_context(|| format!("{}", path.display()))?);
    }
    rows.sort_by_key(|r| r.index);
    rows.dedup_by_key(|r| r.index);
    let missing: Vec<usize> = (0..plan.len()).filter(|i| rows.binary_search_by_key(i, |r| r.index).is_err()).collect();
    if !missing.is_empty() {
        bail!(
            "{} of {} points are in no shard (first: {}); run the missing shards first",
            missing.len(),
            plan.len(),
            missing[0]
        );
    }
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    head.program = program;
    let whole = SweepFile { shard: "1/1".into(), ..head };
    write_atomically(&out.join("sweep.ron"), &whole.bytes()?)?;
    let mut files = vec![out.join("sweep.ron")];
    files.extend(finish(&plan, &columns, &rows, out, true)?);
    Ok(files)
}

/// The first scalar against the first varied parameter; with a second varied
/// parameter, one line per value of it (up to 12), or a map over both with
/// more values. None without a scalar or with more than two parameters.
fn figure_of(plan: &Plan, columns: &Columns, rows: &[Row]) -> Option<Figure> {
    if plan.is_design() {
        return None;
    }
    if plan.vary.len() == 2 && plan.vary[1].n > 12 {
        return map_of(plan, columns, rows);
    }
    let key = columns.keys.first()?;
    let axis = |v: &Vary, unit: &str| if v.log_axis() { Axis::log(&v.key, unit) } else { Axis::linear(&v.key, unit) };
    let y_log = rows.iter().filter_map(|r| r.scalars[0]).all(|y| y > 0.0);
    let y = if y_log { Axis::log(key, &columns.units[0]) } else { Axis::linear(key, &columns.units[0]) };
    let mut fig =
        Figure::new("sweep", &format!("{key} against {}", plan.vary[0].key), axis(&plan.vary[0], &plan.units[0]), y);
    let second: Vec<f64> = plan.vary.get(1).map(Vary::values).unwrap_or_else(|| vec![f64::NAN]);
    if second.len() > 12 || plan.vary.len() > 2 {
        return None;
    }
    for (k, s) in second.iter().enumerate() {
        let mine = rows.iter().filter(|r| plan.vary.len() == 1 || r.values[1] == *s);
        // A point without the scalar is a gap, not a zero: the line breaks there.
        let mut pieces: Vec<Vec<[f64; 2]>> = vec![Vec::new()];
        for r in mine {
            match r.scalars[0] {
                Some(y) => pieces.last_mut().map(|p| p.push([r.values[0], y])).unwrap_or(()),
                None if pieces.last().is_some_and(|p| !p.is_empty()) => pieces.push(Vec::new()),
                None => {}
            }
        }
        let name = match plan.vary.get(1) {
            Some(v) => format!("{} = {} {}", v.key, figure::tick_label(*s), plan.units[1]).trim_end().to_string(),
            None => key.clone(),
        };
        for (j, piece) in pieces.into_iter().filter(|p| !p.is_empty()).enumerate() {
            let style = if piece.len() == 1 { Style::Points } else { Style::Line };
            let label = if j == 0 { name.clone() } else { String::new() };
            fig = fig.with(Series::new(&label, piece, style, k));
        }
    }
    Some(fig)
}

/// The first scalar over two varied parameters as a map: the second (the
/// faster) across, the first up; undefined points blank.
fn map_of(plan: &Plan, columns: &Columns, rows: &[Row]) -> Option<Figure> {
    let key = columns.keys.first()?;
    let (vy, vx) = (&plan.vary[0], &plan.vary[1]);
    let axis = |v: &Vary, unit: &str| if v.log_axis() { Axis::log(&v.key, unit) } else { Axis::linear(&v.key, unit) };
    let zs: Vec<Option<f64>> = rows.iter().map(|r| r.scalars[0]).collect();
    let (xs, ys) = (vx.values(), vy.values());
    if zs.len() != xs.len() * ys.len() {
        return None;
    }
    let fig = Figure::new(
        "sweep",
        &format!("{key} over {} and {}", vx.key, vy.key),
        axis(vx, &plan.units[1]),
        axis(vy, &plan.units[0]),
    );
    let fig = crate::sensitivity::map_figure(fig, (&xs, &ys), &zs, (key, key, &columns.units[0]));
    Some(fig)
}
