"""A blade of finite width from Python: the run is the command line's bit
for bit, the first force is McKyes & Ali's closed form, spilled soil is
conserved, a sweep takes ``blade.width`` like any key, and a blade narrower
than the crescents describe warns."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from conftest import case_path, run_cli

import soilcut

SHORT = {"run.travel": 60.0, "run.increment": 0.3}


def tine(**sets):
    case = soilcut.Case.from_file(case_path("tools/tine.toml"))
    for key, value in {**SHORT, **sets}.items():
        case = case.set(key, value)
    return case


def test_the_tine_is_the_cli_run(cli, tmp_path):
    args = ["run", str(case_path("tools/tine.toml")), "--out", str(tmp_path / "cli"), "-q"]
    for key, value in SHORT.items():
        args += ["--set", f"{key}={value}"]
    run_cli(cli, *args, "--no-plots")
    saved = soilcut.run(tine()).save(tmp_path / "py", pictures=False)
    for name in ["history.csv", "profile.csv"]:
        assert (saved / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name


def test_first_force_is_mckyes_ali_and_mass_is_conserved():
    case = tine()
    result = soilcut.run(case)
    h = result.history
    closed = soilcut.analytic(case)["mckyes_ali"]
    # The grid's angles are d/500 apart: second order in the angle step.
    assert h["force"][0] == pytest.approx(closed["force"], rel=1e-5)
    assert h["force"][0] >= closed["force"] * (1 - 1e-12)
    assert closed["force"] > 5 * soilcut.analytic(case)["fee"]["force"] * case["blade.width"]
    total = h["mass"] + h["mass_spilled"]
    assert h["mass_spilled"][-1] > 0
    assert np.all(np.abs(total - total[0]) <= 1e-11 * total[0])
    assert result.profile["ridge_height"].max() > 0


def test_a_sweep_over_the_width_narrows_the_force_per_width():
    widths = [25.0, 75.0, 300.0]
    rows = soilcut.sweep(tine(), {"blade.width": widths}, jobs=1)
    assert list(rows["status"]) == ["ok"] * 3
    # force_norm is P/(γ0 d² w): the narrower blade carries more per width.
    assert list(rows["initial_force_norm"]) == sorted(rows["initial_force_norm"], reverse=True)


def test_a_blade_narrower_than_a_sixth_of_its_depth_warns():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        soilcut.Simulation(tine(**{"blade.width": 20.0}))
    assert any(issubclass(w.category, soilcut.AccuracyWarning) for w in caught)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        soilcut.Simulation(tine())


def test_a_bad_width_names_the_key():
    with pytest.raises(soilcut.CaseError, match="blade.width") as e:
        soilcut.Simulation(tine(**{"blade.width": -1.0}))
    assert e.value.key == "blade.width"
    assert isinstance(e.value, ValueError)


def test_fit_refuses_a_second_width():
    case = tine()
    h = soilcut.run(case).history
    with pytest.raises(ValueError, match="blade.width"):
        soilcut.fit(case, (h["u"], h["force"]), ["soil.friction.peak"], width=50.0)
