"""A controller commands a depth at every tick of 1 kHz, most ticks between
increments: the command holds until the next increment takes it, and the
session runs as the case it leaves (docs/model.md §17.2, issue 50 item 7)."""

from __future__ import annotations

import math

from conftest import case_path

import soilcut


def row(step: soilcut.Step) -> tuple:
    return tuple(getattr(step, name) for name in soilcut.Step.fields)


def test_a_1khz_controller_runs_as_its_steered_case():
    case = soilcut.Case.from_file(case_path("paper/fig5.toml"))
    d = case["blade.depth"]
    sim = soilcut.Simulation(case)
    records = []
    ticks = 3000  # d/1000 a tick, to 3 d
    for k in range(1, ticks + 1):
        # The tip along a half sine from d up to 0.8 d and back.
        depth = d * (1 - 0.2 * math.sin(math.pi * k / ticks))
        records += sim.advance_to(k * d / 1000, depth=depth)
    assert sim.blade_position >= 3 * d * (1 - 1e-9)
    assert min(r.depth for r in records) < 0.81 * d
    steered = soilcut.Simulation(sim.case)
    again = steered.advance_to(sim.blade_position)
    assert [row(r) for r in again] == [row(r) for r in records]


def test_a_depth_between_increments_is_held_for_the_next_one():
    case = soilcut.Case.from_file(case_path("paper/original.toml"))
    case = case.update({"run.travel": 40.0, "run.increment": 0.4})
    sim = soilcut.Simulation(case)
    sim.advance_to(1.0)
    assert sim.blade_position == 1.2000000000000002
    assert sim.advance_to(1.1, depth=18.0) == []
    assert sim.tip_depth == 20.0
    sim.step()
    assert sim.tip_depth == 18.0
