"""Sweeps (threads, process pools, a Dask cluster), calibration and the
analytical baselines, against the command line and closed forms."""

from __future__ import annotations

import concurrent.futures
import math

import numpy as np
import pytest
from conftest import ROOT, run_cli

import soilcut

pd = pytest.importorskip("pandas")

REFINED = ROOT / "crates/io/testdata/refined.toml"
SHORT = {"run.travel": 10, "run.increment": 1}
# The same settings as the command line's options.
SHORT_SETS = [arg for key, value in SHORT.items() for arg in ("--set", f"{key}={value}")]
VARY = {"soil.friction.peak": "31:40", "soil.friction.initial": [20, 33]}


def short(refined):
    return refined.update(SHORT)


def read(path):
    """sweep.csv as the command line wrote it, its figures as float64 (as
    the Python sweep hands them out, from the numbers themselves)."""
    header = open(path, encoding="utf-8").readline().strip().split(",")
    figures = dict.fromkeys(header[header.index("error") + 1 :], "float64")
    return pd.read_csv(path, keep_default_na=False, na_values=[""], dtype=figures)


def test_sweep_is_the_cli_sweep(cli, tmp_path, refined):
    ours = soilcut.sweep(short(refined), VARY, sample="lhs:6", seed=4, jobs=2)
    out = tmp_path / "cli"
    run_cli(
        cli,
        "sweep",
        str(REFINED),
        "--vary",
        "soil.friction.peak=31:40",
        "--vary",
        "soil.friction.initial=20,33",
        "--sample",
        "lhs:6",
        "--seed",
        "4",
        *SHORT_SETS,
        "--out",
        str(out),
    )
    theirs = read(out / "sweep.csv")
    pd.testing.assert_frame_equal(ours, theirs)
    assert list(ours["run"]) == list(range(1, 7))
    above_peak = ours["soil.friction.initial"] > ours["soil.friction.peak"]
    assert list(ours["status"] == "failed") == list(above_peak), "φc > φp is refused"


def test_a_failed_run_is_a_row(refined):
    frame = soilcut.sweep(short(refined), {"soil.friction.initial": [20, 50]}, jobs=1)
    assert list(frame["status"]) == ["ok", "failed"]
    assert frame["error"][1].startswith("soil.friction.initial: ")
    assert math.isnan(frame["max_force_norm"][1])


def test_samples_and_tuples(refined):
    # At this increment (d/20) half an increment of hardening is about 4°
    # of φ, so the midpoint force (the vertex ground's default) overshoots
    # where a band re-shears hardening soil (docs/model.md §2.12): the
    # stronger soil's larger force is the explicit rule's claim here.
    case = short(refined).update({"run.time_scheme": "explicit"})
    grid = soilcut.sweep(case, {"soil.friction.peak": (33, 37, 3)}, jobs=1)
    assert list(grid["soil.friction.peak"]) == [33.0, 35.0, 37.0]
    listed = soilcut.sweep(case, samples=[{"soil.friction.peak": v} for v in (33.0, 35.0, 37.0)])
    pd.testing.assert_frame_equal(grid, listed)
    peaks = grid["max_force_norm"].to_numpy()
    assert peaks[0] < peaks[1] < peaks[2], "a stronger soil needs a larger force"
    with pytest.raises(ValueError, match="lo:hi:n"):
        soilcut.sweep(case, {"soil.friction.peak": "x:y:z"})
    with pytest.raises(ValueError, match="either vary"):
        soilcut.sweep(case)


def test_a_key_not_of_the_case_is_refused_before_any_run(refined, monkeypatch):
    def no_run(*args):
        raise AssertionError("a run was started")

    monkeypatch.setattr(soilcut._study, "_sweep_row", no_run)
    case = short(refined)
    for spec in (
        {"vary": {"soil.frict": "30:40:2"}},
        {"vary": {"soil.frict": [30, 40]}, "executor": concurrent.futures.ThreadPoolExecutor(1)},
        {"samples": [{"soil.frict": 30}]},
    ):
        with pytest.raises(soilcut.CaseError, match="nearest: `soil.friction`") as e:
            soilcut.sweep(case, **spec)
        assert e.value.key == "soil.frict"


