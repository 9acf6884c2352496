//! `grainscope._native`: the models of the `grainscope` crate for the Python
//! package of the same name. It computes in-process (no command line, no
//! JSON), releases the GIL while it computes, stops at Ctrl-C, and turns
//! every refusal into a Python exception (a mistyped name: `KeyError` with
//! the close matches; a bad value or file: `ValueError`), never a crash.
//! The Python half (`grainscope/__init__.py`) makes numpy arrays, tables and
//! notebook pictures of what this returns.

use grainscope::preset::{self, Preset, PresetError};
use grainscope::scene::controls::{DefaultValue, ParamError, did_you_mean};
use grainscope::scene::schema::SpecKind;
use grainscope::scene::{self, Progress, SCENES, SceneError, SceneOutput, SceneParams};
use grainscope::sweep::{self, Columns, Plan, Shard, SweepError, Vary};
use pyo3::exceptions::{PyKeyError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use std::path::PathBuf;
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

/// How often a computation looks for Ctrl-C.
const SIGNAL_EVERY: Duration = Duration::from_millis(50);

/// A refused parameter: `KeyError` for a name the scene does not have,
/// `ValueError` for a value out of range; the message is the command line's.
fn param_error(e: &ParamError) -> PyErr {
    match e {
        ParamError::UnknownKey { .. } => PyKeyError::new_err(e.to_string()),
        _ => PyValueError::new_err(e.to_string()),
    }
}

/// A scene that failed: its parameter errors as [`param_error`], the model's
/// refusals as `ValueError`.
fn scene_error(e: &SceneError) -> PyErr {
    match e {
        SceneError::Param(p) => param_error(p),
        SceneError::Cancelled => PyRuntimeError::new_err("cancelled"),
        SceneError::Physics(_) => PyValueError::new_err(e.to_string()),
    }
}

/// A preset that cannot be read: `KeyError` for a name that is neither a
/// file nor a shipped preset, `ValueError` for a malformed one.
fn preset_error(e: &PresetError) -> PyErr {
    match e {
        PresetError::Read { cause, .. } if cause.kind() == std::io::ErrorKind::NotFound => {
            PyKeyError::new_err(e.to_string())
        }
        _ => PyValueError::new_err(e.to_string()),
    }
}

/// A sweep that cannot be planned.
fn sweep_error(e: &SweepError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// Runs `work` on its own thread with the GIL released, looking for Ctrl-C
/// (and any other pending signal) every [`SIGNAL_EVERY`]: a signal cancels
/// the work through `progress` and raises its exception (KeyboardInterrupt)
/// once the work has stopped. A panic in the work is a `RuntimeError`.
fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    progress: &Progress,
    work: impl FnOnce(&Progress) -> T + Send + 'static,
) -> PyResult<T> {
    let (tx, rx) = mpsc::channel();
    let mine = progress.clone();
    let worker = std::thread::Builder::new()
        .name("grainscope".into())
        .spawn(move || {
            let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| work(&mine)));
            let _ = tx.send(outcome);
        })
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start the computation: {e}")))?;
    let finished = |outcome: std::thread::Result<T>| {
        outcome.map_err(|panic| {
            let why = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "no message".into());
            PyRuntimeError::new_err(format!("the computation failed: {why}"))
        })
    };
    let mut rx = rx;
    loop {
        // The receiver goes with the wait and comes back: only what is Send
        // crosses to where the GIL is not held.
        let (got, back) = py.detach(move || (rx.recv_timeout(SIGNAL_EVERY), rx));
        rx = back;
        match got {
            Ok(outcome) => {
                let _ = worker.join();
                return finished(outcome);
            }
            Err(RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err("the computation stopped without a result"));
            }
            Err(RecvTimeoutError::Timeout) => {
                if let Err(signal) = py.check_signals() {
                    progress.cancel();
                    py.detach(move || {
                        let _ = rx.recv();
                        let _ = worker.join();
                    });
                    return Err(signal);
                }
            }
        }
    }
}

