"""Shared fixtures: the repository's cases and the command line `soilcut`
(built once, in release, by scripts/test; SOILCUT_BIN names it)."""

from __future__ import annotations

import os
import pathlib
import subprocess

import pytest

import soilcut

ROOT = pathlib.Path(__file__).resolve().parents[2]
CASES = ROOT / "cases"


def case_path(name: str) -> pathlib.Path:
    return CASES / name


@pytest.fixture(scope="session")
def cli() -> str:
    """The path of the `soilcut` command line."""
    path = os.environ.get("SOILCUT_BIN")
    if not path:
        subprocess.run(["cargo", "build", "--release", "-q", "-p", "soilcut"], cwd=ROOT, check=True)
        target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
        path = str(target / "release" / "soilcut")
    return path


def run_cli(cli: str, *args: str, check: bool = True) -> subprocess.CompletedProcess:
    done = subprocess.run([cli, *args], capture_output=True, text=True, cwd=ROOT)
    if check:
        assert done.returncode == 0, done.stderr
    return done


@pytest.fixture
def original() -> soilcut.Case:
    return soilcut.Case.from_file(case_path("paper/original.toml"))


@pytest.fixture
def refined() -> soilcut.Case:
    return soilcut.Case.from_file(ROOT / "crates/io/testdata/refined.toml")
