"""Snapshots, copies and pickles of a Simulation continue bit for bit as
the original would, bad bytes raise soilcut.SnapshotError, and advance_to
lands where its rule says (docs/model.md §17)."""

from __future__ import annotations

import copy
import math
import pickle

import numpy as np
import pytest
from conftest import case_path

import soilcut

FIELDS = soilcut.Step.fields


def row(step: soilcut.Step) -> tuple:
    return tuple(getattr(step, name) for name in FIELDS)


def rest(sim: soilcut.Simulation) -> tuple[list[tuple], dict[str, list]]:
    rows = [row(s) for s in sim]
    return rows, {k: v.tolist() for k, v in sim.surface().items()}


@pytest.fixture
def short() -> soilcut.Case:
    """The original model's case over 2 d at d/50."""
    case = soilcut.Case.from_file(case_path("paper/original.toml"))
    return case.update({"run.travel": 40.0, "run.increment": 0.4})


def test_every_kind_of_copy_continues_bit_for_bit(short):
    sim = soilcut.Simulation(short)
    sim.advance(30)
    branches = [
        soilcut.Simulation.from_snapshot(sim.snapshot()),
        copy.copy(sim),
        copy.deepcopy(sim),
        pickle.loads(pickle.dumps(sim)),
    ]
    expected = rest(sim)
    assert len(expected[0]) == 70
    for branch in branches:
        assert branch.steps_done == 30
        assert rest(branch) == expected


def test_branches_share_nothing(short):
    sim = soilcut.Simulation(short)
    sim.advance(10)
    branch = copy.copy(sim)
    branch.advance(5)
    assert (sim.steps_done, branch.steps_done) == (10, 15)
    assert sim.snapshot() != branch.snapshot()
    assert soilcut.Simulation.from_snapshot(sim.snapshot()).snapshot() == sim.snapshot()


def test_the_case_comes_back_as_steered(short):
    sim = soilcut.Simulation(short)
    sim.advance_to(10.0, depth=15.0)
    restored = pickle.loads(pickle.dumps(sim))
    assert restored.case == sim.case
    assert restored.case["blade.depth_path"][-1] == [10.0, 15.0]
    assert restored.tip_depth == 15.0


@pytest.mark.parametrize(
    "spoil,words",
    [
        (lambda b: b"", "not a soilcut snapshot"),
        (lambda b: b"pickle or something else", "not a soilcut snapshot"),
        (lambda b: b[: len(b) // 2], "truncated"),
        (lambda b: b[:-3], "truncated"),
        (lambda b: b + b"\0", "after its end"),
        (lambda b: b[:200] + bytes([b[200] ^ 1]) + b[201:], "corrupt"),
        (lambda b: b[:8] + (99).to_bytes(4, "little") + b[12:], "another version"),
    ],
)
def test_bad_bytes_raise_snapshot_error(short, spoil, words):
    data = soilcut.Simulation(short).snapshot()
    with pytest.raises(soilcut.SnapshotError, match=words) as raised:
        soilcut.Simulation.from_snapshot(spoil(data))
    assert isinstance(raised.value, ValueError)


def test_advance_to_lands_on_the_first_whole_increment_at_or_beyond_x(short):
    sim, stepped = soilcut.Simulation(short), soilcut.Simulation(short)
    v0 = 0.4
    for x, done in [(2.5 * v0, 3), (5 * v0, 5), (4.5 * v0, 5), (12.01, 31)]:
        records = sim.advance_to(x)
        assert sim.steps_done == done
        assert x * (1 - 1e-9) <= sim.blade_position < x + v0
        expected = [row(stepped.step()) for _ in range(done - stepped.steps_done)]
        assert [row(r) for r in records] == expected
    assert rest(sim) == rest(stepped)


def test_advance_to_steers_the_tip_and_goes_beyond_the_travel(short):
    sim = soilcut.Simulation(short)
    sim.advance_to(10.0)
    records = sim.advance_to(20.0, depth=12.0)
    depths = np.array([r.depth for r in records])
    line = 20.0 + (12.0 - 20.0) * (np.array([r.u for r in records]) - 10.0) / 10.0
    np.testing.assert_allclose(depths, line, rtol=0, atol=1e-9)
    assert sim.tip_depth == 12.0
    sim.advance_to(50.0, depth=20.0)
    assert sim.is_done and sim.case["run.travel"] == 50.0
    assert sim.steps == sim.steps_done == 125
    with pytest.raises(soilcut.StepError, match="travel has been reached"):
        sim.step()


def test_advance_to_refuses_bad_arguments(short):
    sim = soilcut.Simulation(short)
    sim.advance_to(8.0)
    before = sim.snapshot()
    for x in [math.nan, -1.0, 4.0]:
        with pytest.raises(ValueError, match="advance_to: x"):
            sim.advance_to(x)
    for depth in [math.nan, 0.0, 25.0]:
        with pytest.raises(ValueError, match="advance_to: depth"):
            sim.advance_to(12.0, depth=depth)
    assert sim.snapshot() == before
    raked = soilcut.Simulation(short.set("blade.rake", 60.0))
    with pytest.raises(soilcut.CaseError, match="vertical") as raised:
        raked.advance_to(4.0, depth=15.0)
    assert raised.value.key == "blade.depth_path"
