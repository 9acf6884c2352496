"""The Python module against the command line: the same numbers, the same
errors, the same files; and the manners of a Python library (exceptions,
GIL, Ctrl-C, seeds, silence)."""

import io
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import threading
import time

import numpy as np
import pandas as pd
import pytest

import grainscope as gs

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    """The command line built from the same sources (GRAINSCOPE_BIN, or the
    release build of this checkout)."""
    path = pathlib.Path(os.environ.get("GRAINSCOPE_BIN", ROOT / "target" / "release" / "grainscope"))
    if not path.exists():
        pytest.fail(f"no grainscope binary at {path}: build it (cargo build --release) or set GRAINSCOPE_BIN")
    return path


def cli_json(cli, preset, *sets):
    args = [str(cli), "run", preset, "--json"]
    for s in sets:
        args += ["--set", s]
    return json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)


def cli_error(cli, preset, *sets):
    args = [str(cli), "run", preset, "--json"]
    for s in sets:
        args += ["--set", s]
    done = subprocess.run(args, capture_output=True, text=True)
    assert done.returncode != 0
    return done.stderr.strip()


def same_numbers(a, b):
    assert a.keys() == b.keys()
    for k in a:
        if isinstance(b[k], dict):
            # A bound or an undefined value: the same status, bound and reason.
            assert isinstance(a[k], gs.Censored), (k, a[k])
            assert (a[k].status, a[k].why) == (b[k]["status"], b[k]["why"]), (k, a[k], b[k])
            if "bound" in b[k]:
                assert float(a[k]) == b[k]["bound"], k
            else:
                assert math.isnan(a[k]), k
        else:
            # The same code; a different build may round the last bit otherwise.
            assert math.isclose(a[k], b[k], rel_tol=1e-12, abs_tol=1e-300), (k, a[k], b[k])


@pytest.mark.parametrize(
    "preset",
    ["ice-bounce-8ms", "ice-stick-2ms", "restitution-ice", "disk-fig-4-1", "debris-fig-6-2", "mc-kernel-constant"],
)
def test_scalars_equal_the_command_line(cli, preset):
    same_numbers(gs.run(preset).scalars, cli_json(cli, preset))


def test_parameters_change_what_the_command_line_changes(cli):
    r = gs.run("ice-bounce-8ms", velocity=3.0, surface_energy=0.3)
    same_numbers(r.scalars, cli_json(cli, "ice-bounce-8ms", "velocity=3.0", "surface_energy=0.3"))


def test_the_physics_reads_as_in_the_thesis():
    # Two 2 µm ice spheres stick at 2 m/s and bounce at 8 m/s (Sect. 2.4).
    stick, bounce = gs.run("ice-stick-2ms"), gs.run("ice-bounce-8ms")
    assert stick.scalars["sticks"] == 1.0 and stick.scalars["e"] == 0.0
    assert bounce.scalars["sticks"] == 0.0 and 0.5 < bounce.scalars["e"] < 0.8
    # Without adhesion or viscosity nothing is lost: e → 1 as γ and T_vis vanish.
    elastic = gs.run("ice-bounce-8ms", surface_energy=1e-3, t_vis=1e-15)
    assert elastic.scalars["e"] > 0.9999
    # Without adhesion, e is the viscous limit e_D of the same collision.
    dry = gs.run("ice-bounce-8ms", surface_energy=1e-3)
    assert math.isclose(dry.scalars["e"], dry.scalars["e_D"], rel_tol=2e-3)
    assert bounce.units["t_c"] == "s"


def test_a_scene_by_its_id_starts_from_its_defaults():
    a = gs.run(scene="hysteresis")
    b = gs.run(scene="hysteresis", velocity=[p for s in gs.scenes() if s.id == "hysteresis" for p in s.parameters if p.name == "velocity"][0].default)
    assert a.scalars == b.scalars
    assert a.scene == "hysteresis"


def test_scenes_and_presets_are_listed_with_units_ranges_and_meaning():
    scenes = {s.id: s for s in gs.scenes()}
    assert {"hysteresis", "restitution", "disk-map", "mass-distribution"} <= scenes.keys()
    v = scenes["hysteresis"].parameter("velocity")
    assert (v.unit, v.kind) == ("m s^-1", "number")
    assert v.min < v.default < v.max and v.meaning
    # A numerical resolution says so; the physics does not.
    assert scenes["hysteresis"].parameter("rtol").numerical and not v.numerical
    presets = {p.name: p for p in gs.presets()}
    assert presets["ice-bounce-8ms"].scene == "hysteresis"
    assert len(presets) == len(list((ROOT / "presets").glob("*.ron")))


