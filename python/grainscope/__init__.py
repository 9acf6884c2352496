"""grainscope: dust microphysics from two touching grains to planetesimals.

The models of the grainscope explorer (S. Krijt, *From grains to
planetesimals*, Leiden 2015), computed in-process: the same Rust code as the
window and the command line, with numpy arrays out.

>>> import grainscope as gs
>>> r = gs.run("ice-bounce-8ms", velocity=3.0)
>>> r.scalars["e"]                         # keyed as `grainscope run --json`
>>> r.figures[0].series[0].x               # numpy arrays, in the axis units
>>> t = gs.sweep("restitution-ice", vary={"surface_energy": gs.log(0.1, 1.0, 20)})

Parameters are given by their documented names in SI units (`gs.scenes()`
lists them with unit, default, range and meaning). A name a scene does not
have raises `KeyError` naming the close matches; a value out of range raises
`ValueError` with the command line's message. Computations release the GIL
and stop at Ctrl-C. Nothing is printed.
"""

from __future__ import annotations

import csv
import functools
import io
import json
import math
import os
import tempfile
from dataclasses import dataclass
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _native

__version__: str = _native.__version__

__all__ = [
    "Axis",
    "Censored",
    "Figure",
    "Heatmap",
    "Parameter",
    "Preset",
    "Range",
    "Result",
    "Scene",
    "Series",
    "lin",
    "log",
    "morris",
    "presets",
    "run",
    "scenes",
    "sobol",
    "sweep",
]

#: Pixel size of a figure drawn for a notebook (the explorer's export size).
FIGURE_SIZE: Tuple[int, int] = (1200, 900)


@dataclass(frozen=True)
class Preset:
    """A shipped preset: a scene with its parameters, as in `grainscope presets`."""

    #: Name to pass to `run` and `sweep`, e.g. "ice-bounce-8ms".
    name: str
    #: The scene it opens.
    scene: str
    #: Its title.
    title: str


@dataclass(frozen=True)
class Parameter:
    """A documented parameter of a scene (as `grainscope params SCENE`)."""

    #: Name, as a keyword of `run` and a key of `sweep(vary=...)`.
    name: str
    #: Label in the explorer window.
    label: str
    #: "number", "count", "toggle", "material" or "choice".
    kind: str
    #: SI unit of the value ("" if dimensionless).
    unit: str
    #: The scene's default.
    default: Any
    #: Smallest valid value (numbers and counts).
    min: Optional[float]
    #: Largest valid value (numbers and counts).
    max: Optional[float]
    #: Whether the parameter spans decades (a log slider in the window).
    log: bool
    #: The valid values of a choice.
    choices: Tuple[str, ...]
    #: What it means.
    meaning: str
    #: Whether it changes only the figures' look, not the numbers.
    style_only: bool
    #: Whether it sets a numerical resolution, sample or limit of the method
    #: (a tolerance, a count, a step, a seed) rather than the physics: a
    #: converged answer does not depend on it.
    numerical: bool = False


@dataclass(frozen=True)
class Scene:
    """A scene of the explorer: one computation and its parameters."""

    #: Identifier, for `run(scene=...)`.
    id: str
    #: Title.
    title: str
    #: Thesis sections and figures it covers.
    source: str
    #: Whether one computation takes seconds or more.
    heavy: bool
    #: Its parameters.
    parameters: Tuple[Parameter, ...]

    def parameter(self, name: str) -> Parameter:
        """The parameter called `name` (KeyError if the scene has none)."""
        for p in self.parameters:
            if p.name == name:
                return p
        raise KeyError(f"{self.id} has no parameter '{name}'")


def presets() -> List[Preset]:
    """The shipped presets."""
    return [Preset(*p) for p in _native.presets()]


_SCENES: Optional[List[Scene]] = None


