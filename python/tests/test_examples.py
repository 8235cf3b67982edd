"""The example notebook runs top to bottom without an error, and names
what it needs besides the package."""

from __future__ import annotations

import json
import re
import sys

import pytest
import tomllib
from conftest import ROOT

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")


def test_the_notebook_runs(monkeypatch):
    # Headless here; the notebook itself picks no backend, so that Jupyter
    # shows its figures inline.
    monkeypatch.setenv("MPLBACKEND", "Agg")
    path = ROOT / "examples" / "soilcut.ipynb"
    notebook = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(
        notebook,
        timeout=300,
        kernel_name="python3",
        resources={"metadata": {"path": str(path.parent)}},
    )
    client.execute()  # raises CellExecutionError on any error
    outputs = [o for c in notebook.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "200 runs" in text and "FitResult" in text


def test_the_notebook_leaves_the_backend_to_jupyter():
    cells = json.loads((ROOT / "examples" / "soilcut.ipynb").read_text(encoding="utf-8"))["cells"]
    code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    assert "import matplotlib.pyplot as plt" in code
    assert "matplotlib.use(" not in code, "a backend set in the notebook hides its figures"


def test_the_examples_extra_installs_what_the_examples_import():
    project = tomllib.loads((ROOT / "python" / "pyproject.toml").read_text(encoding="utf-8"))
    extra = {
        re.split(r"[<>=\[ ]", r)[0] for r in project["project"]["optional-dependencies"]["examples"]
    }
    cells = json.loads((ROOT / "examples" / "soilcut.ipynb").read_text(encoding="utf-8"))["cells"]
    code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    code += (ROOT / "examples" / "mpc.py").read_text(encoding="utf-8")
    imported = set(re.findall(r"^\s*(?:import|from)\s+(\w+)", code, re.M))
    needed = imported - set(sys.stdlib_module_names) - {"numpy", "soilcut", "__future__"}
    assert needed and needed <= extra, (needed, extra)
    first = "".join(cells[0]["source"])
    assert 'pip install "./python[examples]"' in first