def test_figures_are_numpy_arrays_with_axes_and_maps():
    r = gs.run("ice-bounce-8ms")
    f = r.figure("contact-radius")
    assert (f.x.label, f.x.unit, f.y.unit) == ("mutual approach δ", "nm", "nm")
    s = f.series[0]
    assert isinstance(s.x, np.ndarray) and s.x.dtype == float and s.x.shape == s.y.shape and len(s.x) > 100
    # The contact radius of a bounce returns to zero where the spheres part.
    assert s.y.max() > 200 and s.y[-1] < 0.05 * s.y.max()
    speeds = gs.run(scene="collision-speeds")
    maps = [f.heatmap for f in speeds.figures if f.heatmap is not None]
    assert maps and maps[0].z.shape == (len(maps[0].y), len(maps[0].x))
    assert np.isfinite(maps[0].z).any()
    # The map of dominant sources names its regions at points inside it.
    sources = speeds.figure("dominant-source")
    assert len(sources.labels) >= 3
    for text, x, y in sources.labels:
        assert text and sources.heatmap.x[0] <= x <= sources.heatmap.x[-1], (text, x)


def test_a_result_draws_itself_and_reopens_its_state():
    r = gs.run("ice-bounce-8ms", velocity=5.0)
    png = r._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000
    assert r._repr_svg_().lstrip().startswith(("<svg", "<?xml"))
    assert "velocity: 5.0" in r.preset or "velocity: 5" in r.preset


def test_save_writes_the_files_of_run_out(cli, tmp_path):
    r = gs.run("ice-bounce-8ms", velocity=4.0)
    written = sorted(pathlib.Path(p).name for p in r.save(tmp_path / "py"))
    subprocess.run([str(cli), "run", "ice-bounce-8ms", "--set", "velocity=4.0", "--out", str(tmp_path / "cli")], check=True, capture_output=True)
    assert written == sorted(p.name for p in (tmp_path / "cli").iterdir())
    for name in written:
        if name.endswith((".csv", ".json")):
            assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name


def test_to_frame_is_tidy():
    df = gs.run("ice-bounce-8ms").to_frame()
    assert list(df.columns) == ["figure", "series", "x", "y"]
    assert set(df["figure"]) == {f.id for f in gs.run("ice-bounce-8ms").figures if f.series}
    assert df.attrs["axes"]["contact-radius"] == ("mutual approach δ [nm]", "contact radius a [nm]")


def test_a_mistyped_name_is_a_key_error_naming_the_close_matches(cli):
    with pytest.raises(KeyError) as e:
        gs.run("ice-bounce-8ms", velocty=3.0)
    assert "did you mean 'velocity'" in str(e.value)
    assert str(e.value).strip("'\"") in cli_error(cli, "ice-bounce-8ms", "velocty=3.0")
    with pytest.raises(KeyError, match="did you mean 'ice-bounce-8ms'"):
        gs.run("ice-bounce-8m")
    with pytest.raises(KeyError, match="did you mean 'hysteresis'"):
        gs.run(scene="hysteresys")
    with pytest.raises(KeyError, match="did you mean 'surface_energy'"):
        gs.sweep("ice-bounce-8ms", vary={"surface_energi": [0.1, 0.2]})


def test_a_bad_value_is_a_value_error_with_the_command_lines_message(cli):
    with pytest.raises(ValueError) as e:
        gs.run("ice-bounce-8ms", velocity=-3.0)
    assert cli_error(cli, "ice-bounce-8ms", "velocity=-3.0") == f"error: --set velocity=-3.0: {e.value}"
    with pytest.raises(ValueError, match="velocity"):
        gs.run("ice-bounce-8ms", velocity=float("nan"))
    with pytest.raises(ValueError):
        gs.run("ice-bounce-8ms", crack_law="perhaps")
    with pytest.raises(TypeError):
        gs.run("ice-bounce-8ms", velocity=[1, 2])
    with pytest.raises(ValueError, match="not both"):
        gs.run("ice-bounce-8ms", scene="hysteresis")
    with pytest.raises(ValueError):
        gs.sweep("ice-bounce-8ms", vary={"velocity": [1.0, float("inf")]})
    with pytest.raises(ValueError, match="malformed|expected|RON|preset"):
        bad = pathlib.Path(os.environ.get("TMPDIR", "/tmp")) / "grainscope-bad-preset.ron"
        bad.write_text("(scene: Hysteresis((velocity: ")
        gs.run(str(bad))


