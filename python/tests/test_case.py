"""Cases: round trips (TOML, dict, pickle), --set's keys, and every error
path with the command line's message."""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest
from conftest import case_path, run_cli

import soilcut


def test_round_trips_keep_the_case(original, refined):
    for case in (original, refined):
        assert soilcut.Case.from_toml(case.to_toml()) == case
        assert soilcut.Case.from_dict(case.to_dict()) == case
        assert pickle.loads(pickle.dumps(case)) == case
        assert case.resolved() == case
        assert case.resolved().resolved_toml() == case.resolved_toml()


def test_resolved_fills_the_defaults(original):
    assert "rake" not in original.to_dict()["blade"]
    resolved = original.resolved()
    assert resolved.to_dict()["blade"]["rake"] == 90.0 == original["blade.rake"]
    assert "cohesion" not in original.to_dict()["soil"]
    assert resolved.to_dict()["soil"]["cohesion"] == 0.0


def test_a_key_the_resolved_case_lacks_is_a_key_error_that_says_why(refined):
    assert refined["run.vertex_spacing"] > 0
    with pytest.raises(KeyError, match="run.node_spacing: not in this case as resolved"):
        refined["run.node_spacing"]
    with pytest.raises(KeyError, match="soil.colour"):
        refined["soil.colour"]


def test_set_returns_a_new_case_as_the_cli_reads_it(cli, original, tmp_path):
    changed = original.set("soil.friction.peak", 36).set("run.increment", 0.5)
    assert original["soil.friction.peak"] == 35.0, "a case never changes"
    assert changed["soil.friction.peak"] == 36
    same = original.update({"soil.friction.peak": np.int64(36), "run.increment": np.float64(0.5)})
    assert same == changed
    out = tmp_path / "cli"
    run_cli(
        cli,
        "run",
        str(case_path("paper/original.toml")),
        "--set",
        "soil.friction.peak=36",
        "--set",
        "run.increment=0.5",
        "--set",
        "run.travel=1",
        "--no-plots",
        "-q",
        "--out",
        str(out),
    )
    written = (out / "case.resolved.toml").read_text()
    assert changed.set("run.travel", 1).resolved_toml() == written


def test_tables_and_strings_are_set_like_the_cli(refined):
    varied = refined.set("choices", {"band_shear": "by-position"})
    assert varied["choices.band_shear"] == "by-position"
    assert (
        refined.set("soil.friction", {"initial": 20, "peak": 36, "residual": 30})[
            "soil.friction.peak"
        ]
        == 36
    )


CLI_ERRORS = [
    ("blade.depth", -1, "blade.depth=-1"),
    ("blade.depth", "deep", 'blade.depth="deep"'),
    ("blade.depth", math.nan, "blade.depth=nan"),
    ("blade.dpth", 1, "blade.dpth=1"),
    ("soil.friction.peak", 95, "soil.friction.peak=95"),
    ("soil.d50", 0.6, "soil.d50=0.6"),
    ("run.increment", 30, "run.increment=30"),
    ("choices.face_friction", "smooth", 'choices.face_friction="smooth"'),
    ("run.increment", "abc", "run.increment=abc"),
    ("run.increment", True, "run.increment=true"),
]


@pytest.mark.parametrize("key,value,cli_set", CLI_ERRORS)
def test_errors_are_case_errors_with_the_cli_message(cli, original, key, value, cli_set):
    with pytest.raises(soilcut.CaseError) as raised:
        original.set(key, value)
    path = case_path("paper/original.toml")
    done = run_cli(cli, "check", str(path), "--set", cli_set, check=False)
    assert done.returncode == 2
    # The command line names the --set that gave the value, not the file.
    assert done.stderr == f"error: --set {cli_set}: {raised.value}\n"
    assert isinstance(raised.value, ValueError)
    assert raised.value.key is not None and str(raised.value).startswith(raised.value.key)


def test_a_value_of_the_wrong_type_is_named_in_the_case_files_words(original):
    with pytest.raises(soilcut.CaseError) as raised:
        original.set("run.increment", "abc")
    assert str(raised.value) == 'run.increment: expected a number, got the string "abc"'
    with pytest.raises(soilcut.CaseError, match="expected a number, got the boolean true$"):
        original.set("run.increment", True)


def test_a_value_python_cannot_express_in_toml_names_the_key(original):
    with pytest.raises(soilcut.CaseError, match=r"^blade\.depth: a value of type object") as e:
        original.set("blade.depth", object())
    assert e.value.key == "blade.depth"


def test_text_and_dict_errors(original):
    with pytest.raises(soilcut.CaseError, match="line 1"):
        soilcut.Case.from_toml("name = = 1")
    d = original.to_dict()
    del d["blade"]["depth"]
    with pytest.raises(soilcut.CaseError, match="^blade.depth: required key is missing$"):
        soilcut.Case.from_dict(d)
    with pytest.raises(soilcut.CaseError, match="unknown key"):
        soilcut.Case.from_dict({**original.to_dict(), "colour": "red"})
    with pytest.raises(FileNotFoundError):
        soilcut.Case.from_file("no/such/case.toml")
    with pytest.raises(TypeError):
        soilcut.Case(original.to_dict())


def test_errors_pickle_with_their_key(original):
    with pytest.raises(soilcut.CaseError) as raised:
        original.set("blade.depth", -1)
    again = pickle.loads(pickle.dumps(raised.value))
    assert (str(again), again.key) == (str(raised.value), "blade.depth")


def test_a_path_is_taken_where_a_case_is(original, tmp_path):
    short = original.update({"run.travel": 1.0, "run.increment": 0.2})
    path = tmp_path / "short.toml"
    path.write_text(short.to_toml(), encoding="utf-8")
    reference = soilcut.run(short).history["force"]
    for given in (path, str(path)):
        np.testing.assert_array_equal(soilcut.run(given).history["force"], reference)
        assert soilcut.Simulation(given).case == short
    # A one-line string ending in .toml is a path even if it names no file.
    with pytest.raises(FileNotFoundError):
        soilcut.Simulation(str(tmp_path / "missing.toml"))
    # A one-line string without "=" is no case's text: a path, even without .toml.
    with pytest.raises(FileNotFoundError):
        soilcut.run(str(tmp_path / "missing"))
    with pytest.raises(TypeError, match=r"^update: changes must be .* got the item 1$"):
        original.update([1, 2])
    # The text itself is still the text.
    assert soilcut.Simulation(short.to_toml()).case == short


def test_from_file_refuses_what_is_no_path_and_names_the_file(tmp_path):
    with pytest.raises(TypeError, match="takes a path"):
        soilcut.Case.from_file(123)
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "bad"\nmodel = "original"\n[blade]\ndepth = -1\n', encoding="utf-8")
    with pytest.raises(soilcut.CaseError) as e:
        soilcut.Case.from_file(bad)
    assert str(e.value).startswith(f"{bad}: ")
    with pytest.raises(soilcut.CaseError, match=f"^{bad}: "):
        soilcut.run(str(bad))
