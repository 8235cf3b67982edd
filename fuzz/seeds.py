"""Writes the hand-made seed inputs of the fuzz targets (docs/fuzzing.md).

    python3 fuzz/seeds.py DIR     # DIR/<target>/seed-NNN

The committed corpus (fuzz/corpus/) is these seeds and what the fuzzer
found from them, minimised together with `cargo fuzz cmin`.
"""

import pathlib
import struct
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
ORIGINAL = (ROOT / "crates/io/testdata/original.toml").read_text()
REFINED = (ROOT / "crates/io/testdata/refined.toml").read_text()


def case_seeds():
    shipped = sorted((ROOT / "cases").glob("**/*.toml"))
    yield from (p.read_bytes() for p in shipped)
    variants = [
        ("travel = 20.0", "travel = nan"),
        ("travel = 20.0", "travel = inf"),
        ("travel = 20.0", "travel = 1e308"),
        ("travel = 20.0", "travel = 3e5"),
        ("travel = 20.0", "travel = 2e4"),
        ("travel = 20.0", "travel = -20.0"),
        ("travel = 20.0", 'travel = "far"'),
        ("increment = 0.2", "increment = 1e-300"),
        ("increment = 0.2", 'increment = 0.2\nground = "nodes"'),
        ("increment = 0.2", "increment = 0.2\nvertex_spacing = 0.0"),
        # More vertices than the fuzzer creates a simulation for (1e6) and
        # fewer than a case may hold (5e7): parsed and validated only.
        ("increment = 0.2", "increment = 0.2\nvertex_spacing = 0.0001"),
        ("depth = 20.0", "depth = 1e9"),
        ("depth = 20.0", "depth = 0"),
        ("depth = 20.0", "depth = 20\nrake = 19.9"),
        ("depth = 20.0", "depth = 20\nrake = 45"),
        ("depth = 20.0", "depth = 20\nwidth = 1"),
        ("depth = 20.0", "depth = 20\nwidth = -1"),
        ("depth = 20.0", "depth = 20\nadhesion = 2"),
        ("depth = 20.0", "depth = 20\ndepth_path = [[0, 10], [5, 25]]"),
        ("depth = 20.0", "depth = 20\ndepth_path = [[5, 10], [0, 25]]"),
        ("depth = 20.0", "depth = 20\ndepth_path = [[0, 10, 3]]"),
        ("wall_friction = 10.0", "wall_friction = 89.0"),
        ("wall_friction = 10.0", "wall_friction = -1"),
        ("peak = 35.0", "peak = 90.0"),
        ("peak = 35.0", "peak = 1e400"),
        ("residual = 30.0", "residual = 36.0"),
        ("residual_shear = 4.0", "residual_shear = 4.0\ncohesion = 5\nsurcharge = 2"),
        ("residual_shear = 4.0", "residual_shear = 4.0\nrepose = 0"),
        ("residual_shear = 4.0", "residual_shear = 4.0\ncolour = 1"),
        ('model = "original"', 'model = "fancy"'),
        ('model = "original"', 'model = "original"\n[bin]\nlength = 25'),
        ('model = "original"', 'model = "original"\n[bin]\nlength = 20'),
        ('model = "original"', 'model = "original"\n[choices]\nface_friction = "sign"'),
        ('model = "original"', 'model = "original"\n[choices]\nband_shear = "full"'),
        ('name = "base"', 'name = "a/b"'),
        ('name = "base"', 'name = ""'),
        ('name = "base"', "name = 3"),
        ("[run]", "[run]\n[run.deep]\nx = 1"),
        ("[soil]", "[[soil]]"),
    ]
    for old, new in variants:
        yield ORIGINAL.replace(old, new, 1).encode()
    for old, new in [
        ("band_width_d50 = 7", "band_width = 4.2"),
        ("band_width_d50 = 7", "band_width = 4.2\nband_width_d50 = 7"),
        ("band_width_d50 = 7", "band_width_d50 = 40"),
        ("d50 = 0.6", "d50 = -0.6"),
        ("peak = 5", "peak = 45"),
        ("peak_shear = 2", "peak_shear = 5"),
        ('model = "refined"', 'model = "refined"\n[choices]\nband_angles = "angle-of-mean-shear"'),
    ]:
        yield REFINED.replace(old, new, 1).encode()
    yield REFINED.replace('model = "refined"', 'model = "original"').encode()
    yield b""
    yield b"name = "
    yield b"a = [" * 200
    yield b"a = {" * 200
    yield b"[" + b"a." * 300 + b"b]"
    yield ORIGINAL.replace("base", "ba\xe9se").encode("latin-1")
    yield b"\xff\xfe" + ORIGINAL.encode("utf-16-le")
    yield ORIGINAL.encode()[:57]


