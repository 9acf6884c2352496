"""The example notebook runs top to bottom (its cells assert what they show)."""

import os
import pathlib

import nbformat
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "examples" / "grainscope-from-python.ipynb"


def test_the_example_notebook_runs_top_to_bottom(tmp_path):
    nbclient = pytest.importorskip("nbclient")
    nb = nbformat.read(NOTEBOOK, as_version=4)
    # Run where the notebook lies, as a reader would; its files go to a scratch copy.
    work = tmp_path / "examples"
    work.mkdir()
    nbclient.NotebookClient(nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(work)}}).execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []) if o.output_type == "error"]
    assert not errors
    pictures = sum("image/png" in o.get("data", {}) for c in nb.cells for o in c.get("outputs", []))
    assert pictures >= 4, pictures
    kept = os.environ.get("NOTEBOOK_OUT")
    if kept:
        pathlib.Path(kept).parent.mkdir(parents=True, exist_ok=True)
        nbformat.write(nb, kept)
