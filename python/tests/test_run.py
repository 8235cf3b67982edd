"""Runs: the Python results equal the command line's files bit for bit, and
stepping a Simulation gives the run's history."""

from __future__ import annotations

import json
import pickle
import threading
import warnings

import numpy as np
import pytest
from conftest import case_path, run_cli

import soilcut

FILES = ["history.csv", "profile.csv", "frames.csv", "case.resolved.toml"]


def cli_run(cli, path, out, *sets, plots=False):
    args = ["run", str(path), "--out", str(out), "-q"]
    for s in sets:
        args += ["--set", s]
    if not plots:
        args.append("--no-plots")
    run_cli(cli, *args)


@pytest.mark.parametrize(
    "path,sets",
    [
        ("paper/original.toml", []),
        ("paper/table1-hs.toml", ["run.increment=0.2"]),
        ("tools/inclined.toml", ["run.increment=0.2"]),
        ("tools/scoop.toml", ["run.increment=0.2"]),
    ],
)
def test_save_writes_the_cli_folder_bit_for_bit(cli, tmp_path, path, sets):
    case = soilcut.Case.from_file(case_path(path))
    for s in sets:
        key, value = s.split("=")
        case = case.set(key, float(value))
    cli_run(cli, case_path(path), tmp_path / "cli", *sets)
    saved = soilcut.run(case).save(tmp_path / "py", pictures=False)
    for name in FILES:
        assert (saved / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    ours = json.loads((saved / "summary.json").read_text())
    theirs = json.loads((tmp_path / "cli" / "summary.json").read_text())
    del ours["wall_time_s"], theirs["wall_time_s"]
    assert ours == theirs


def test_pictures_are_the_cli_pictures(cli, tmp_path, original):
    case = original.set("run.travel", 4)
    cli_run(cli, case_path("paper/original.toml"), tmp_path / "cli", "run.travel=4", plots=True)
    saved = soilcut.run(case).save(tmp_path / "py")
    pictures = sorted(p.relative_to(tmp_path / "cli") for p in (tmp_path / "cli").rglob("*"))
    pictures = [p for p in pictures if p.suffix in (".png", ".svg", ".gif")]
    assert len(pictures) >= 7
    for p in pictures:
        assert (saved / p).read_bytes() == (tmp_path / "cli" / p).read_bytes(), p


def test_save_refuses_an_occupied_folder(tmp_path, original):
    result = soilcut.run(original.set("run.travel", 1))
    result.save(tmp_path / "a", pictures=False)
    with pytest.raises(FileExistsError):
        result.save(tmp_path / "a", pictures=False)
    result.save(tmp_path / "a", pictures=False, force=True)


def test_a_folder_save_cannot_use_is_named_in_python_words(tmp_path, original):
    result = soilcut.run(original.set("run.travel", 1))
    for folder in [f"{tmp_path}/..", str(tmp_path / ("n" * 256))]:
        with pytest.raises(ValueError) as raised:
            result.save(folder, pictures=False)
        assert "--out" not in str(raised.value) and "folder" in str(raised.value)


def test_force_replaces_only_a_folder_soilcut_wrote(tmp_path, original):
    result = soilcut.run(original.set("run.travel", 1))
    notes = tmp_path / "notes.txt"
    notes.write_text("mine")
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("mine")
    with pytest.raises(FileExistsError, match="not a folder"):
        result.save(notes, pictures=False, force=True)
    with pytest.raises(FileExistsError, match="soilcut did not write it"):
        result.save(mine, pictures=False, force=True)
    assert notes.read_text() == "mine" and (mine / "notes.txt").read_text() == "mine"


def test_a_run_that_stops_keeps_its_increments(tmp_path, original):
    # A bin two increments longer than the travel: the last increments find
    # no mechanism before the wall.
    inc, d = original["run.increment"], original["blade.depth"]
    # (The increment given: in a bin the original model's default is finer.)
    case = original.update(
        {"run.travel": 4 * d, "run.increment": inc, "bin.length": 4 * d + 2 * inc}
    )
    with pytest.raises(soilcut.StepError, match="bin.length") as raised:
        soilcut.run(case)
    result = raised.value.result
    stopped = result.summary["stopped"]
    assert stopped["increment"] == result.summary["steps"] + 1 == len(result.history["step"]) + 1
    assert "bin.length" in stopped["reason"]
    saved = result.save(tmp_path / "r", pictures=False)
    assert json.loads((saved / "summary.json").read_text())["stopped"] == stopped
    assert "stopped" not in soilcut.run(original.set("run.travel", 1)).summary


def test_arrays_are_the_files_numbers(tmp_path, refined):
    result = soilcut.run(refined)
    saved = result.save(tmp_path / "r", pictures=False)
    lines = (saved / "history.csv").read_text().splitlines()
    header = lines[0].split(",")
    assert list(result.history) == header
    rows = [[float(v) for v in line.split(",")] for line in lines[1:]]
    for k, name in enumerate(header):
        assert result.history[name].tolist() == [r[k] for r in rows], name
    assert result.history["step"].dtype == np.int64
    assert len(result.profile["x"]) == len((saved / "profile.csv").read_text().splitlines()) - 1
    assert result.frames[0].step == 0 and result.frames[-1].step == result.summary["steps"]
    assert result.summary["steps"] == len(result.history["u"])


def test_stepping_gives_the_run(refined):
    result = soilcut.run(refined)
    sim = soilcut.Simulation(refined)
    assert sim.steps == result.summary["steps"] and sim.steps_done == 0
    records = list(sim)
    assert sim.is_done and sim.steps_done == len(records)
    for name in [
        "u",
        "force",
        "force_norm",
        "force_h",
        "force_v",
        "beta_deg",
        "x_emergence",
        "y_emergence",
        "friction_deg",
        "slip",
        "dilation_deg",
        "dilation_area",
        "mass",
        "depth",
    ]:
        assert [getattr(r, name) for r in records] == result.history[name].tolist(), name
    assert [r.step for r in records] == result.history["step"].tolist()
    surface = sim.surface()
    for name, column in result.profile.items():
        assert surface[name].tolist() == column.tolist(), name
    assert sim.case == refined.resolved()


def test_advance_and_step_agree(refined):
    a, b = soilcut.Simulation(refined), soilcut.Simulation(refined)
    assert a.advance(7) == 7
    for _ in range(7):
        b.step()
    assert a.blade_position == b.blade_position and a.mass == b.mass
    assert a.step().force == b.step().force
    assert a.advance(10**9) == a.steps - 8 and a.is_done
    with pytest.raises(soilcut.StepError, match="travel has been reached"):
        a.step()
    assert a.steps_done == a.steps, "a refused step changes nothing"


def test_results_pickle(refined):
    result = soilcut.run(refined)
    again = pickle.loads(pickle.dumps(result))
    assert again.case == result.case and again.summary == result.summary
    for name in result.history:
        assert np.array_equal(again.history[name], result.history[name])


def test_runs_in_threads_give_the_same_history(refined):
    """The interpreter is released while a case runs: threads run cases side
    by side, and each result is the one of a lone run."""
    alone = soilcut.run(refined).history["force"]
    results = [None] * 3

    def work(i):
        results[i] = soilcut.run(refined).history["force"]

    threads = [threading.Thread(target=work, args=(i,)) for i in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        assert np.array_equal(r, alone)


def test_history_frame(refined):
    pd = pytest.importorskip("pandas")
    frame = soilcut.run(refined).history_frame()
    assert isinstance(frame, pd.DataFrame) and frame.columns[0] == "step"


def test_a_blade_flatter_than_the_repose_runs_in_both_front_ends(cli, original):
    """A scraper raked at 30° in sand of 30° repose: the command line's check
    and the Python package accept it alike, and it cuts."""
    case = original.update({"blade.rake": 30, "blade.wall_friction": 5})
    path = case_path("paper/original.toml")
    done = run_cli(
        cli,
        "check",
        str(path),
        "--set",
        "blade.rake=30",
        "--set",
        "blade.wall_friction=5",
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert soilcut.Simulation(case).step().force > 0
    with pytest.raises(soilcut.CaseError, match="line 1"):
        soilcut.Simulation("name = = 2")


def test_a_narrow_tine_warns_as_the_cli_does(original):
    narrow = original.update({"blade.width": 1.0, "run.travel": 4})
    with pytest.warns(soilcut.AccuracyWarning, match="blade.width = 1"):
        soilcut.run(narrow)
    with pytest.warns(soilcut.AccuracyWarning):
        soilcut.Simulation(narrow)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        soilcut.Simulation(narrow.set("blade.width", 20.0))


def test_an_old_node_grid_key_warns_and_runs_on_the_node_grid(original):
    old = original.update({"run.vertex_spacing": 0.0, "run.travel": 4})
    with pytest.warns(soilcut.CaseFormWarning, match='write run.ground = "nodes"'):
        records = soilcut.run(old)
    assert records.case["run.ground"] == "nodes"
    with pytest.raises(soilcut.CaseError, match="run.vertex_spacing"):
        original.update({"run.ground": "nodes", "run.vertex_spacing": 0.4})