def override_seeds():
    # The first byte picks the base case (0 original, 1 refined, 2
    # deepening, 3 tine); NUL separates the arguments.
    sets = [
        "0run.increment=0.02",
        "0run.increment=nan",
        "0run.increment=-1",
        "0run.travel=1e308",
        "0run.travel=5000",
        '0run.ground="nodes"',
        "0model=refined",
        '0model="refined"',
        "0soil.friction={ peak = 36, residual = 30 }",
        "0soil.friction.peak=95",
        "0soil.friction.pk=3",
        "0blade.rake=19",
        "0blade.rake=45\0bin.length=30",
        "0bin.length=120",
        "0bin.width=1",
        "0colour=1",
        "0run.increment.x=1",
        "0run..increment=1",
        "0=1",
        "0run.increment",
        "0name=a b",
        '0name="a-1_b.c"',
        "0blade.depth_path=[[0, 5], [10, 20]]",
        "0blade.depth_path=[[0, 0.1]]",
        "0choices.face_friction=sign",
        "0soil={}",
        "0blade=3",
        "1soil.band_width=9",
        "1soil.d50=-0.6\0soil.band_width_d50=-15",
        "1soil.band_width_d50=40",
        "1choices.band_shear=by-position\0choices.unit_weight=per-node-formula",
        "1soil.dilation={initial=0,peak=0,residual=0}",
        "1soil.dilation.peak=45",
        # Soil that never softens: the vertex ground whose search compares
        # the bands' midpoint forces (M51a), raked, steered, wide, in a bin.
        "1soil.friction.residual=35",
        "1soil.friction.residual=35\0blade.rake=60",
        "1soil.friction.residual=35\0blade.depth_path=[[0, 10], [20, 20]]",
        "1soil.friction.residual=35\0blade.width=30",
        "1soil.friction.residual=35\0bin.length=60",
        "1soil.friction.residual=35\0run.time_scheme=explicit",
        "2blade.depth_path=[[0, 10], [40, 20], [30, 5]]",
        "2run.increment=0.2",
        "3blade.width=1",
        "3blade.width=0",
        "3blade.width=inf",
        "3blade.width=1e-300",
        "3run.travel=1",
        " run . increment = 0.02 ",
        "0a.b.c.d.e.f.g.h=1",
        "0run.increment=0.02\0run.increment=0.04\0run.travel=2",
    ]
    for s in sets:
        yield s.encode()
    yield b"0run.increment=\xff"


