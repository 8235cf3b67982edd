"""`soilcut.sensitivity` against `soilcut sensitivity`: on threads, on
process pools of one and two workers and on a Dask cluster, the same files
(indices.csv first) as the command line's for the same case, keys and
seed; bad arguments named as Python names them, before any run."""

from __future__ import annotations

import concurrent.futures
import io
import json

import pytest
from conftest import case_path, run_cli

import soilcut

pd = pytest.importorskip("pandas")

CASE = case_path("paper/fig5.toml")
# Fig. 5 over u/d = 0.5 in increments of d/20: ten increments a run.
SHORT = {"run.travel": 10, "run.increment": 1}
VARY = {"soil.friction.peak": (35, 45), "blade.wall_friction": "5:15"}
# Sobol, N = 16 with the dummy: 16 × 5 design points and 5 of the
# tornado, two members each (170 runs).
OPTIONS = {"method": "sobol", "samples": 16, "members": 2, "dummy": True, "seed": 3}
# Every file but timing.csv, the wall times.
SAME = ["indices.csv", "samples.csv", "tornado.csv", "summary.json", "sensitivity.md"]


@pytest.fixture(scope="module")
def cli_files(cli, tmp_path_factory) -> dict[str, str]:
    """The command line's files of the study."""
    out = tmp_path_factory.mktemp("cli") / "study"
    sets = [a for key, value in SHORT.items() for a in ("--set", f"{key}={value}")]
    run_cli(
        cli,
        "sensitivity",
        str(CASE),
        "--vary",
        "soil.friction.peak=35:45",
        "--vary",
        "blade.wall_friction=5:15",
        "--method",
        "sobol",
        "--samples",
        "16",
        "--members",
        "2",
        "--dummy",
        "--seed",
        "3",
        "-q",
        "--out",
        str(out),
        *sets,
    )
    return {name: (out / name).read_text(encoding="utf-8") for name in SAME}


def study(**options) -> soilcut.SensitivityResult:
    case = soilcut.Case.from_file(CASE).update(SHORT)
    return soilcut.sensitivity(case, VARY, **{**OPTIONS, **options})


def assert_is_the_cli_s(result: soilcut.SensitivityResult, cli_files: dict[str, str]):
    assert result.complete, result.summary["stopped"]
    for name in SAME:
        assert result.files[name] == cli_files[name], name
    # Every output has indices of the three inputs.
    assert len(result.indices) == 3 * len(result.summary["outputs"])
    assert result.indices["S1"].notna().any()


@pytest.mark.parametrize("jobs", [1, 2])
def test_threads_give_the_cli_s_files(cli_files, jobs):
    assert_is_the_cli_s(study(jobs=jobs), cli_files)


@pytest.mark.parametrize("workers", [1, 2])
def test_process_pools_give_the_cli_s_files(cli_files, workers):
    with concurrent.futures.ProcessPoolExecutor(workers) as pool:
        result = study(executor=pool)
    assert_is_the_cli_s(result, cli_files)


def test_a_dask_cluster_gives_the_cli_s_files(cli_files):
    distributed = pytest.importorskip("distributed")
    with (
        distributed.LocalCluster(
            processes=True, n_workers=2, threads_per_worker=1, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        result = study(executor=client.get_executor())
        workers = client.run(lambda: __import__("os").getpid())
    assert len(set(workers.values())) == 2, "two worker processes"
    assert_is_the_cli_s(result, cli_files)


def test_the_frames_are_the_files_and_the_pictures_are_drawn(tmp_path):
    result = study(method="morris", samples=2, pictures=tmp_path / "pictures")
    for name, frame in [
        ("indices.csv", result.indices),
        ("samples.csv", result.samples),
        ("tornado.csv", result.tornado),
    ]:
        pd.testing.assert_frame_equal(frame, pd.read_csv(io.StringIO(result.files[name])))
    assert list(result.indices.columns[2:]) == [
        "mu_star",
        "mu_star_low",
        "mu_star_high",
        "sigma",
        "mu",
    ]
    assert len(result.samples) == 2 * 4 * 2, "r (keys + 1) points, two members each"
    assert result.summary == json.loads(result.files["summary.json"])
    names = sorted(p.rsplit("/", 1)[-1] for p in result.pictures)
    assert names == ["indices.png", "morris.png", "tornado.png"]
    assert all((tmp_path / "pictures" / n).stat().st_size > 0 for n in names)


@pytest.mark.parametrize(
    ("options", "says"),
    [
        ({"vary": {}}, "give at least one key in vary"),
        ({"vary": {"soil.friction.peak": (45, 35)}}, "a range needs finite lo < hi"),
        ({"vary": {"soil.friction.peak": "35:45:3"}}, "vary soil.friction.peak=35:45:3"),
        ({"vary": {"soil.friction.peak": [1, 2, 3]}}, "vary soil.friction.peak: expected"),
        ({"samples": 24}, "samples 24: Sobol indices need N a power of 2"),
        ({"method": "fast"}, "method fast: expected morris or sobol"),
        ({"method": "morris", "levels": 3}, "levels 3: Morris's grid"),
        ({"members": 0}, "members 0"),
        ({"vary": {"soil.frict": (1, 2)}}, "soil.frict"),
    ],
)
def test_bad_arguments_are_named_as_python_names_them(monkeypatch, options, says):
    def no_run(*_):
        raise AssertionError("a run was started")

    monkeypatch.setattr(soilcut._sensitivity, "_run", no_run)
    case = soilcut.Case.from_file(CASE).update(SHORT)
    arguments = {**OPTIONS, "vary": VARY, **options}
    vary = arguments.pop("vary")
    with pytest.raises(ValueError) as raised:
        soilcut.sensitivity(
            case, vary, **arguments, executor=concurrent.futures.ThreadPoolExecutor(1)
        )
    assert says in str(raised.value)
    assert "--" not in str(raised.value)
