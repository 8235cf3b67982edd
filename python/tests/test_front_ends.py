"""Snapshots cross front ends: one taken through the C ABI (the shared
library ``soilcut-ffi``, called here by ctypes as a C program would)
restores in Python with its case and continues bit for bit, and one taken
in Python restores through the C ABI. Both read the case's text by one
function of ``soilcut-io`` (``case_from_note``)."""

from __future__ import annotations

import ctypes
import pathlib
import subprocess
import sys

import pytest
from conftest import ROOT

import soilcut

NAMES = ["step"] + (
    "u u_over_d force force_norm force_h force_v beta_deg x_emergence mass y_emergence "
    "friction_deg slip dilation_deg dilation_area depth mass_spilled weight force_factor "
    "face_friction_deg moment tool_x tool_y tool_rotation"
).split()


class Step(ctypes.Structure):
    """`SoilcutStep` of crates/ffi/include/soilcut.h, field for field."""

    _fields_ = [("step", ctypes.c_uint64)] + [(n, ctypes.c_double) for n in NAMES[1:]]


def library_name() -> str:
    if sys.platform == "darwin":
        return "libsoilcut_ffi.dylib"
    return "soilcut_ffi.dll" if sys.platform == "win32" else "libsoilcut_ffi.so"


@pytest.fixture(scope="module")
def ffi(cli) -> ctypes.CDLL:
    """The C ABI's shared library, built in release beside the command line
    (scripts/test builds both)."""
    path = pathlib.Path(cli).parent / library_name()
    if not path.exists():
        subprocess.run(
            ["cargo", "build", "--release", "-q", "-p", "soilcut-ffi"], cwd=ROOT, check=True
        )
    lib = ctypes.CDLL(str(path))
    handle = ctypes.POINTER(ctypes.c_void_p)
    lib.soilcut_new_from_toml.argtypes = [
        ctypes.c_char_p,
        ctypes.c_void_p,
        ctypes.c_size_t,
        ctypes.POINTER(handle),
    ]
    lib.soilcut_step.argtypes = [handle, ctypes.POINTER(Step)]
    lib.soilcut_snapshot.argtypes = [
        handle,
        ctypes.c_char_p,
        ctypes.c_size_t,
        ctypes.POINTER(ctypes.c_size_t),
    ]
    lib.soilcut_restore.argtypes = [ctypes.c_char_p, ctypes.c_size_t, ctypes.POINTER(handle)]
    lib.soilcut_free.argtypes = [handle]
    lib.handle = handle
    return lib


def c_new(lib, text: str):
    sim = lib.handle()
    assert lib.soilcut_new_from_toml(text.encode(), None, 0, ctypes.byref(sim)) == 0
    return sim


# The record's fields both front ends have (u_over_d is the C record's own).
SHARED = [n for n in NAMES if n != "u_over_d"]


def c_steps(lib, sim, n: int) -> list[list[float]]:
    out = []
    for _ in range(n):
        record = Step()
        assert lib.soilcut_step(sim, ctypes.byref(record)) == 0
        out.append([getattr(record, name) for name in SHARED])
    return out


def py_steps(sim, n: int) -> list[list[float]]:
    records = [sim.step() for _ in range(n)]
    return [[getattr(r, name) for name in SHARED] for r in records]


@pytest.fixture
def case(original) -> soilcut.Case:
    return original.update({"run.increment": 0.5, "run.travel": 40})


def test_a_c_snapshot_restores_in_python_with_its_case(ffi, case):
    sim = c_new(ffi, case.to_toml())
    c_steps(ffi, sim, 20)
    needed = ctypes.c_size_t()
    assert ffi.soilcut_snapshot(sim, None, 0, ctypes.byref(needed)) == 0
    buf = ctypes.create_string_buffer(needed.value)
    assert ffi.soilcut_snapshot(sim, buf, needed.value, ctypes.byref(needed)) == 0
    restored = soilcut.Simulation.from_snapshot(buf.raw[: needed.value])
    assert restored.case == case and restored.steps_done == 20
    assert py_steps(restored, 15) == c_steps(ffi, sim, 15), "bit for bit"
    ffi.soilcut_free(sim)


def test_a_python_snapshot_restores_in_c(ffi, case):
    sim = soilcut.Simulation(case)
    py_steps(sim, 20)
    data = sim.snapshot()
    restored = ffi.handle()
    assert ffi.soilcut_restore(data, len(data), ctypes.byref(restored)) == 0
    assert c_steps(ffi, restored, 15) == py_steps(sim, 15), "bit for bit"
    ffi.soilcut_free(restored)