def scenes() -> List[Scene]:
    """Every scene with its documented parameters (units SI)."""
    global _SCENES
    if _SCENES is None:
        _SCENES = [
            Scene(
                id=s["id"],
                title=s["title"],
                source=s["source"],
                heavy=s["heavy"],
                parameters=tuple(Parameter(**{**p, "choices": tuple(p["choices"])}) for p in s["parameters"]),
            )
            for s in _native.scenes()
        ]
    return list(_SCENES)


def _kinds(preset: Optional[str], scene: Optional[str]) -> Dict[str, str]:
    """The kind of every parameter of the scene ("number", "count",
    "toggle", "material", "choice"), by name."""
    id = _native.scene_of(preset, scene)
    return {p.name: p.kind for s in scenes() if s.id == id for p in s.parameters}


def _text(name: str, value: Any, kind: Optional[str] = None) -> str:
    """A parameter value as the command line's `--set NAME=TEXT` takes it,
    checked against the parameter's kind: a switch takes a bool (Python's or
    numpy's), a number a real number, a count a whole number, a material or a
    choice a text."""
    is_bool = isinstance(value, (bool, np.bool_))
    is_int = isinstance(value, (int, np.integer)) and not is_bool
    is_real = is_int or isinstance(value, (float, np.floating))
    if kind == "toggle":
        if not is_bool:
            raise TypeError(f"{name} is a switch: it takes True or False, not {type(value).__name__} {value!r}")
        return "true" if value else "false"
    if kind == "number" and not is_real:
        raise TypeError(f"{name} takes a number, not {type(value).__name__} {value!r}")
    if kind == "count":
        if is_real and not is_int and float(value).is_integer():
            value = int(value)
        elif not is_int:
            raise TypeError(f"{name} takes a whole number, not {type(value).__name__} {value!r}")
    if kind in ("material", "choice") and not isinstance(value, str):
        raise TypeError(f"{name} takes a text (one of its documented choices), not {type(value).__name__} {value!r}")
    if is_bool:
        return "true" if value else "false"
    if is_int:
        return str(int(value))
    if is_real:
        return repr(float(value))
    if isinstance(value, str):
        return value
    raise TypeError(f"{name}: a number, a bool or a text, not {type(value).__name__}")


def _sets(params: Mapping[str, Any], seed: Optional[int], preset: Optional[str], scene: Optional[str]) -> List[Tuple[str, str]]:
    kinds = _kinds(preset, scene) if params else {}
    # A name the scene does not have passes unchecked: the module answers
    # it with its close matches.
    sets = [(k, _text(k, v, kinds.get(k))) for k, v in params.items()]
    if seed is not None:
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise ValueError(f"seed={seed!r}: a whole number ≥ 0")
        # A scene that draws no random numbers gives the same result with any seed.
        id = _native.scene_of(preset, scene)
        if any(p.name == "seed" for s in scenes() if s.id == id for p in s.parameters):
            sets.append(("seed", str(int(seed))))
    return sets


@dataclass(frozen=True)
class Axis:
    """An axis of a figure: quantity, unit as shown, scale."""

    label: str
    unit: str
    log: bool

    @property
    def title(self) -> str:
        """"label [unit]", or the label alone when dimensionless."""
        return f"{self.label} [{self.unit}]" if self.unit else self.label


@dataclass(frozen=True)
class Series:
    """A curve or set of points of a figure, in its axes' units."""

    #: Legend entry ("" for none).
    name: str
    #: Horizontal values.
    x: np.ndarray
    #: Vertical values.
    y: np.ndarray
    #: How the explorer draws it: "Line", "Dashed", "Points", …
    style: str


@dataclass(frozen=True)
class Heatmap:
    """A map drawn under a figure's series."""

    #: Cell centres along x (axis units).
    x: np.ndarray
    #: Cell centres along y (axis units).
    y: np.ndarray
    #: Values, shape (len(y), len(x)): z[j, i] belongs to (x[i], y[j]).
    z: np.ndarray
    #: What the colour shows.
    label: str
    #: Unit of the values ("" if dimensionless).
    unit: str
    #: Category names of a categorical map (z holds indices into it).
    categories: Tuple[str, ...]