def measured_seeds():
    yield from [
        "u,force\n0,1.5\n0.25,2.5\n",
        "# lab test 3\nforce, u ,t\n1.5,0,9\n\n2.5,0.25,9\n",
        '\ufeff"time, s","U","Force"\n"0",0,1.5\n"1, 2",0.25,"2.5"\n',
        "u;force;note\n0;1,5;a, b\n0,25;2,5;c\n",
        "u\tforce\n0\t1.5\n0.25\t2.5\n",
        "u,force,weight\n0,1.5,2\n0.25,2.5,0\n",
        "u,force,weight\n0,1,0\n1,2,0\n",
        "u,force,weight\n0,1,1\n1,2,-1\n",
        "u,force\n0,1\n1,nan\n",
        "u,force\n0,1\n1,inf\n",
        "u,force\n0,1\n1,1e400\n",
        "u,force\n0,1\n1,\n",
        "u,force\n0,1\n1\n",
        "u,force\n0,1\n",
        "u,f\n0,1\n1,2\n",
        "",
        "# only a comment\n",
        'u,force\n0,1\n"1,2\n',
        "u,force\r\n0,1\r\n1,2\r\n",
        "u,force\r0,1\r1,2\r",
        "u;force;weight\n0;1,5;0,5\n1;2;1\n",
        "U,FORCE,Weight,u\n0,1,1,9\n1,2,1,9\n",
    ]
    yield b"u,force\n0,1\n1,\xff\n"
    yield "u;force\n0;1\n1;2\n".encode("utf-16-le")


# ffi_calls: each input is a program of C ABI calls, op byte first
# (crates/fuzz-bodies/src/ffi.rs reads them in this order).
NUMBERS = [
    float("nan"),
    float("inf"),
    float("-inf"),
    -1.0,
    -0.0,
    0.0,
    5e-324,
    1e-300,
    0.02,
    0.04,
    0.1,
    0.2,
    0.3,
    0.5,
    1.0,
    2.0,
    10.0,
    15.0,
    20.0,
    40.0,
    1e6,
    1e19,
    1e21,
    sys.float_info.max,
]
NULL, MISALIGNED, VALID = 0, 1, 2
# Buffer lengths: 0, the one needed, one less, one more, (4, n) any n.
ZERO, NEEDED, LESS, MORE = 0, 1, 2, 3


def u16(n):
    return bytes([n & 0xFF, n >> 8])


def num(v):
    for i, t in enumerate(NUMBERS):
        if str(t) == str(v):
            return bytes([i])
    return b"\x80" + struct.pack("<d", v)


def text(s, limit=4096):
    data = s.encode() if isinstance(s, str) else s
    return u16(len(data) % (limit + 1)) + data


def sets(*args):
    return bytes([len(args)]) + b"".join(text(a, 64) for a in args)


def new_toml(slot, case, *overrides):
    return b"\x00" + text(case) + sets(*overrides) + bytes([slot])


def new_base(slot, pick, *overrides):
    return bytes([1, pick]) + sets(*overrides) + bytes([slot])


def step(slot, ptr=VALID):
    return bytes([3, slot, ptr])


def advance(slot, x, depth=float("nan"), callback=True, reenter=False, made=VALID):
    flags = made | (4 if callback else 0) | (8 if reenter else 0)
    return bytes([4, slot]) + num(x) + num(depth) + bytes([flags])


def last_step(slot, ptr=VALID):
    return bytes([5, slot, ptr])


def state(slot, ptr=VALID):
    return bytes([6, slot, ptr])


def surface(slot, length=NEEDED, given=31, ptr=VALID):
    return bytes([7, slot, ptr, length, given])


def snapshot(slot, length=NEEDED, buf=True, ptr=VALID):
    return bytes([8, slot, ptr, length, 1 if buf else 0])


def restore(slot, how=0, *args):
    return bytes([9, slot, how]) + b"".join(args)


def last_error(slot, length=NEEDED):
    return bytes([10, slot, length])


def warnings(slot, length=NEEDED, ptr=VALID):
    return bytes([11, slot, ptr, length])


def free(slot):
    return bytes([12, slot])


