"""examples/mpc.py runs shortened: its chosen depth path keeps the draft
under the limit, scores at least the constant depth's soil moved per unit
of work, and its picture is written."""

from __future__ import annotations

import importlib.util
import sys

import numpy as np
import pytest
from conftest import ROOT

pytest.importorskip("matplotlib")


def load_mpc():
    spec = importlib.util.spec_from_file_location("mpc", ROOT / "examples" / "mpc.py")
    mpc = importlib.util.module_from_spec(spec)
    sys.modules["mpc"] = mpc  # dataclasses look their module up there
    spec.loader.exec_module(mpc)
    return mpc


def test_without_matplotlib_it_stops_before_planning(tmp_path, capsys, monkeypatch):
    mpc = load_mpc()
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(SystemExit) as stop:
        mpc.main(["--quick", "--out", str(tmp_path / "mpc.png")])
    assert stop.value.code == 2
    said = capsys.readouterr()
    assert "pip install matplotlib" in said.err and "planning" not in said.out


def test_the_planner_obeys_the_limit_and_beats_the_constant_depth(tmp_path, capsys):
    mpc = load_mpc()
    out = tmp_path / "mpc.png"
    figures = mpc.main(["--quick", "--out", str(out)])
    assert out.stat().st_size > 10_000 and out.read_bytes()[:4] == b"\x89PNG"
    assert figures["peak"] <= figures["limit"]
    assert figures["objective"] >= figures["baseline_objective"]
    # The planner steered: its path is not the constant depth.
    assert np.ptp(figures["depth"]) > 0.05 * mpc.D
    np.testing.assert_allclose(figures["u"], figures["baseline_u"])
    assert "planned:" in capsys.readouterr().out
