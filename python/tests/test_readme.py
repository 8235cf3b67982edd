"""The README's and the user guide's Python runs as written (issue 29,
issue 41): their ``python`` blocks in
order, in one namespace (a later block uses the ``case`` of an earlier
one), and its ``python -c`` commands, from a folder holding a copy of the
repository's cases, so that what they write lands there.
(``crates/cli/tests/readme.rs`` runs its shell commands.)"""

from __future__ import annotations

import re
import shlex
import shutil
import subprocess
import sys

import pytest
from conftest import ROOT

pytest.importorskip("pandas")
pytest.importorskip("gymnasium")


def documents() -> str:
    """The README, then the user guide's chapters in the order of
    docs/guide/index.md's table of contents (as crates/cli/tests/readme.rs
    reads them): the examples run in that order."""
    guide = ROOT / "docs" / "guide"
    toctree = (guide / "index.md").read_text(encoding="utf-8").split("```{toctree}")[1]
    entries = [e.strip() for e in toctree.split("```")[0].splitlines()]
    chapters = [e for e in entries if e and not e.startswith((":", "/"))]
    texts = [(ROOT / "README.md").read_text(encoding="utf-8")]
    texts += [(guide / f"{c}.md").read_text(encoding="utf-8") for c in chapters]
    return "\n".join(texts)


README = documents()


def blocks(language: str) -> list[str]:
    """The fenced blocks of ``language``, indented ones included."""
    fence = re.compile(rf"^( *)```{language}\n(.*?)^\1```$", re.S | re.M)
    return [m.group(2) for m in fence.finditer(README)]


def python_commands() -> list[list[str]]:
    """The ``python -c`` lines of the shell blocks, as argument lists."""
    lines = [line.strip() for block in blocks("sh") for line in block.splitlines()]
    return [shlex.split(line)[1:] for line in lines if line.startswith("python -c ")]


@pytest.fixture
def sandbox(tmp_path, monkeypatch):
    shutil.copytree(ROOT / "cases", tmp_path / "cases")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_the_readme_has_python_to_run():
    assert len(blocks("python")) >= 3 and python_commands()


def test_the_python_blocks_run_in_order(sandbox):
    namespace: dict = {}
    for block in blocks("python"):
        exec(compile(block, "README.md", "exec"), namespace)
    assert (sandbox / "out" / "original-py" / "history.csv").is_file()
    # A user runs the first block again: it replaces what it wrote.
    exec(compile(blocks("python")[0], "README.md", "exec"), {})


def test_the_python_commands_run(sandbox):
    for args in python_commands():
        done = subprocess.run([sys.executable, *args], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        assert done.stdout.strip()