/// The preset a call names: a shipped preset or a file (`preset`), or a
/// scene's defaults (`scene`), with `sets` (key, value as text, SI) applied.
fn preset_of(preset: Option<&str>, scene: Option<&str>, sets: &[(String, String)]) -> PyResult<Preset> {
    let mut p = match (preset, scene) {
        (Some(_), Some(_)) => return Err(PyValueError::new_err("give a preset or a scene, not both")),
        (Some(name), None) => preset::resolve(name).map_err(|e| preset_error(&e))?,
        (None, Some(id)) => {
            let scene = SceneParams::default_for(id).ok_or_else(|| {
                let ids: Vec<&str> = SCENES.iter().map(|s| s.id).collect();
                PyKeyError::new_err(format!(
                    "unknown scene '{id}'{} (scenes: {})",
                    did_you_mean(id, &ids),
                    ids.join(", ")
                ))
            })?;
            Preset { title: scene.info().title.to_string(), description: String::new(), scene, sensitivity: None }
        }
        (None, None) => return Err(PyValueError::new_err("give a preset name or file, or scene=")),
    };
    for (key, value) in sets {
        p.scene.set(key, value).map_err(|e| param_error(&e))?;
    }
    Ok(p)
}

/// A preset from the RON text [`preset_ron`] made.
fn from_ron(text: &str) -> PyResult<Preset> {
    Preset::from_ron(text, "preset").map_err(|e| preset_error(&e))
}

/// The shipped presets: (name, scene id, title).
/// The build: "grainscope VERSION (commit …, DATE)", as every exported file names it.
#[pyfunction]
fn program() -> String {
    grainscope::provenance::program()
}

#[pyfunction]
fn presets() -> PyResult<Vec<(String, String, String)>> {
    preset::SHIPPED
        .iter()
        .map(|(file, text)| {
            let p = Preset::from_ron(text, file).map_err(|e| preset_error(&e))?;
            Ok((file.trim_end_matches(".ron").to_string(), p.scene.info().id.to_string(), p.title))
        })
        .collect()
}

/// One parameter of a scene, as `gs.scenes()` lists it.
#[derive(serde::Serialize)]
struct Parameter {
    name: &'static str,
    label: &'static str,
    kind: &'static str,
    unit: &'static str,
    default: serde_json::Value,
    min: Option<f64>,
    max: Option<f64>,
    log: bool,
    choices: Vec<&'static str>,
    meaning: &'static str,
    style_only: bool,
    numerical: bool,
}

/// One scene, as `gs.scenes()` lists it.
#[derive(serde::Serialize)]
struct SceneEntry {
    id: &'static str,
    title: &'static str,
    source: &'static str,
    heavy: bool,
    parameters: Vec<Parameter>,
}

/// Every scene with its documented parameters (units SI).
#[pyfunction]
fn scenes(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    let mut list = Vec::new();
    for info in SCENES {
        let Some(params) = SceneParams::default_for(info.id) else { continue };
        let parameters = params
            .specs()
            .iter()
            .map(|c| {
                let default = match c.default.as_ref().or(params.get(c.key).as_ref()) {
                    Some(DefaultValue::Number(v)) => serde_json::json!(v),
                    Some(DefaultValue::Count(v)) => serde_json::json!(v),
                    Some(DefaultValue::Toggle(on)) => serde_json::json!(on),
                    Some(DefaultValue::Text(t)) => serde_json::json!(t),
                    None => serde_json::Value::Null,
                };
                let (kind, min, max, log, choices) = match &c.kind {
                    SpecKind::Number { min, max, log, .. } => ("number", Some(*min), Some(*max), *log, vec![]),
                    SpecKind::Count { min, max } => ("count", Some(*min as f64), Some(*max as f64), false, vec![]),
                    SpecKind::Toggle => ("toggle", None, None, false, vec![]),
                    SpecKind::Material => ("material", None, None, false, vec![]),
                    SpecKind::Choice { options } => {
                        ("choice", None, None, false, options.iter().map(|(k, _)| *k).collect())
                    }
                };
                Parameter {
                    name: c.key,
                    label: c.label,
                    kind,
                    unit: c.si_unit,
                    default,
                    min,
                    max,
                    log,
                    choices,
                    meaning: c.doc,
                    style_only: c.style_only,
                    numerical: c.numerical,
                }
            })
            .collect();
        list.push(SceneEntry { id: info.id, title: info.title, source: info.source, heavy: info.heavy, parameters });
    }
    Ok(pythonize::pythonize(py, &list)?)
}

/// The RON text of the preset a call names (see [`preset_of`]): what a
/// result's `preset` is, and what a sweep sends to its workers.
#[pyfunction]
#[pyo3(signature = (preset=None, scene=None, sets=Vec::new()))]
fn preset_ron(preset: Option<&str>, scene: Option<&str>, sets: Vec<(String, String)>) -> PyResult<String> {
    preset_of(preset, scene, &sets)?.to_ron().map_err(|e| preset_error(&e))
}

