"""The bucket dig of digs/bucket.json: its profile, its path and the region it carries.

Plain Python (no Yade): bucket.py moves the DEM's bucket with it and
`python3 dig.py [DIG]` checks the dig's geometry against the long bin
(prints the lowest point of the profile in each phase, the heel's
clearance over the cut ground, the distances to the end wall, the floor
and the start wall). Lengths in mm, angles in degrees.

The tool frame: origin at the cutting edge (the lip), x forward, y up at
rotation 0. The world frame: x from the lip's start, y up from the
levelled surface. A pose (x, y, theta) places the tool's reference point
(the pivot) at (x, y) and turns the tool by theta about it, counter-
clockwise positive (curl: the lip turns up). The path is piecewise linear
in the progress s: x, y and theta interpolate linearly between poses; each
pose's s is the lip's path length from the start (mm), so the tool, moved
at ds/dt = speed, moves the lip at the speed on average over every phase
and exactly in the translations.
"""

import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DIG = os.path.join(HERE, "digs", "bucket.json")
PROFILE_KEYS = ("lip", "heel", "arc_centre", "arc_radius", "arc_through", "rim")


class DigError(ValueError):
    """A dig file whose key is missing or out of its range."""


def load(path=DIG):
    """The dig of a JSON file, checked (DigError names the key and its range)."""
    with open(path) as f:
        dig = json.load(f)
    for key in ("depth", "speed", "pivot", "profile", "poses", "record_every_d"):
        if key not in dig:
            raise DigError(f"{path}: key `{key}` is missing")
    for key in ("depth", "speed", "record_every_d", "surface_every_d"):
        if not (isinstance(dig.get(key), (int, float)) and dig[key] > 0):
            raise DigError(f"{path}: `{key}` must be a number > 0")
    for key in PROFILE_KEYS:
        if key not in dig["profile"]:
            raise DigError(f"{path}: key `profile.{key}` is missing")
    poses = dig["poses"]
    if len(poses) < 2:
        raise DigError(f"{path}: `poses` needs at least 2 poses")
    for k, p in enumerate(poses):
        for key in ("s", "x", "y", "theta"):
            if not (isinstance(p.get(key), (int, float)) and math.isfinite(p[key])):
                raise DigError(f"{path}: `poses[{k}].{key}` must be a finite number")
        if k and not p["s"] > poses[k - 1]["s"]:
            raise DigError(f"{path}: `poses[{k}].s` must exceed the previous pose's")
    return dig


def pose(dig, s):
    """(x, y, theta) at progress s (clamped to the path's ends)."""
    poses = dig["poses"]
    s = min(max(s, poses[0]["s"]), poses[-1]["s"])
    for a, b in zip(poses, poses[1:]):
        if s <= b["s"]:
            t = (s - a["s"]) / (b["s"] - a["s"])
            return tuple(a[k] + t * (b[k] - a[k]) for k in ("x", "y", "theta"))
    raise AssertionError("unreachable: s is clamped to the last pose")


def phase(dig, s):
    """The index of the phase (0: the first pair of poses) that holds s."""
    poses = dig["poses"]
    for k in range(1, len(poses)):
        if s <= poses[k]["s"]:
            return k - 1
    return len(poses) - 2


def to_world(dig, at, p):
    """A tool-frame point p in the world at pose `at`."""
    x, y, theta = at
    px, py = dig["pivot"]
    c, s = math.cos(math.radians(theta)), math.sin(math.radians(theta))
    u, v = p[0] - px, p[1] - py
    return (x + c * u - s * v, y + s * u + c * v)


def to_tool(dig, at, q):
    """A world point q in the tool frame at pose `at`."""
    x, y, theta = at
    px, py = dig["pivot"]
    c, s = math.cos(math.radians(theta)), math.sin(math.radians(theta))
    u, v = q[0] - x, q[1] - y
    return (px + c * u + s * v, py - s * u + c * v)


def profile(dig, arc_segments):
    """The profile in the tool frame: lip, heel, the arc in `arc_segments`
    chords (from the heel through arc_through to the rim), as a polyline."""
    pr = dig["profile"]
    cx, cy = pr["arc_centre"]
    a0 = math.atan2(pr["heel"][1] - cy, pr["heel"][0] - cx)
    a1 = math.atan2(pr["rim"][1] - cy, pr["rim"][0] - cx)
    mid = math.atan2(pr["arc_through"][1] - cy, pr["arc_through"][0] - cx)
    sweep = (a1 - a0) % (2 * math.pi)
    if (mid - a0) % (2 * math.pi) > sweep:  # the arc goes the other way round
        sweep -= 2 * math.pi
    r = pr["arc_radius"]
    arc = [
        (
            cx + r * math.cos(a0 + sweep * k / arc_segments),
            cy + r * math.sin(a0 + sweep * k / arc_segments),
        )
        for k in range(1, arc_segments)
    ]
    return [tuple(pr["lip"]), tuple(pr["heel"])] + arc + [tuple(pr["rim"])]


def cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def inside(dig, p):
    """Whether a tool-frame point lies in the bucket: the region bounded by the
    profile and the chord rim-lip, which is the triangle lip-heel-rim and the
    arc's segment beyond the chord heel-rim (a half disc for this profile)."""
    pr = dig["profile"]
    lip, heel, rim = pr["lip"], pr["heel"], pr["rim"]
    sides = (cross(lip, heel, p), cross(heel, rim, p), cross(rim, lip, p))
    if all(v >= 0 for v in sides) or all(v <= 0 for v in sides):
        return True
    cx, cy = pr["arc_centre"]
    beyond = cross(heel, rim, p) * cross(heel, rim, pr["arc_through"]) > 0
    return beyond and math.hypot(p[0] - cx, p[1] - cy) <= pr["arc_radius"]