class Figure:
    """A figure of a result: axes, series as numpy arrays, an optional map.

    In a notebook it shows itself as the explorer draws it.
    """

    def __init__(self, computed: Any, data: Mapping[str, Any]):
        self._computed = computed
        #: Identifier (the file stem of `save`).
        self.id: str = data["id"]
        #: Title.
        self.title: str = data["title"]
        #: Horizontal axis.
        self.x: Axis = _axis(data["x"])
        #: Vertical axis.
        self.y: Axis = _axis(data["y"])
        #: The curves and points.
        self.series: List[Series] = [
            Series(name=s["name"], x=xy[:, 0], y=xy[:, 1], style=_style(s["style"]))
            for s in data["series"]
            for xy in [np.array(s["points"], dtype=float).reshape(-1, 2)]
        ]
        #: Text placed at data points: (text, x, y) in the axis units.
        self.labels: List[Tuple[str, float, float]] = [
            (label["text"], float(label["at"][0]), float(label["at"][1])) for label in data.get("labels", [])
        ]
        h = data.get("heatmap")
        #: The map under the series, if any.
        self.heatmap: Optional[Heatmap] = None
        if h is not None:
            x = np.array(h["x"], dtype=float)
            y = np.array(h["y"], dtype=float)
            self.heatmap = Heatmap(
                x=x,
                y=y,
                z=np.array(h["values"], dtype=float).reshape(len(y), len(x)),
                label=h["label"],
                unit=h["unit"],
                categories=tuple(h.get("categories", ())),
            )

    def png(self, size: Tuple[int, int] = FIGURE_SIZE) -> bytes:
        """The figure as PNG bytes, the preset embedded (it reopens in the explorer)."""
        return self._computed.render(self.id, "png", tuple(size))

    def svg(self, size: Tuple[int, int] = FIGURE_SIZE) -> str:
        """The figure as an SVG document, the preset embedded."""
        return self._computed.render(self.id, "svg", tuple(size)).decode("utf-8")

    def _repr_png_(self) -> bytes:
        return self.png()

    def to_frame(self) -> Any:
        """The series as a tidy pandas DataFrame: series, x, y (needs pandas)."""
        pd = _pandas("Figure.to_frame")
        frames = [pd.DataFrame({"series": s.name, "x": s.x, "y": s.y}) for s in self.series]
        df = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=["series", "x", "y"])
        df.attrs.update({"figure": self.id, "x": self.x.title, "y": self.y.title})
        return df

    def __repr__(self) -> str:
        return f"<Figure {self.id!r}: {self.title}; {len(self.series)} series; x {self.x.title}, y {self.y.title}>"


def _axis(a: Mapping[str, Any]) -> Axis:
    return Axis(label=a["label"], unit=a["unit"], log=_style(a["scale"]) == "Log")


def _style(value: Any) -> str:
    """A unit enum variant as pythonize gives it (a name, or {name: fields})."""
    if isinstance(value, str):
        return value
    if isinstance(value, Mapping) and len(value) == 1:
        return next(iter(value))
    return str(value)


def _pandas(what: str) -> Any:
    try:
        import pandas
    except ImportError as e:
        raise ImportError(f"{what} needs pandas: pip install pandas") from e
    return pandas


class Censored(float):
    """A scalar that has no value, as a float that says so: a bound
    (`status` "above": the value lies above the float, the bound) or
    undefined (`status` "undefined": the float is NaN). `why` gives the
    reason. Arithmetic sees the plain float."""

    status: str
    why: str

    def __new__(cls, value: float, status: str, why: str) -> "Censored":
        self = super().__new__(cls, value)
        self.status = status
        self.why = why
        return self

    def __repr__(self) -> str:
        if self.status == "above":
            return f"> {float(self)!r} ({self.why})"
        return f"undefined ({self.why})"

    __str__ = __repr__


def _scalar(value: Any) -> Any:
    """A scalar of `run --json`: a float, or a `Censored` for a bound or an
    undefined value."""
    if isinstance(value, Mapping):
        status = str(value.get("status", "undefined"))
        bound = value.get("bound")
        return Censored(float(bound) if bound is not None else math.nan, status, str(value.get("why", "")))
    return value