/// The scene a call names (see [`preset_of`]).
#[pyfunction]
#[pyo3(signature = (preset=None, scene=None))]
fn scene_of(preset: Option<&str>, scene: Option<&str>) -> PyResult<&'static str> {
    Ok(preset_of(preset, scene, &[])?.scene.info().id)
}

/// A computed scene: its preset and output.
#[pyclass(frozen, module = "grainscope._native")]
struct Computed {
    preset: Preset,
    out: SceneOutput,
}

#[pymethods]
impl Computed {
    /// The scene's identifier.
    #[getter]
    fn scene(&self) -> &'static str {
        self.preset.scene.info().id
    }

    /// The preset's title.
    #[getter]
    fn title(&self) -> &str {
        &self.preset.title
    }

    /// The preset (RON) that reproduces this result.
    fn preset_ron(&self) -> PyResult<String> {
        self.preset.to_ron().map_err(|e| preset_error(&e))
    }

    /// The scalars as the command line's `run --json` prints them.
    fn scalars_json(&self) -> PyResult<String> {
        serde_json::to_string(&self.out.scalars_json(self.preset.scene.censored()))
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// The scalars: (key, label, value, unit), value in SI units.
    fn scalars(&self) -> Vec<(&'static str, &'static str, f64, &'static str)> {
        self.out.scalars.iter().map(|s| (s.key, s.label, s.value, s.unit)).collect()
    }

    /// The figures as they are exported (dicts of the figure's fields).
    fn figures<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(pythonize::pythonize(py, &self.preset.scene.exported_figures(&self.out))?)
    }

    /// Warnings the scene gave.
    fn warnings(&self) -> Vec<String> {
        self.out.warnings.clone()
    }

    /// Notes the scene gave.
    fn notes(&self) -> Vec<String> {
        self.out.notes.clone()
    }

    /// Figure `id` drawn as `ext` ("png" or "svg") at `size` pixels, with
    /// the preset embedded (the file reopens this state in the explorer).
    fn render<'py>(&self, py: Python<'py>, id: &str, ext: &str, size: (u32, u32)) -> PyResult<Bound<'py, PyBytes>> {
        if !matches!(ext, "png" | "svg") {
            return Err(PyValueError::new_err(format!("'{ext}': a figure is drawn as png or svg")));
        }
        if !(64..=8192).contains(&size.0) || !(64..=8192).contains(&size.1) {
            return Err(PyValueError::new_err(format!("size {size:?}: each side between 64 and 8192 pixels")));
        }
        let figures = self.preset.scene.exported_figures(&self.out);
        let fig = figures.iter().find(|f| f.id == id).ok_or_else(|| {
            let ids: Vec<&str> = figures.iter().map(|f| f.id.as_str()).collect();
            PyKeyError::new_err(format!("no figure '{id}'{} (figures: {})", did_you_mean(id, &ids), ids.join(", ")))
        })?;
        let stamp =
            grainscope::provenance::Stamp::of(&self.preset).map_err(|e| PyValueError::new_err(e.to_string()))?;
        let bytes = py
            .detach(|| grainscope::provenance::figure_bytes(fig, ext, size, Some(&stamp)))
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(PyBytes::new(py, &bytes))
    }

    /// Writes what the command line's `run --out DIR` writes; returns the paths.
    fn save(&self, py: Python<'_>, dir: PathBuf) -> PyResult<Vec<String>> {
        let files = py
            .detach(|| grainscope::export::write_outputs(&self.out, Some(&self.preset), &dir))
            .map_err(|e| PyValueError::new_err(format!("{e:#}")))?;
        Ok(files.iter().map(|p| p.display().to_string()).collect())
    }
}

/// Computes the preset a call names (see [`preset_of`]), GIL released,
/// Ctrl-C stops it.
#[pyfunction]
#[pyo3(signature = (preset=None, scene=None, sets=Vec::new()))]
fn run(py: Python<'_>, preset: Option<&str>, scene: Option<&str>, sets: Vec<(String, String)>) -> PyResult<Computed> {
    let preset = preset_of(preset, scene, &sets)?;
    let params = preset.scene.clone();
    let out = interruptible(py, &Progress::default(), move |progress| scene::compute(&params, progress))?
        .map_err(|e| scene_error(&e))?;
    Ok(Computed { preset, out })
}

