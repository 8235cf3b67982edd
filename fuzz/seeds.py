"""Writes the hand-made seed inputs of the fuzz targets (docs/fuzzing.md).

    python3 fuzz/seeds.py DIR     # DIR/<target>/seed-NNN

The committed corpus (fuzz/corpus/) is these seeds and what the fuzzer
found from them, minimised together with `cargo fuzz cmin`.
"""

import pathlib
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
        ("increment = 0.2", "increment = 0.2\nnode_spacing = 0.6"),
        ("increment = 0.2", "increment = 0.2\nnode_spacing = 0.3"),
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
        "0run.node_spacing=0.6",
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


def main():
    out = pathlib.Path(sys.argv[1])
    for target, seeds in [
        ("case_toml", case_seeds()),
        ("set_override", override_seeds()),
        ("measured_csv", measured_seeds()),
    ]:
        d = out / target
        d.mkdir(parents=True, exist_ok=True)
        for i, seed in enumerate(seeds):
            data = seed.encode() if isinstance(seed, str) else seed
            (d / f"seed-{i:03}").write_bytes(data)


if __name__ == "__main__":
    main()