class Result:
    """A computed scene: scalars, figures, the preset that reproduces it."""

    def __init__(self, computed: Any):
        self._computed = computed
        #: The scene's identifier.
        self.scene: str = computed.scene
        #: The preset's title.
        self.title: str = computed.title
        #: The scalars, keyed exactly as `grainscope run --json` (SI units).
        #: A bound or an undefined value is a `Censored` float: the bound
        #: (or NaN) with its `status` ("above", "undefined") and `why`.
        self.scalars: Dict[str, float] = {k: _scalar(v) for k, v in json.loads(computed.scalars_json()).items()}
        #: Each scalar's status: "value", "above" (only a lower bound is
        #: known) or "undefined".
        self.status: Dict[str, str] = {
            k: (v.status if isinstance(v, Censored) else "value") for k, v in self.scalars.items()
        }
        listed = computed.scalars()
        #: The unit of each scalar ("" if dimensionless).
        self.units: Dict[str, str] = {k: u for k, _, _, u in listed}
        #: The label of each scalar, as the explorer shows it.
        self.labels: Dict[str, str] = {k: label for k, label, _, _ in listed}
        #: Warnings the scene gave.
        self.warnings: List[str] = computed.warnings()
        #: Notes the scene gave.
        self.notes: List[str] = computed.notes()
        #: The build that computed it: "grainscope VERSION (commit …, DATE)".
        self.program: str = _native.program()

    @functools.cached_property
    def figures(self) -> List[Figure]:
        """The figures, as exported (made into arrays when first asked for)."""
        return [Figure(self._computed, f) for f in self._computed.figures()]

    @property
    def preset(self) -> str:
        """The preset (RON text) that reproduces this result in the explorer and CLI."""
        return self._computed.preset_ron()

    def figure(self, id: str) -> Figure:
        """The figure called `id` (KeyError if none)."""
        for f in self.figures:
            if f.id == id:
                return f
        raise KeyError(f"no figure '{id}' (figures: {', '.join(f.id for f in self.figures)})")

    def to_frame(self) -> Any:
        """Every series of every figure as one tidy pandas DataFrame:
        figure, series, x, y (needs pandas). Axis titles are in `df.attrs`."""
        pd = _pandas("Result.to_frame")
        frames = []
        for f in self.figures:
            for s in f.series:
                frames.append(pd.DataFrame({"figure": f.id, "series": s.name, "x": s.x, "y": s.y}))
        df = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=["figure", "series", "x", "y"])
        df.attrs["axes"] = {f.id: (f.x.title, f.y.title) for f in self.figures}
        df.attrs["program"] = self.program
        df.attrs["preset"] = self.preset
        return df

    def save(self, folder: Any) -> List[str]:
        """Writes what `grainscope run --out FOLDER` writes (CSV, SVG and PNG per
        figure, scalars.json), all or nothing; returns the paths."""
        return self._computed.save(str(folder))

    def _repr_png_(self) -> Optional[bytes]:
        return self.figures[0].png() if self.figures else None

    def _repr_svg_(self) -> Optional[str]:
        return self.figures[0].svg() if self.figures else None

    def __repr__(self) -> str:
        shown = ", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in list(self.scalars.items())[:4])
        more = ", …" if len(self.scalars) > 4 else ""
        return f"<Result {self.scene}: {shown}{more}; {len(self.figures)} figures>"


def run(preset: Optional[str] = None, /, *, scene: Optional[str] = None, seed: Optional[int] = None, **params: Any) -> Result:
    """Computes a shipped preset or preset file (`preset`), or a scene's
    defaults (`scene=`), with `params` (documented names, SI units) changed.

    `seed` sets the first random seed of the Monte Carlo scenes (results are
    reproducible for a given seed); scenes without random numbers ignore it.
    """
    sets = _sets(params, seed, preset, scene)
    return Result(_native.run(preset, scene, sets))