def test_sweeps_equal_the_command_lines_table(cli, tmp_path):
    vary = {"velocity": gs.log(0.5, 20.0, 6)}
    df = gs.sweep("ice-bounce-8ms", vary=vary, scalars=["e", "sticks"])
    subprocess.run(
        [str(cli), "sweep", "ice-bounce-8ms", "--vary", "velocity=log:0.5:20.0:6", "--scalars", "e,sticks", "--out", str(tmp_path / "cli")],
        check=True,
        capture_output=True,
    )
    expected = pd.read_csv(tmp_path / "cli" / "sweep.csv", dtype={"error": "string"})
    pd.testing.assert_frame_equal(df, expected)
    assert list(df.columns) == ["point", "velocity [m s^-1]", "e", "sticks", "error"]
    # Slow spheres stick, fast ones bounce.
    assert df["sticks"].iloc[0] == 1.0 and df["sticks"].iloc[-1] == 0.0
    # A list of values is a sweep too, and `out=` writes the command line's folder.
    listed = gs.sweep("ice-bounce-8ms", vary={"velocity": np.array([1.0, 3.0, 9.0])}, scalars=["e"], out=tmp_path / "py")
    assert list(listed["velocity [m s^-1]"]) == [1.0, 3.0, 9.0]
    subprocess.run(
        [str(cli), "sweep", "ice-bounce-8ms", "--vary", "velocity=list:1.0:3.0:9.0", "--scalars", "e", "--out", str(tmp_path / "cli-list")],
        check=True,
        capture_output=True,
    )
    assert (tmp_path / "py" / "sweep.csv").read_bytes() == (tmp_path / "cli-list" / "sweep.csv").read_bytes()


def test_a_grid_varies_the_last_parameter_fastest():
    t = gs.sweep("ice-bounce-8ms", vary={"surface_energy": [0.2, 0.7], "velocity": [2.0, 8.0]}, scalars=["e"])
    assert list(t["surface_energy [J m^-2]"]) == [0.2, 0.2, 0.7, 0.7]
    assert list(t["velocity [m s^-1]"]) == [2.0, 8.0, 2.0, 8.0]


def test_a_sweep_spread_over_a_dask_cluster_gives_the_same_table():
    distributed = pytest.importorskip("dask.distributed")
    vary = {"velocity": gs.lin(1.0, 10.0, 7), "surface_energy": [0.3, 0.7]}
    local = gs.sweep("ice-bounce-8ms", vary=vary, scalars=["e", "t_c"])
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            spread = gs.sweep("ice-bounce-8ms", vary=vary, scalars=["e", "t_c"], client=client, shards=5)
    pd.testing.assert_frame_equal(local, spread)


def test_the_table_without_pandas_is_a_dict_of_arrays(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    t = gs.sweep("ice-bounce-8ms", vary={"velocity": [1.0, 8.0]}, scalars=["e"])
    assert isinstance(t, dict) and t["point"].tolist() == [0, 1]
    assert t["e"].dtype == float and t["error"] == [None, None]


def test_seeds_make_monte_carlo_results_reproducible():
    a = gs.run("mc-kernel-constant", seed=3, runs=2)
    b = gs.run("mc-kernel-constant", seed=3, runs=2)
    c = gs.run("mc-kernel-constant", seed=4, runs=2)
    assert a.scalars == b.scalars
    assert a.scalars != c.scalars
    # A scene without random numbers takes any seed and ignores it.
    assert gs.run("ice-bounce-8ms", seed=5).scalars == gs.run("ice-bounce-8ms").scalars


def test_the_gil_is_released_while_computing():
    ticks = []
    worker = threading.Thread(target=lambda: gs.run("mc-kernel-linear"))
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.005)
    worker.join()
    # Held, the GIL would let this thread tick once or twice in ~1.7 s.
    assert len(ticks) > 20, len(ticks)


