"""The package over native handles: a case is parsed once and handed to
every call as it is; results arrive as the model's numbers, not as text
parsed back; the rules the command line and Python share give the same
answers from both."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from conftest import ROOT, run_cli

import soilcut
from soilcut import _soilcut


def test_a_case_holds_its_native_case_and_text(original):
    text = (ROOT / "cases/paper/original.toml").read_text()
    assert original.to_toml() == text, "the text as given, comments and all"
    assert isinstance(original._native, _soilcut.NativeCase)
    changed = original.set("run.travel", 4)
    assert changed["run.travel"] == 4 and original["run.travel"] != 4
    assert changed.to_dict()["run"]["travel"] == 4
    # Any of the three forms runs the same case.
    a = soilcut.run(changed).history["force"]
    b = soilcut.run(changed.to_toml()).history["force"]
    assert a.tolist() == b.tolist()
    with pytest.raises(TypeError, match="soilcut.Case"):
        _soilcut.run(42)


def test_files_numbers_are_the_arrays_and_dicts(tmp_path, original):
    result = soilcut.run(original.set("run.travel", 4))
    saved = result.save(tmp_path / "r", pictures=False)
    for name, arrays in [("profile.csv", result.profile), ("history.csv", result.history)]:
        lines = (saved / name).read_text().splitlines()
        assert list(arrays) == lines[0].split(",")
        columns = zip(*[[float(v) for v in line.split(",")] for line in lines[1:]])
        for (key, values), column in zip(arrays.items(), columns):
            assert values.tolist() == list(column), f"{name}: {key}"
    frames = _soilcut.csv_columns("frames.csv", (saved / "frames.csv").read_text())
    assert sum(len(f.x) for f in result.frames) == len(frames["x"])
    assert np.concatenate([f.y for f in result.frames]).tolist() == frames["y"].tolist()
    assert json.loads((saved / "summary.json").read_text()) == result.summary


def test_a_failed_advance_keeps_its_records(original):
    # A bin two increments longer than the travel: the last increments find
    # no mechanism before the wall.
    inc, d = original["run.increment"], original["blade.depth"]
    # (The increment given: in a bin the original model's default is finer.)
    case = original.update(
        {"run.travel": 4 * d, "run.increment": inc, "bin.length": 4 * d + 2 * inc}
    )
    sim = soilcut.Simulation(case)
    sim.advance_to(d)
    before = sim.steps_done
    with pytest.raises(soilcut.StepError, match="bin.length") as raised:
        sim.advance_to(4 * d)
    steps = raised.value.steps
    assert len(steps) == sim.steps_done - before > 0
    assert [s.step for s in steps] == list(range(before + 1, sim.steps_done + 1))
    assert steps[-1].u == pytest.approx(sim.blade_position - inc)


def test_bad_arguments_name_themselves_and_the_simulation_has_a_repr(original):
    sim = soilcut.Simulation(original.set("run.travel", 1))
    with pytest.raises(ValueError, match=r"^advance: n must be a whole number >= 0 .*got -1$"):
        sim.advance(-1)
    with pytest.raises(TypeError, match="^advance_to: x must be a number .*not str$"):
        sim.advance_to("40")
    with pytest.raises(TypeError, match="^advance_to: depth must be a number"):
        sim.advance_to(1, depth="deep")
    assert sim.steps_done == 0
    sim.advance(2)
    assert repr(sim) == (
        f'Simulation("original": 2 of {sim.steps} increments, u = {sim.blade_position}, '
        f"tip depth {sim.tip_depth})"
    )


def test_sweep_tuples_obey_the_spec_rules(original):
    case = original.set("run.travel", 1)
    for spec, words in [
        ((37, 33, 3), "hi must be >= lo"),
        ((33, 37, 0), "whole number >= 1"),
        ((33, 37, 2.5), "whole number >= 1"),
        ((33, 33, 3), "needs hi > lo"),
        (("a", 37), "lo of"),
        ((math.nan, 37), "not a finite number"),
        ([], "no values"),
    ]:
        with pytest.raises(ValueError, match=words):
            soilcut.sweep(case, {"soil.friction.peak": spec})


def test_a_sweep_row_is_numbered_from_one(original):
    native = original._native
    with pytest.raises(ValueError, match="from 1 to total"):
        _soilcut.sweep_row(native, ["soil.friction.peak"], [35.0], 0, 1)
    short = original.set("run.travel", 1)._native
    row, _ = _soilcut.sweep_row(short, ["soil.friction.peak"], [35.0], 1, 1)
    assert list(row)[:4] == ["run", "soil.friction.peak", "status", "error"]
    assert row["run"] == [1]


def test_landscape_at_is_checked_as_the_command_line_checks_it(original, cli):
    last = original["run.travel"] / original["blade.depth"]
    with pytest.raises(ValueError) as ours:
        soilcut.landscape(original, last + 1)
    theirs = run_cli(
        cli,
        "landscape",
        str(ROOT / "cases/paper/original.toml"),
        "--at",
        str(last + 1),
        check=False,
    )
    assert theirs.returncode == 2
    rule = str(ours.value).removeprefix("at ")
    assert rule.startswith("must be a number from 0 to run.travel / blade.depth = ")
    assert f"--at {rule}" in theirs.stderr