@dataclass(frozen=True)
class Range:
    """Values of a swept parameter, spaced evenly (`lin`) or evenly in the
    logarithm (`log`), `start` first and `stop` last."""

    spacing: str
    start: float
    stop: float
    num: int

    def text(self, name: str) -> str:
        """The command line's `--vary` text."""
        return f"{name}={self.spacing}:{self.start!r}:{self.stop!r}:{self.num}"

    def values(self) -> np.ndarray:
        """The values."""
        if self.spacing == "log":
            return np.geomspace(self.start, self.stop, self.num)
        return np.linspace(self.start, self.stop, self.num)


def lin(start: float, stop: float, num: int = 0) -> Range:
    """`num` values evenly spaced from `start` to `stop` (for a sweep; a
    sensitivity range needs no count)."""
    return Range("lin", float(start), float(stop), int(num))


def log(start: float, stop: float, num: int = 0) -> Range:
    """`num` values evenly spaced in the logarithm from `start` to `stop` (both
    > 0; for a sweep; a sensitivity range needs no count)."""
    return Range("log", float(start), float(stop), int(num))


def _vary_text(name: str, values: Union[Range, Sequence[float], np.ndarray]) -> str:
    if isinstance(values, Range):
        if values.num < 1:
            raise ValueError(f"vary[{name!r}]: a sweep needs a count, e.g. gs.{values.spacing}({values.start!r}, {values.stop!r}, 10)")
        return values.text(name)
    if isinstance(values, (str, bytes)):
        raise TypeError(f"vary[{name!r}]: gs.lin(...), gs.log(...) or a list of numbers")
    numbers = [float(v) for v in np.asarray(values, dtype=float).ravel()]
    if not numbers:
        raise ValueError(f"vary[{name!r}]: no values")
    bad = [v for v in numbers if not math.isfinite(v)]
    if bad:
        raise ValueError(f"vary[{name!r}]: {bad[0]} is not a finite number")
    return f"{name}=list:" + ":".join(repr(v) for v in numbers)


def _shard_table(preset_ron: str, vary: List[str], scalars: List[str], k: int, n: int) -> str:
    """Shard `k` of `n` of a sweep: what one Dask task computes."""
    return _native.sweep_table(preset_ron, vary, scalars, k, n)


def _read_files(folder: str) -> Dict[str, bytes]:
    """The files of a folder (none if it does not exist)."""
    if not os.path.isdir(folder):
        return {}
    out = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            with open(path, "rb") as f:
                out[name] = f.read()
    return out


def _write_files(folder: str, files: Mapping[str, bytes]) -> None:
    """Writes `files` into `folder`, each whole or not at all."""
    os.makedirs(folder, exist_ok=True)
    for name, data in files.items():
        path = os.path.join(folder, name)
        with open(path + ".part", "wb") as f:
            f.write(data)
        os.replace(path + ".part", path)


def _shard_task(kind: str, args: Tuple[Any, ...], k: int, n: int, files: Mapping[str, bytes]) -> Dict[str, bytes]:
    """One Dask task: shard `k` of `n` of a sweep ("sweep") or a sensitivity
    design ("design"), computed in a folder of the worker's own that starts
    with the shard's files so far (so it resumes); returns the folder's
    files. Workers need no file system shared with the client."""
    with tempfile.TemporaryDirectory() as folder:
        _write_files(folder, files)
        if kind == "sweep":
            _native.sweep_folder(*args, folder, k, n)
        else:
            _native.sensitivity_folder(*args, folder, k, n)
        return _read_files(folder)


def _spread(client: Any, kind: str, args: Tuple[Any, ...], n: int, out: str) -> None:
    """Computes a sweep or design over a Dask `client` in `n` shards kept in
    `out`/shards/K-of-N (each resumed from what it holds there), then merges
    them into `out` as `grainscope sweep-merge` does: the unsharded run's files."""
    dirs = [os.path.join(out, "shards", f"{k}-of-{n}") for k in range(1, n + 1)]
    futures = client.map(
        _shard_task, [kind] * n, [args] * n, list(range(1, n + 1)), [n] * n, [_read_files(d) for d in dirs], pure=False
    )
    for d, future in zip(dirs, futures):
        # Each shard is kept as soon as it is done: a later call resumes from it.
        _write_files(d, future.result())
    _native.merge_folders(dirs, out)