def ffi_seeds():
    whole = [state(0), step(0), last_step(0), surface(0), warnings(0)]
    for pick in range(4):
        yield new_base(0, pick) + b"".join(whole) + advance(0, 0.6, reenter=True)
    yield new_base(0, 0) + last_step(0) + step(0, MISALIGNED) + step(0, NULL) + last_step(0)
    yield (
        new_base(0, 0) + step(0) + snapshot(0) + restore(1) + step(1) + step(0) + free(0) + state(1)
    )
    yield new_base(1, 1) + snapshot(1) + restore(0, 1, u16(100), b"\x01") + restore(0, 2, u16(50))
    yield new_base(0, 0) + snapshot(0) + restore(1) + free(0) + free(1)
    yield new_base(0, 3) + snapshot(0) + restore(0, 0) + surface(0) + warnings(0, ZERO)
    yield (
        restore(0, 3, text(b"SOILCUT\x01" + bytes(40), 512))
        + restore(1, 4, b"\x05")
        + restore(0, 0)
    )
    for x in [float("nan"), float("inf"), -1.0, 1e21, sys.float_info.max, 0.0, 1e19, 1e6]:
        yield new_base(0, 0) + advance(0, x) + advance(0, 0.3, x)
    yield new_base(0, 2) + advance(0, 1.0, 15.0, reenter=True) + advance(0, 0.5) + last_step(0)
    yield (
        new_base(0, 0)
        + advance(0, 0.6, made=MISALIGNED)
        + advance(0, 0.6, made=NULL, callback=False)
    )
    yield new_base(0, 0, "run.travel=0.4") + step(0) + step(0) + step(0) + step(0) + last_step(0)
    yield new_base(0, 0, "run.increment=0.02") + state(0) + surface(0) + snapshot(0)
    yield new_base(0, 0, "run.increment=nan") + new_base(0, 0, "colour=1") + last_error(2)
    yield new_base(0, 1, "soil.band_width=9", "blade.rake=45") + last_error(0, LESS)
    yield (
        new_base(0, 3, "blade.width=1")
        + warnings(0)
        + warnings(0, LESS, NULL)
        + warnings(0, MORE, MISALIGNED)
    )
    yield (
        new_base(0, 0)
        + surface(0, LESS)
        + surface(0, MORE)
        + surface(0, ZERO, 1)
        + surface(0, NEEDED, 3, MISALIGNED)
    )
    yield (
        new_base(0, 0)
        + snapshot(0, LESS)
        + snapshot(0, ZERO, False)
        + snapshot(0, MORE, False)
        + snapshot(0, NEEDED, True, NULL)
    )
    yield last_error(2, ZERO) + last_error(2, LESS) + last_error(2, MORE) + bytes([10, 2, 4, 3])
    yield (
        step(2)
        + last_step(2)
        + state(2)
        + surface(2)
        + snapshot(2)
        + warnings(2)
        + advance(2, 1.0)
        + free(2)
    )
    yield bytes([2, 0]) + bytes([2, 1]) + last_error(2)
    yield new_toml(0, "") + new_toml(0, "name = ") + new_toml(1, b"\xff\xfe") + last_error(2)
    for case in sorted((ROOT / "cases").glob("**/*.toml")):
        yield (
            new_toml(0, case.read_text()) + step(0) + state(0) + snapshot(0) + restore(1) + step(1)
        )
    yield (
        new_toml(0, ORIGINAL, "run.travel=0.6")
        + advance(0, 0.2)
        + advance(0, 0.1)
        + advance(0, 2.0)
        + step(0)
    )
    yield new_toml(0, REFINED) + step(0) + free(0) + step(0) + free(0)


def main():
    out = pathlib.Path(sys.argv[1])
    for target, seeds in [
        ("case_toml", case_seeds()),
        ("set_override", override_seeds()),
        ("measured_csv", measured_seeds()),
        ("ffi_calls", ffi_seeds()),
    ]:
        d = out / target
        d.mkdir(parents=True, exist_ok=True)
        for i, seed in enumerate(seeds):
            data = seed.encode() if isinstance(seed, str) else seed
            (d / f"seed-{i:03}").write_bytes(data)


if __name__ == "__main__":
    main()