/// The plan and columns of a sweep of `preset_ron` over `vary` (texts as
/// `--vary` takes them); a varied name the scene lacks is a `KeyError`.
fn plan_of(py: Python<'_>, preset_ron: &str, vary: &[String], scalars: &[String]) -> PyResult<(Plan, Columns)> {
    let plan = checked_plan(preset_ron, vary)?;
    let scalars = scalars.to_vec();
    let base = plan.clone();
    let columns = interruptible(py, &Progress::default(), move |progress| Columns::of(&base, &scalars, progress))?
        .map_err(|e| sweep_error(&e))?;
    Ok((plan, columns))
}

/// The plan of a sweep, checked without computing anything.
fn checked_plan(preset_ron: &str, vary: &[String]) -> PyResult<Plan> {
    let preset = from_ron(preset_ron)?;
    let parsed = vary.iter().map(|v| Vary::parse(v)).collect::<Result<Vec<_>, _>>().map_err(|e| sweep_error(&e))?;
    let known = preset.scene.keys();
    if let Some(v) = parsed.iter().find(|v| !known.contains(&v.key.as_str())) {
        return Err(param_error(&ParamError::unknown(&v.key, &known)));
    }
    Plan::new(preset.scene, parsed).map_err(|e| sweep_error(&e))
}

/// Checks a sweep's names and values (nothing computed): its number of points.
#[pyfunction]
fn sweep_points(preset_ron: &str, vary: Vec<String>) -> PyResult<usize> {
    Ok(checked_plan(preset_ron, &vary)?.len())
}

/// The table (the command line's `sweep.csv`) of shard `k` of `n` of a
/// sweep: the points k, k + n, … computed in parallel, GIL released.
#[pyfunction]
#[pyo3(signature = (preset_ron, vary, scalars, k=1, n=1))]
fn sweep_table(
    py: Python<'_>,
    preset_ron: &str,
    vary: Vec<String>,
    scalars: Vec<String>,
    k: usize,
    n: usize,
) -> PyResult<String> {
    let shard = shard_of(k, n)?;
    let (plan, columns) = plan_of(py, preset_ron, &vary, &scalars)?;
    let indices: Vec<usize> = (0..plan.len()).filter(|&i| shard.owns(i)).collect();
    let rows = interruptible(py, &Progress::default(), move |progress| {
        sweep::run(&plan, &columns, &indices, progress, &|_| {}).map(|rows| sweep::table(&plan, &columns, &rows))
    })?
    .map_err(|e| scene_error(&e))?;
    Ok(rows)
}

/// The whole table from the tables of shards (any order): exactly the table
/// of the unsharded sweep.
#[pyfunction]
fn merge_tables(
    py: Python<'_>,
    preset_ron: &str,
    vary: Vec<String>,
    scalars: Vec<String>,
    tables: Vec<String>,
) -> PyResult<String> {
    let (plan, columns) = plan_of(py, preset_ron, &vary, &scalars)?;
    let mut rows = Vec::new();
    for t in &tables {
        rows.extend(sweep::read_rows(t, &plan, &columns).map_err(|e| sweep_error(&e))?);
    }
    rows.sort_by_key(|r| r.index);
    rows.dedup_by_key(|r| r.index);
    if rows.len() != plan.len() {
        return Err(PyValueError::new_err(format!("the shards hold {} of {} points", rows.len(), plan.len())));
    }
    Ok(sweep::table(&plan, &columns, &rows))
}

/// The shard `k` of `n`, checked.
fn shard_of(k: usize, n: usize) -> PyResult<Shard> {
    if k == 0 || k > n {
        return Err(PyValueError::new_err(format!("shard {k}/{n}: expected 1 ≤ k ≤ n")));
    }
    Ok(Shard { k, n })
}

