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
    fn plan(&self) -> Result<(Plan, Columns)> {
        let vary = self.vary.iter().map(|v| Vary::parse(v)).collect::<Result<Vec<_>, _>>()?;
        let plan = Plan::new(self.preset.scene.clone(), vary)?;
        let columns = Columns::new(self.scalars.clone(), self.units.clone(), &plan.base);
        Ok((plan, columns))
    }

    fn read(dir: &Path) -> Result<SweepFile> {
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

/// Runs `preset` over `vary` (shard `shard`) into `out`, resuming from rows
/// already there; `report` hears each finished point (done, of total).
pub fn run(
    preset: Preset,
    vary: &[String],
    scalars: &[String],
    shard: Shard,
    out: &Path,
    report: &(dyn Fn(usize, usize) + Sync),
) -> Result<Summary> {
    let parsed = vary.iter().map(|v| Vary::parse(v)).collect::<Result<Vec<_>, _>>()?;
    let plan = Plan::new(preset.scene.clone(), parsed)?;
    let progress = Progress::default();
    let columns = Columns::of(&plan, scalars, &progress)?;
    let mut file = SweepFile {
        preset,
        vary: plan.vary.iter().map(Vary::text).collect(),
        scalars: columns.keys.clone(),
        units: columns.units.clone(),
        shard: format!("{}/{}", shard.k, shard.n),
        program: crate::provenance::program(),
    };
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