def test_ctrl_c_interrupts_a_long_run():
    # Python leaves SIGINT ignored when it starts with SIGINT ignored (as a
    # shell's background jobs do): the child installs the usual handler.
    code = (
        "import os, signal, threading, time, grainscope as gs\n"
        "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()\n"
        "t0 = time.perf_counter()\n"
        "try:\n"
        "    gs.run('mc-fig-4-9')\n"
        "    print('finished')\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted after %.1f s' % (time.perf_counter() - t0))\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.stdout.startswith("interrupted after"), done.stdout + done.stderr
    assert float(done.stdout.split()[2]) < 10.0, done.stdout


def test_the_library_prints_nothing(capfd):
    gs.run("ice-bounce-8ms")
    gs.sweep("ice-bounce-8ms", vary={"velocity": [1.0, 2.0]})
    gs.run("mc-kernel-constant", runs=1)
    out, err = capfd.readouterr()
    assert out == "" and err == ""


def test_a_switch_takes_a_bool_and_every_wrong_type_is_named():
    # No silent coercion: "yes", 1 and "perhaps" are not switches.
    for wrong in ("yes", 1, 1.0, "perhaps"):
        with pytest.raises(TypeError, match="plasticity is a switch"):
            gs.run("ice-bounce-8ms", plasticity=wrong)
    # numpy's bool is a bool.
    on = gs.run("ice-bounce-8ms", plasticity=np.bool_(True))
    assert on.scalars["e"] == gs.run("ice-bounce-8ms", plasticity=True).scalars["e"]
    with pytest.raises(TypeError, match="velocity takes a number"):
        gs.run("ice-bounce-8ms", velocity="fast")
    with pytest.raises(TypeError, match="velocity takes a number"):
        gs.run("ice-bounce-8ms", velocity=True)
    with pytest.raises(TypeError, match="crack_law takes a text"):
        gs.run("ice-bounce-8ms", crack_law=2)
    with pytest.raises(TypeError, match="vary takes a mapping"):
        gs.sweep("ice-bounce-8ms", vary=[1.0, 2.0])
    with pytest.raises(TypeError, match="velocity takes a number"):
        gs.sweep("ice-bounce-8ms", vary={"t_vis": [1e-11]}, velocity="4")


def test_a_bound_and_an_undefined_value_say_so():
    # With plastic yield at 100 MPa nothing bounces up to 10⁴ m/s: v_s is a
    # lower bound; without plasticity there is no yield velocity.
    r = gs.run("restitution-ice", plasticity=True, n_radii=2, n_t_vis=1, n_velocities=20)
    v = r.scalars["v_stick"]
    assert isinstance(v, gs.Censored) and r.status["v_stick"] == "above"
    assert float(v) == 1e4 and "bounces" in v.why and repr(v).startswith("> 10000.0")
    plain = gs.run("restitution-ice", n_radii=2, n_t_vis=1, n_velocities=20)
    assert plain.status["v_y"] == "undefined" and math.isnan(plain.scalars["v_y"])
    assert "plasticity is off" in plain.scalars["v_y"].why
    assert plain.status["v_stick"] == "value" and type(plain.scalars["v_stick"]) is float
    # A sticking collision has no contact time.
    stick = gs.run("ice-stick-2ms")
    assert stick.status["t_c"] == "undefined" and "stick" in stick.scalars["t_c"].why
    # In a sweep the status stands beside the value.
    t = gs.sweep("ice-bounce-8ms", vary={"velocity": [2.0, 8.0]}, scalars=["e", "t_c"])
    assert list(t.columns) == ["point", "velocity [m s^-1]", "e", "t_c [s]", "t_c status", "error"]
    assert t["t_c status"][0].startswith("undefined: ") and math.isnan(t["t_c [s]"][0])


def test_results_and_tables_name_the_build_and_preset():
    r = gs.run("ice-bounce-8ms")
    assert r.program.startswith("grainscope ") and "(commit " in r.program
    df = r.to_frame()
    assert df.attrs["program"] == r.program and "Hysteresis" in df.attrs["preset"]
    t = gs.sweep("ice-bounce-8ms", vary={"velocity": [2.0, 8.0]}, scalars=["e"])
    assert t.attrs["program"] == r.program and "velocity" in t.attrs["preset"]


def test_morris_and_sobol_equal_the_command_lines_indices(cli, tmp_path):
    vary = {"velocity": gs.log(3, 30), "radius_1": gs.log(1e-6, 4e-6)}
    m = gs.morris("ice-bounce-8ms", vary=vary, output="e", tie={"radius_2": "radius_1"}, trajectories=6, out=tmp_path / "m")
    assert list(m.index) == ["velocity", "radius_1"]
    assert list(m.columns) == ["mu", "mu_star", "sigma", "mu_star_conf"]
    assert m.attrs["program"].startswith("grainscope") and m.attrs["runs"] == 18
    args = [
        str(cli), "sensitivity", "ice-bounce-8ms", "--method", "morris", "--samples", "6", "--vary", "velocity=log:3.0:30.0",
        "--vary", "radius_1=log:1e-06:4e-06", "--tie", "radius_2=radius_1", "--output", "e", "--out", str(tmp_path / "cli"),
    ]
    subprocess.run(args, check=True, capture_output=True)
    expected = pd.read_csv(tmp_path / "cli" / "indices.csv", index_col=0)
    # The same runs, the same indices (μ*'s interval is a bootstrap of the same seed too).
    assert np.allclose(m.to_numpy(), expected[["mu", "mu_star", "sigma", "mu_star_conf"]].to_numpy(), rtol=0, atol=0)
    assert (tmp_path / "m" / "sweep.csv").read_bytes() == (tmp_path / "cli" / "sweep.csv").read_bytes()
    # Called again on its folder, it resumes: the same frame.
    again = gs.morris("ice-bounce-8ms", vary=vary, output="e", tie={"radius_2": "radius_1"}, trajectories=6, out=tmp_path / "m")
    pd.testing.assert_frame_equal(again, m)

    total, first, second = gs.sobol("ice-bounce-8ms", vary=vary, output="e", samples=16, second_order=True, log_output=True)
    assert list(total.columns) == ["ST", "ST_conf"] and list(first.columns) == ["S1", "S1_conf"]
    assert list(second.index) == [("velocity", "radius_1")] and list(second.columns) == ["S2", "S2_conf"]
    assert total.attrs["runs"] == 16 * 6 and total.attrs["output"] == "ln e"
    assert total["ST"]["velocity"] > total["ST"]["radius_1"]


def test_sensitivity_arguments_are_checked():
    with pytest.raises(TypeError, match="vary takes a mapping"):
        gs.morris("ice-bounce-8ms", vary=[("velocity", (1, 2))], output="e")
    with pytest.raises(TypeError, match=r"vary\['velocity'\] takes"):
        gs.morris("ice-bounce-8ms", vary={"velocity": "fast"}, output="e")
    with pytest.raises(TypeError, match="output takes"):
        gs.sobol("ice-bounce-8ms", vary={"velocity": (1, 10)}, output=3)
    with pytest.raises(ValueError, match="power of two"):
        gs.sobol("ice-bounce-8ms", vary={"velocity": (1, 10)}, output="e", samples=100)
    with pytest.raises(ValueError, match="no scalar 'speed'"):
        gs.morris("ice-bounce-8ms", vary={"velocity": (1, 10)}, output="speed")
    with pytest.raises(ValueError, match="a sweep needs a count"):
        gs.sweep("ice-bounce-8ms", vary={"velocity": gs.log(1, 10)})


def test_sensitivity_spread_over_a_dask_cluster_keeps_and_resumes_its_shards(tmp_path):
    distributed = pytest.importorskip("dask.distributed")
    vary = {"velocity": gs.log(3, 30), "radius_1": gs.log(1e-6, 4e-6)}
    tie = {"radius_2": "radius_1"}
    local = gs.morris("ice-bounce-8ms", vary=vary, output="e", tie=tie, trajectories=6, out=tmp_path / "local")
    local_total, local_first = gs.sobol("ice-bounce-8ms", vary=vary, output="e", samples=16)
    grid = {"velocity": gs.lin(1.0, 10.0, 5)}
    local_sweep = gs.sweep("ice-bounce-8ms", vary=grid, scalars=["e"])
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            spread = gs.morris("ice-bounce-8ms", vary=vary, output="e", tie=tie, trajectories=6, out=tmp_path / "m", client=client, shards=3)
            # The merged folder is the unsharded run's, byte for byte, and its indices are the same.
            assert (tmp_path / "m" / "sweep.csv").read_bytes() == (tmp_path / "local" / "sweep.csv").read_bytes()
            assert sorted(p.name for p in (tmp_path / "m" / "shards").iterdir()) == ["1-of-3", "2-of-3", "3-of-3"]
            pd.testing.assert_frame_equal(spread, local)
            # A shard lost (an interrupted run): called again, only it is computed anew.
            shutil.rmtree(tmp_path / "m" / "shards" / "2-of-3")
            kept = (tmp_path / "m" / "shards" / "1-of-3" / "sweep.csv").read_bytes()
            again = gs.morris("ice-bounce-8ms", vary=vary, output="e", tie=tie, trajectories=6, out=tmp_path / "m", client=client, shards=3)
            pd.testing.assert_frame_equal(again, local)
            assert (tmp_path / "m" / "shards" / "1-of-3" / "sweep.csv").read_bytes() == kept
            total, first = gs.sobol("ice-bounce-8ms", vary=vary, output="e", samples=16, client=client)
            pd.testing.assert_frame_equal(total, local_total)
            pd.testing.assert_frame_equal(first, local_first)
            swept = gs.sweep("ice-bounce-8ms", vary=grid, scalars=["e"], out=tmp_path / "s", client=client)
            pd.testing.assert_frame_equal(swept, local_sweep, check_dtype=False)
    with pytest.raises(TypeError, match="shards takes"):
        gs.morris("ice-bounce-8ms", vary=vary, output="e", shards=0)