/// Runs a sweep (shard `k` of `n`) into folder `out` as the command line's
/// `sweep --shard K/N --out` does (resuming from the rows already there);
/// returns the table of the rows in the folder.
#[pyfunction]
#[pyo3(signature = (preset_ron, vary, scalars, out, k=1, n=1))]
fn sweep_folder(
    py: Python<'_>,
    preset_ron: &str,
    vary: Vec<String>,
    scalars: Vec<String>,
    out: PathBuf,
    k: usize,
    n: usize,
) -> PyResult<String> {
    let shard = shard_of(k, n)?;
    let preset = from_ron(preset_ron)?;
    // Names and values are checked first, with the errors of a sweep in memory.
    checked_plan(preset_ron, &vary)?;
    let folder = out.clone();
    interruptible(py, &Progress::default(), move |_| {
        grainscope::sweep_files::run(preset, &vary, &[], &scalars, shard, &folder, &|_, _| {})
    })?
    .map_err(|e| PyValueError::new_err(format!("{e:#}")))?;
    std::fs::read_to_string(out.join("sweep.csv"))
        .map_err(|e| PyValueError::new_err(format!("{}: {e}", out.join("sweep.csv").display())))
}

/// Runs a global sensitivity design into folder `out` as the command
/// line's `sensitivity --out` does (resuming from the runs already there)
/// and analyses it; returns the analysis as JSON (`sensitivity.json`'s
/// "analysis"). Shard `k` of `n` (n > 1) only computes its runs, as
/// `sensitivity --shard K/N` does, and returns an empty text.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (preset_ron, method, factors, tie, output, samples, levels, second_order, seed, log_output, out, k=1, n=1))]
fn sensitivity_folder(
    py: Python<'_>,
    preset_ron: &str,
    method: &str,
    factors: Vec<String>,
    tie: Vec<String>,
    output: String,
    samples: usize,
    levels: usize,
    second_order: bool,
    seed: u64,
    log_output: bool,
    out: PathBuf,
    k: usize,
    n: usize,
) -> PyResult<String> {
    use grainscope::global_sensitivity::{Design, Method, parse_factor};
    let shard = shard_of(k, n)?;
    let preset = from_ron(preset_ron)?;
    let factors =
        factors.iter().map(|f| parse_factor(f)).collect::<Result<Vec<_>, _>>().map_err(PyValueError::new_err)?;
    let method = match method {
        "morris" => Method::Morris { trajectories: samples, levels },
        "sobol" => Method::Sobol { samples, second_order },
        other => return Err(PyValueError::new_err(format!("method {other:?}: morris or sobol"))),
    };
    let design = Design { method, factors, seed };
    design.unit_points().map_err(|e| PyValueError::new_err(e.to_string()))?;
    let folder = out.clone();
    let analysis = interruptible(py, &Progress::default(), move |_| {
        grainscope::sweep_files::run_design(preset, design, &tie, &[output], shard, &folder, &|_, _| {}).and_then(
            |_| if shard.n > 1 { Ok(None) } else { grainscope::sweep_files::analyse(&folder, log_output).map(Some) },
        )
    })?
    .map_err(|e| PyValueError::new_err(format!("{e:#}")))?;
    match analysis {
        Some(a) => serde_json::to_string(&a.0).map_err(|e| PyValueError::new_err(e.to_string())),
        None => Ok(String::new()),
    }
}

/// Merges the folders of a sharded sweep or design into `out`, as
/// `grainscope sweep-merge` does: the files of the unsharded run.
#[pyfunction]
fn merge_folders(dirs: Vec<PathBuf>, out: PathBuf) -> PyResult<()> {
    grainscope::sweep_files::merge(&dirs, &out).map_err(|e| PyValueError::new_err(format!("{e:#}")))?;
    Ok(())
}

/// Analyses a finished (or merged) design's folder, as `grainscope
/// sensitivity --analyse` does; returns the analysis as JSON.
#[pyfunction]
fn analyse_folder(py: Python<'_>, out: PathBuf, log_output: bool) -> PyResult<String> {
    let analysis =
        interruptible(py, &Progress::default(), move |_| grainscope::sweep_files::analyse(&out, log_output))?
            .map_err(|e| PyValueError::new_err(format!("{e:#}")))?;
    serde_json::to_string(&analysis.0).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<Computed>()?;
    m.add_function(wrap_pyfunction!(program, m)?)?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(scenes, m)?)?;
    m.add_function(wrap_pyfunction!(preset_ron, m)?)?;
    m.add_function(wrap_pyfunction!(scene_of, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_points, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_table, m)?)?;
    m.add_function(wrap_pyfunction!(merge_tables, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_folder, m)?)?;
    m.add_function(wrap_pyfunction!(sensitivity_folder, m)?)?;
    m.add_function(wrap_pyfunction!(merge_folders, m)?)?;
    m.add_function(wrap_pyfunction!(analyse_folder, m)?)?;
    Ok(())
}
