"""Ensembles: ``soilcut.run(case, ensemble=N)`` equals ``soilcut run CASE
--ensemble N`` bit for bit, its spread is that of its members, and bad
arguments are ``ValueError``s."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import case_path, run_cli

import soilcut

SHORT = ["run.travel=20", "run.increment=0.2"]


def short(path: str) -> soilcut.Case:
    return soilcut.Case.from_file(case_path(path)).set("run.travel", 20).set("run.increment", 0.2)


def test_the_ensemble_is_the_command_lines_bit_for_bit(cli, tmp_path):
    args = ["run", str(case_path("paper/table1-s.toml")), "--ensemble", "3", "--no-plots", "-q"]
    for s in SHORT:
        args += ["--set", s]
    run_cli(cli, *args, "--out", str(tmp_path / "cli"))
    ens = soilcut.run(short("paper/table1-s.toml"), ensemble=3, jobs=2)
    saved = ens.save(tmp_path / "py", pictures=False)
    for name in ["ensemble.csv", "summary.json", "k-1/history.csv", "k+1/case.resolved.toml"]:
        assert (saved / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    assert ens.folders == ["k-1", "k+0", "k+1"]


def test_spread_of_the_members_window_means():
    ens = soilcut.run(short("paper/table1-hs.toml"), ensemble=4)
    assert isinstance(ens, soilcut.Ensemble)
    assert len(ens.members) == 4
    d = 20.0
    for w in range(len(ens.windows["mean"])):
        means = []
        for m in ens.members:
            u, f = m.history["u"], m.history["force_norm"]
            means.append(f[np.floor(u / d) == w].mean())
        assert ens.windows["mean"][w] == pytest.approx(np.mean(means), rel=1e-12)
        assert ens.windows["std"][w] == pytest.approx(np.std(means, ddof=1), rel=1e-9, abs=1e-15)
        # NumPy sums a window in another order than Rust: equal to round-off.
        assert ens.windows["min"][w] == pytest.approx(min(means), rel=1e-12)
    d50 = [m.case.to_dict()["soil"]["d50"] for m in ens.members]
    assert d50 == pytest.approx([0.6 * (1 + 0.001 * k) for k in (-2, -1, 0, 1)], rel=1e-15)
    assert ens.summary["perturbation"]["key"] == "soil.d50"
    assert "Ensemble('table1-hs': 4 members" in repr(ens)


def test_member_zero_is_the_plain_run():
    case = short("paper/original.toml")
    ens = soilcut.run(case, ensemble=3)
    alone = soilcut.run(case)
    np.testing.assert_array_equal(ens.members[1].history["force"], alone.history["force"])
    assert ens.summary["perturbation"]["key"] == "blade.wall_friction"


@pytest.mark.parametrize("bad", [1, 0, -3, 2.5, "7", True])
def test_bad_member_counts_are_value_errors(bad):
    with pytest.raises(ValueError, match="ensemble"):
        soilcut.run(short("paper/original.toml"), ensemble=bad)


def test_bad_jobs_are_value_errors():
    with pytest.raises(ValueError, match="jobs"):
        soilcut.run(short("paper/original.toml"), ensemble=3, jobs=-1)
