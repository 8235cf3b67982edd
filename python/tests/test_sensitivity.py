"""`soilcut sensitivity`'s indices equal SALib's on the same samples: the
command's samples.csv (inputs and outputs of every run, in the design's
order) handed to SALib's analyzers, the command's indices.csv beside them.
The test function runs through the command's hidden `--function` option."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import case_path, run_cli

SALib = pytest.importorskip("SALib")
from SALib.analyze import morris, sobol  # noqa: E402

KEYS = ["x1", "x2", "x3"]
PROBLEM = {"num_vars": 3, "names": KEYS, "bounds": [[-math.pi, math.pi]] * 3}


def study(
    cli: str, tmp_path, method: str, samples: int, *extra: str
) -> tuple[pd.DataFrame, pd.DataFrame]:
    out = tmp_path / method
    vary = [a for k in KEYS for a in ("--vary", f"{k}={-math.pi!r}:{math.pi!r}")]
    run_cli(
        cli,
        "sensitivity",
        str(case_path("paper/fig5.toml")),
        "--function",
        "ishigami",
        "--method",
        method,
        "--samples",
        str(samples),
        "--seed",
        "5",
        "-q",
        "--out",
        str(out),
        *vary,
        *extra,
    )
    return pd.read_csv(out / "samples.csv"), pd.read_csv(out / "indices.csv")


def test_sobol_indices_equal_salib_s(cli, tmp_path):
    samples, indices = study(cli, tmp_path, "sobol", 1024)
    y = samples["f"].to_numpy()
    si = sobol.analyze(PROBLEM, y, calc_second_order=False)
    np.testing.assert_allclose(indices["S1"], si["S1"], rtol=0, atol=1e-10)
    np.testing.assert_allclose(indices["ST"], si["ST"], rtol=0, atol=1e-10)
    # The intervals are bootstraps of other resamples: alike, not equal.
    half = (indices["S1_high"] - indices["S1_low"]) / 2
    assert np.all(np.abs(half / si["S1_conf"] - 1) < 0.3)


def test_second_order_indices_equal_salib_s(cli, tmp_path):
    samples, indices = study(cli, tmp_path, "sobol", 1024, "--second-order")
    y = samples["f"].to_numpy()
    assert len(y) == 1024 * (2 * len(KEYS) + 2)
    si = sobol.analyze(PROBLEM, y, calc_second_order=True)
    np.testing.assert_allclose(indices["S1"], si["S1"], rtol=0, atol=1e-10)
    np.testing.assert_allclose(indices["ST"], si["ST"], rtol=0, atol=1e-10)
    pairs = pd.read_csv(tmp_path / "sobol" / "indices2.csv")
    theirs = [si["S2"][KEYS.index(a), KEYS.index(b)] for a, b in zip(pairs["key"], pairs["key2"])]
    assert list(zip(pairs["key"], pairs["key2"])) == [("x1", "x2"), ("x1", "x3"), ("x2", "x3")]
    np.testing.assert_allclose(pairs["S2"], theirs, rtol=0, atol=1e-10)


def test_morris_indices_equal_salib_s(cli, tmp_path):
    samples, indices = study(cli, tmp_path, "morris", 30, "--levels", "4")
    x = samples[KEYS].to_numpy()
    y = samples["f"].to_numpy()
    si = morris.analyze(PROBLEM, x, y, num_levels=4)
    for ours, theirs in [("mu_star", "mu_star"), ("sigma", "sigma"), ("mu", "mu")]:
        np.testing.assert_allclose(indices[ours], si[theirs], rtol=0, atol=1e-10)