def capacity(dig, arc_segments=3600):
    """The area of the bucket's inside (mm^2): the profile closed by the chord rim-lip."""
    p = profile(dig, arc_segments)
    return abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(p, p[1:] + p[:1]))) / 2


def lip_length(dig, s0, s1, n=20000):
    """The lip's path length (mm) from s0 to s1, summed over n chords."""
    lip = dig["profile"]["lip"]
    pts = [to_world(dig, pose(dig, s0 + (s1 - s0) * k / n), lip) for k in range(n + 1)]
    return sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))


def cut_ground(lip_track, x):
    """The ground the lip has cut to so far at x: the surface (0) or the lowest
    passage of the lip's path (a polyline) over x, whichever is lower (mm)."""
    ys = [0.0]
    for (ax, ay), (bx, by) in zip(lip_track, lip_track[1:]):
        if min(ax, bx) <= x <= max(ax, bx) and ax != bx:
            ys.append(ay + (by - ay) * (x - ax) / (bx - ax))
    return min(ys)


def check(dig, end_wall, floor, start_wall, start_wall_top, step=0.5):
    """Per phase: the lowest points of the profile and of its heel, and the
    least relief behind the lip (atan of a profile point's height above the
    ground the lip has cut over its distance from the lip, for the points
    behind the lip and below the surface: > 0, the bucket does not plough
    behind its lip); then the bin's margins. Returns the margins (mm)."""
    lip0, heel0 = dig["profile"]["lip"], dig["profile"]["heel"]
    line = [p for p in densify(profile(dig, 36), 1.0) if math.dist(p, lip0) > 1.0]
    track, worst = [], {}
    margins = {"end wall": math.inf, "floor": math.inf, "start wall top": math.inf}
    s_end = dig["poses"][-1]["s"]
    for k in range(int(math.ceil(s_end / step)) + 1):
        s = min(k * step, s_end)
        at = pose(dig, s)
        lip = to_world(dig, at, lip0)
        track.append(lip)
        pts = [to_world(dig, at, p) for p in line]
        w = worst.setdefault(
            phase(dig, s), {"lowest": (math.inf,), "heel": (math.inf,), "relief": (math.inf,)}
        )
        low = min(pts + [lip], key=lambda q: q[1])
        heel = to_world(dig, at, heel0)
        w["lowest"] = min(w["lowest"], (low[1], s, low))
        w["heel"] = min(w["heel"], (heel[1], s, heel))
        for q in pts:
            if q[0] < lip[0] and q[1] < 0:
                up = q[1] - cut_ground(track, q[0])
                w["relief"] = min(
                    w["relief"], (math.degrees(math.atan2(up, math.dist(q, lip))), s, q)
                )
        margins["end wall"] = min(margins["end wall"], end_wall - max(q[0] for q in pts + [lip]))
        margins["floor"] = min(margins["floor"], low[1] - floor)
        back = [q[1] - start_wall_top for q in pts if q[0] <= start_wall]
        margins["start wall top"] = min([margins["start wall top"]] + back)
    print(f"lip path length {s_end:.2f} mm = {s_end / dig['depth']:.2f} d")
    for ph, w in sorted(worst.items()):
        print(f"phase {ph + 1}: " + "; ".join(describe(k, v) for k, v in w.items()))
    print(", ".join(f"{k} margin {v:.2f} mm" for k, v in margins.items()))
    return margins


def describe(what, worst):
    """One line of check()'s table."""
    if worst[0] == math.inf:
        return f"{what}: none below the surface"
    unit = "deg" if what == "relief" else "mm"
    value, s, q = worst
    return f"{what} {value:.2f} {unit} at ({q[0]:.2f}, {q[1]:.2f}), s = {s:.1f}"


def densify(poly, spacing):
    """The polyline's vertices and points between them at most `spacing` apart."""
    out = [poly[0]]
    for a, b in zip(poly, poly[1:]):
        n = max(1, int(math.ceil(math.dist(a, b) / spacing)))
        out += [
            (a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(1, n + 1)
        ]
    return out


def main():
    dig = load(sys.argv[1] if len(sys.argv) > 1 else DIG)
    poses = dig["poses"]
    for a, b in zip(poses, poses[1:]):
        length = lip_length(dig, a["s"], b["s"])
        print(f"{b.get('phase', '?')}: s {a['s']:g} -> {b['s']:g}, lip path {length:.3f} mm")
        lip = to_world(dig, (b["x"], b["y"], b["theta"]), dig["profile"]["lip"])
        print(f"  lip at ({lip[0]:.3f}, {lip[1]:.3f}), theta {b['theta']:g}")
    print(f"the bucket's inside: {capacity(dig):.1f} mm^2")
    # the long bin (bed.py --long, 20 mm cut): end wall 300 mm ahead of the lip's
    # start, floor 75 mm below the surface, start wall at -40 mm cut down by
    # bucket.py to START_WALL_TOP above the surface
    check(dig, 300.0, -75.0, -40.0, 10.0)


if __name__ == "__main__":
    main()