def _workers(client: Any) -> int:
    try:
        return max(1, sum(client.nthreads().values()))
    except Exception:
        return 1


def sweep(
    preset: Optional[str] = None,
    /,
    *,
    vary: Mapping[str, Union[Range, Sequence[float], np.ndarray]],
    scene: Optional[str] = None,
    scalars: Optional[Sequence[str]] = None,
    out: Any = None,
    client: Any = None,
    shards: Optional[int] = None,
    seed: Optional[int] = None,
    **params: Any,
) -> Any:
    """A scene's scalars over a grid of parameter values: the table of
    `grainscope sweep` (a row per point: point, the varied values, the
    scalars, error; units in the column names).

    `vary` maps parameter names to `gs.lin(...)`, `gs.log(...)` or a list of
    values; several make a grid (the last varies fastest). `scalars` picks
    columns (keys of `Result.scalars`); all by default. `out` writes the
    command line's folder (sweep.csv, sweep.ron, figures) and resumes from the
    rows already in it. `client`, a `dask.distributed.Client`, spreads the
    points over its workers in `shards` deterministic slices (one per worker
    thread by default); the table is the same as computed here. With both,
    the shards are kept in `out`/shards and merged into `out`; a call
    again resumes each from what it holds.

    Returns a pandas DataFrame when pandas is installed (its `attrs` name
    the build, "program", and the preset, "preset"), else a dict of numpy
    arrays (the `error` and `KEY status` columns lists of texts or None).
    A scalar that can be a bound or undefined has a `KEY status` column
    beside it: empty for a value, else "above: WHY" (the value column holds
    the bound) or "undefined: WHY".
    """
    if not isinstance(vary, Mapping):
        raise TypeError(f"vary takes a mapping of parameter names to values, e.g. vary={{'velocity': gs.log(1, 10, 5)}}, not {type(vary).__name__}")
    if not vary:
        raise ValueError("nothing to vary: give vary={'name': gs.log(...)}")
    preset_ron = _native.preset_ron(preset, scene, _sets(params, seed, preset, scene))
    texts = [_vary_text(k, v) for k, v in vary.items()]
    chosen = list(scalars) if scalars is not None else []
    if out is not None and client is not None:
        points = _native.sweep_points(preset_ron, texts)
        n = max(1, min(points, int(shards) if shards else _workers(client)))
        _spread(client, "sweep", (preset_ron, texts, chosen), n, str(out))
        with open(os.path.join(str(out), "sweep.csv"), encoding="utf-8") as f:
            table = f.read()
    elif out is not None:
        table = _native.sweep_folder(preset_ron, texts, chosen, str(out))
    elif client is not None:
        points = _native.sweep_points(preset_ron, texts)
        n = max(1, min(points, int(shards) if shards else _workers(client)))
        futures = client.map(
            _shard_table, [preset_ron] * n, [texts] * n, [chosen] * n, list(range(1, n + 1)), [n] * n, pure=False
        )
        table = _native.merge_tables(preset_ron, texts, chosen, client.gather(futures))
    else:
        table = _native.sweep_table(preset_ron, texts, chosen, 1, 1)
    t = _table(table)
    if hasattr(t, "attrs"):
        # Which build and preset made the table (a DataFrame's attrs).
        t.attrs["program"] = _native.program()
        t.attrs["preset"] = preset_ron
    return t


def _factor_text(name: str, values: Any) -> str:
    """A factor of a sensitivity design: `gs.lin(a, b)`, `gs.log(a, b)` (the
    count is ignored) or a pair (a, b), uniform in the value."""
    if isinstance(values, Range):
        return f"{name}={values.spacing}:{values.start!r}:{values.stop!r}"
    if isinstance(values, (tuple, list)) and len(values) == 2 and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
        return f"{name}=lin:{float(values[0])!r}:{float(values[1])!r}"
    raise TypeError(f"vary[{name!r}] takes gs.lin(a, b), gs.log(a, b) or a pair (a, b), not {values!r}")