def test_without_pandas_a_sweep_fails_before_its_runs(refined, monkeypatch):
    def no_run(*args):
        raise AssertionError("a run was started")

    monkeypatch.setattr(soilcut._study._soilcut, "sweep_run", no_run)
    monkeypatch.setitem(__import__("sys").modules, "pandas", None)
    with pytest.raises(ImportError, match=r"soilcut\[pandas\]"):
        soilcut.sweep(short(refined), {"soil.friction.peak": [33]})


def test_a_process_pool_gives_the_thread_result(refined):
    case = short(refined)
    alone = soilcut.sweep(case, VARY, sample="lhs:6", seed=4, jobs=1)
    with concurrent.futures.ProcessPoolExecutor(2) as pool:
        spread = soilcut.sweep(case, VARY, sample="lhs:6", seed=4, executor=pool)
    pd.testing.assert_frame_equal(alone, spread)


def test_a_dask_cluster_gives_the_thread_result(refined):
    distributed = pytest.importorskip("distributed")
    case = short(refined)
    alone = soilcut.sweep(case, VARY, sample="lhs:8", seed=1, jobs=1)
    with (
        distributed.LocalCluster(
            processes=True, n_workers=2, threads_per_worker=1, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        spread = soilcut.sweep(case, VARY, sample="lhs:8", seed=1, executor=client.get_executor())
        workers = client.run(lambda: __import__("os").getpid())
    assert len(set(workers.values())) == 2, "two worker processes"
    pd.testing.assert_frame_equal(alone, spread)


def test_fit_recovers_the_friction_of_a_synthetic_curve(tmp_path, cli, refined):
    case = short(refined)
    truth = soilcut.run(case.set("soil.friction.peak", 37.0)).history
    measured = pd.DataFrame({"u": truth["u"], "force": truth["force"]})
    budget = dict(evaluations=48, population=16, polish=20, profile_points=0)
    result = soilcut.fit(case, measured, ["soil.friction.peak"], **budget, seed=3, jobs=1)
    assert result.best_rms < 0.05 * result.start_rms
    assert abs(result.best["soil.friction.peak"] - 37.0) < 0.2
    assert result.best_case["soil.friction.peak"] == result.best["soil.friction.peak"]
    # The same calibration from the command line writes the same files.
    csv = tmp_path / "measured.csv"
    measured.to_csv(csv, index=False)
    out = tmp_path / "fit"
    run_cli(
        cli,
        "fit",
        str(REFINED),
        "--measured",
        str(csv),
        "--free",
        "soil.friction.peak",
        "--evaluations",
        "48",
        "--population",
        "16",
        "--polish",
        "20",
        "--profile-points",
        "0",
        "--seed",
        "3",
        "--jobs",
        "1",
        *SHORT_SETS,
        "--out",
        str(out),
    )
    for name in ["fit.csv", "best.toml"]:
        assert result.files[name] == (out / name).read_text(), name

    # curves.csv names each test: the measured file's path from the command line.
    def without_test_column(text):
        return [line.split(",", 1)[1] for line in text.splitlines()]

    python, command_line = result.files["curves.csv"], (out / "curves.csv").read_text()
    assert without_test_column(python) == without_test_column(command_line)


def test_fit_by_cma_es_is_the_cli_fit(tmp_path, cli, refined):
    case = short(refined)
    truth = soilcut.run(case.set("soil.friction.peak", 37.0)).history
    measured = pd.DataFrame({"u": truth["u"], "force": truth["force"]})
    budget = dict(evaluations=40, population=0, polish=10, profile_points=0)
    result = soilcut.fit(
        case, measured, ["soil.friction.peak"], method="cmaes", **budget, seed=5, jobs=2
    )
    assert result.best_rms < 0.05 * result.start_rms
    assert "CMA-ES" in result.files["fit.md"]
    csv = tmp_path / "measured.csv"
    measured.to_csv(csv, index=False)
    out = tmp_path / "fit"
    args = ["--measured", str(csv), "--free", "soil.friction.peak", "--method", "cmaes"]
    args += ["--evaluations", "40", "--polish", "10", "--profile-points", "0", "--seed", "5"]
    args += ["--jobs", "1", *SHORT_SETS]
    run_cli(cli, "fit", str(REFINED), *args, "--out", str(out))
    for name in ["fit.csv", "search.csv", "best.toml"]:
        assert result.files[name] == (out / name).read_text(), name
    with pytest.raises(ValueError, match="^method pso: expected de .* or cmaes"):
        soilcut.fit(case, measured, ["soil.friction.peak"], method="pso")


@pytest.mark.parametrize(
    "call, says",
    [
        (lambda c: soilcut.fit(c, ([0, 10], [1, 2]), []), "give at least one key in free"),
        (
            lambda c: soilcut.fit(
                c, ([0, 10], [1, 2]), ["soil.friction.peak"], bounds={"x": (1, 2)}
            ),
            "bounds x: not one of the free keys",
        ),
        (
            lambda c: soilcut.fit(c, ([0, 10], [1, 2]), ["run.travel"]),
            'give bounds={"run.travel": (lo, hi)}',
        ),
        (
            lambda c: soilcut.fit(c, ([0, 10], [1, 2]), ["soil.friction.peak"], objective="x"),
            "objective x: expected raw",
        ),
        (lambda c: soilcut.sweep(c, {}), "give at least one key in vary"),
        (lambda c: soilcut.sweep(c, {"soil.friction.peak": "30:40"}, sample="lhs"), "sample lhs: "),
        (lambda c: soilcut.sweep(c, {"soil.friction.peak": "30:40"}), 'is for sample="lhs:N"'),
    ],
)
def test_study_errors_name_the_python_arguments(refined, call, says):
    """The study crate's messages name the command line's options; Python's
    name its own arguments instead."""
    with pytest.raises(ValueError) as raised:
        call(refined)
    assert says in str(raised.value)
    assert "--" not in str(raised.value)


def test_fit_width_divides_the_measured_force(refined):
    case = short(refined)
    truth = soilcut.run(case).history
    budget = dict(evaluations=16, population=16, polish=2, profile_points=0, jobs=1)
    per_width = soilcut.fit(case, (truth["u"], truth["force"]), ["soil.friction.peak"], **budget)
    total = soilcut.fit(
        case, (truth["u"], 50 * truth["force"]), ["soil.friction.peak"], width=50, **budget
    )
    # (50 P) / 50 is P to an ulp, not always exactly.
    assert per_width.start_rms == 0.0
    assert total.start_rms < 1e-12
    with pytest.raises(ValueError, match="width"):
        soilcut.fit(case, (truth["u"], truth["force"]), ["soil.friction.peak"], width=0)


def test_fit_names_a_path_and_a_nan_in_the_measured_curve(refined):
    free = ["soil.friction.peak"]
    with pytest.raises(TypeError, match=r"^measured: .* not a path \('measured.csv'\)"):
        soilcut.fit(refined, "measured.csv", free)
    force = np.array([1.0, math.nan, 3.0])
    with pytest.raises(ValueError, match=r"^measured: force\[1\] is nan: every value must be"):
        soilcut.fit(refined, (np.array([0.0, 1.0, 2.0]), force), free)


def test_analytic_baselines_are_the_closed_forms(original, cli):
    b = soilcut.analytic(original)
    phi = math.radians(original["soil.friction.peak"])
    d, gamma = original["blade.depth"], original["soil.unit_weight"]
    kp = math.tan(math.pi / 4 + phi / 2) ** 2
    assert b["rankine"]["force"] == pytest.approx(0.5 * gamma * d * d * kp, rel=1e-12)
    assert b["rankine"]["failure_angle_deg"] == pytest.approx(45 - math.degrees(phi) / 2)
    assert b["coulomb"]["force"] > b["rankine"]["force"], "wall friction adds to the force"
    assert b["fee"]["force"] == pytest.approx(b["coulomb"]["force"], rel=1e-9)
    assert b["fee"]["factors"]["n_gamma"] == pytest.approx(b["fee"]["force_norm"], rel=1e-12)
    printed = run_cli(cli, "analytic", str(ROOT / "cases/paper/original.toml")).stdout
    row = next(line for line in printed.splitlines() if line.startswith("Coulomb"))
    assert float(row.split()[-5]) == round(b["coulomb"]["force"], 6)


def test_sweep_rows_travel_as_columns(refined):
    # What a worker sends back is the row of sweep.csv as columns of one
    # value: the frame of the rows is the frame of the whole sweep.
    case = short(refined)
    frame = soilcut.sweep(case, {"soil.friction.peak": [35, 36]}, jobs=1)
    rows = [
        soilcut._study._sweep_row(case, ["soil.friction.peak"], [v], i + 1, 2)
        for i, v in enumerate([35, 36])
    ]
    pd.testing.assert_frame_equal(soilcut._study._frame(rows), frame)


def test_landscape_is_the_cli_landscape(cli, tmp_path, refined):
    # The landscape's forces are the search's, at the start of the
    # increment: the step's under the explicit rule.
    refined = refined.update({"run.time_scheme": "explicit"})
    taken = soilcut.landscape(refined, 0.5)
    out = tmp_path / "ls"
    explicit = ["--set", "run.time_scheme=explicit"]
    run_cli(cli, "landscape", str(REFINED), "--at", "0.5", "--out", str(out), *explicit)
    theirs = soilcut._soilcut.csv_columns("landscape.csv", (out / "landscape.csv").read_text())
    assert list(taken.candidates) == list(theirs)
    for name, column in theirs.items():
        assert taken.candidates[name].tolist() == column.tolist(), name
    least = taken.candidates["force_over_least"].min()
    assert least == 1.0 and taken.u >= 0.5 * refined["blade.depth"]
    run = soilcut.run(refined).history
    step = int(round(taken.u / refined["run.increment"]))
    assert taken.candidates["force"].min() == run["force"][step], "the least is the run's choice"
    with pytest.raises(ValueError, match="at must be"):
        soilcut.landscape(refined, 2.0)


def test_landscape_map_is_the_cli_map(cli, tmp_path, refined):
    taken = soilcut.landscape_map(refined, 0.25)
    out = tmp_path / "map"
    run_cli(cli, "landscape", str(REFINED), "--every", "0.25", "--out", str(out))
    theirs = soilcut._soilcut.csv_columns(
        "landscape_map.csv", (out / "landscape_map.csv").read_text()
    )
    assert list(taken.columns) == list(theirs)
    for name, column in theirs.items():
        assert taken.columns[name].tolist() == column.tolist(), name
    # u/d = 0, 0.25, 0.5, 0.75 and 1 (the end of the travel).
    assert sorted(set(taken.columns["u_over_d"].tolist())) == [0.0, 0.25, 0.5, 0.75, 1.0]
    assert 0 <= taken.far_ties <= 5
    with pytest.raises(ValueError, match="every must be"):
        soilcut.landscape_map(refined, 0.0)


def test_bounds_are_the_cli_bounds(cli, tmp_path, refined):
    taken = soilcut.bounds(refined, 0, mesh=3)
    out = tmp_path / "b"
    run_cli(cli, "bounds", str(REFINED), "--at", "0", "--mesh", "3", "--out", str(out))
    theirs = soilcut._soilcut.csv_columns("bounds.csv", (out / "bounds.csv").read_text())
    assert list(taken.columns) == list(theirs)
    timed = {"lower_seconds", "upper_seconds"}
    for name, column in theirs.items():
        if name not in timed:
            assert taken.columns[name].tolist() == column.tolist(), name
    assert taken.lower_status == "Solved" and taken.upper_status == "Solved"
    assert taken["lower"] <= taken["upper"]
    with pytest.raises(ValueError, match="mesh must be an integer from 1 to 64"):
        soilcut.bounds(refined, 0, mesh=0)
    with pytest.raises(ValueError, match="floor must be rigid or soil"):
        soilcut.bounds(refined, 0, floor="sand")
    with pytest.raises(ValueError, match="field must be columns or slope"):
        soilcut.bounds(refined, 0, field="mean")