def _sensitivity(
    method: str,
    preset: Optional[str],
    vary: Any,
    output: Any,
    scene: Optional[str],
    tie: Any,
    samples: int,
    levels: int,
    second_order: bool,
    seed: int,
    log_output: bool,
    out: Any,
    client: Any,
    shards: Optional[int],
    params: Mapping[str, Any],
) -> Dict[str, Any]:
    if not isinstance(vary, Mapping) or not vary:
        raise TypeError("vary takes a mapping of parameter names to ranges, e.g. vary={'velocity': gs.log(1, 10)}")
    if not isinstance(output, str):
        raise TypeError(f"output takes a scalar's key (a text), not {type(output).__name__}")
    ties = dict(tie or {})
    for k, v in ties.items():
        if not isinstance(k, str) or not isinstance(v, str):
            raise TypeError("tie takes a mapping of parameter names to parameter names, e.g. tie={'radius_2': 'radius_1'}")
    for name, value in (("samples", samples), ("levels", levels), ("seed", seed)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
            raise TypeError(f"{name} takes a whole number, not {value!r}")
    if shards is not None and (isinstance(shards, bool) or not isinstance(shards, (int, np.integer)) or shards < 1):
        raise TypeError(f"shards takes a whole number ≥ 1, not {shards!r}")
    preset_ron = _native.preset_ron(preset, scene, _sets(params, None, preset, scene))
    factors = [_factor_text(k, v) for k, v in vary.items()]
    args = (
        preset_ron, method, factors, [f"{k}={v}" for k, v in ties.items()], output,
        int(samples), int(levels), bool(second_order), int(seed), bool(log_output),
    )

    def go(folder: str) -> Dict[str, Any]:
        if client is None:
            return json.loads(_native.sensitivity_folder(*args, folder))
        n = int(shards) if shards else _workers(client)
        _spread(client, "design", args, n, folder)
        return json.loads(_native.analyse_folder(folder, bool(log_output)))

    if out is not None:
        return go(str(out))
    with tempfile.TemporaryDirectory() as folder:
        return go(folder)


def _attrs(frame: Any, analysis: Mapping[str, Any]) -> Any:
    if hasattr(frame, "attrs"):
        frame.attrs["program"] = analysis["program"]
        frame.attrs["computed_by"] = analysis["computed_by"]
        frame.attrs["runs"] = analysis["runs"]
        frame.attrs["undefined"] = analysis["undefined"]
        frame.attrs["bounded"] = analysis["bounded"]
        frame.attrs["output"] = analysis["output"]
    return frame


def _frame(rows: Dict[str, List[float]], index: List[str]) -> Any:
    try:
        import pandas as pd
    except ImportError:
        return {"parameter": index, **{k: np.array(v, dtype=float) for k, v in rows.items()}}
    return pd.DataFrame(rows, index=index)


def _number(v: Any) -> float:
    return math.nan if v is None else float(v)


def morris(
    preset: Optional[str] = None,
    /,
    *,
    vary: Mapping[str, Any],
    output: str,
    scene: Optional[str] = None,
    tie: Optional[Mapping[str, str]] = None,
    trajectories: int = 20,
    levels: int = 4,
    seed: int = 2015,
    log_output: bool = False,
    out: Any = None,
    client: Any = None,
    shards: Optional[int] = None,
    **params: Any,
) -> Any:
    """Morris's elementary effects of scalar `output` over the ranges in
    `vary` (`gs.lin(a, b)`, `gs.log(a, b)` or a pair): μ, μ*, σ and μ*'s
    interval per parameter, as `grainscope sensitivity --method morris`.

    `tie` maps a parameter to the one whose value it takes ({'radius_2':
    'radius_1'}: equal spheres); `log_output` analyses ln of the output.
    `out` keeps the runs in a folder (resumed when called again). `client`,
    a `dask.distributed.Client`, spreads the runs over its workers in
    `shards` slices (one per worker thread by default), with `out` or
    without; the indices are the same as computed here. Returns a
    DataFrame shaped like SALib's `to_df()` (a row per parameter; `attrs`
    name the build, the runs and how many were undefined or bounds), or a
    dict of arrays without pandas.
    """
    a = _sensitivity(
        "morris", preset, vary, output, scene, tie, trajectories, levels, False, seed, log_output, out, client, shards, params
    )
    names = [f["key"] for f in a["design"]["factors"]]
    m = a["morris"]
    rows = {k: [_number(i[k]) for i in m] for k in ("mu", "mu_star", "sigma", "mu_star_conf")}
    return _attrs(_frame(rows, names), a)


def sobol(
    preset: Optional[str] = None,
    /,
    *,
    vary: Mapping[str, Any],
    output: str,
    scene: Optional[str] = None,
    tie: Optional[Mapping[str, str]] = None,
    samples: int = 256,
    second_order: bool = False,
    seed: int = 2015,
    log_output: bool = False,
    out: Any = None,
    client: Any = None,
    shards: Optional[int] = None,
    **params: Any,
) -> Any:
    """Sobol' indices of scalar `output` over the ranges in `vary`, as
    `grainscope sensitivity --method sobol`: `samples` base samples (a power
    of two), N(d + 2) runs (N(2d + 2) with `second_order`).

    Returns a list of frames shaped like SALib's `to_df()`: total indices
    (ST, ST_conf), first-order (S1, S1_conf) and, with `second_order`, S2
    and S2_conf indexed by parameter pairs. `tie`, `log_output`, `out`,
    `client` and `shards` as for `morris`.
    """
    a = _sensitivity(
        "sobol", preset, vary, output, scene, tie, samples, 4, second_order, seed, log_output, out, client, shards, params
    )
    names = [f["key"] for f in a["design"]["factors"]]
    r = a["sobol"]
    idx = r["indices"]
    total = _frame({"ST": [_number(i["total"]) for i in idx], "ST_conf": [_number(i["total_conf"]) for i in idx]}, names)
    first = _frame({"S1": [_number(i["first"]) for i in idx], "S1_conf": [_number(i["first_conf"]) for i in idx]}, names)
    frames = [_attrs(total, a), _attrs(first, a)]
    if r.get("second"):
        s2, conf = r["second"]
        pairs = [(names[j], names[k]) for j in range(len(names)) for k in range(j + 1, len(names))]
        rows = {
            "S2": [_number(s2[j][k]) for j in range(len(names)) for k in range(j + 1, len(names))],
            "S2_conf": [_number(conf[j][k]) for j in range(len(names)) for k in range(j + 1, len(names))],
        }
        try:
            import pandas as pd

            second = pd.DataFrame(rows, index=pd.MultiIndex.from_tuples(pairs))
        except ImportError:
            second = {"pair": pairs, **{k: np.array(v) for k, v in rows.items()}}
        frames.append(_attrs(second, a))
    return frames


def _table(text: str) -> Any:
    """A sweep table as a DataFrame, or without pandas a dict of arrays."""
    try:
        import pandas as pd
    except ImportError:
        pd = None
    texts = [n for n in next(csv.reader(io.StringIO(text))) if n == "error" or n.endswith(" status")]
    if pd is not None:
        df = pd.read_csv(io.StringIO(text), dtype={n: "string" for n in texts})
        return df
    rows = list(csv.reader(io.StringIO(text)))
    header, body = rows[0], rows[1:]
    columns: Dict[str, Any] = {}
    for j, name in enumerate(header):
        cells = [r[j] for r in body]
        if name in texts:
            columns[name] = [c or None for c in cells]
        elif name == "point":
            columns[name] = np.array([int(c) for c in cells], dtype=np.int64)
        else:
            columns[name] = np.array([float(c) if c else math.nan for c in cells], dtype=float)
    return columns

