#!/usr/bin/env python3
"""Sketches for docs/model.md, written to docs/img/model_*.png.

Usage (from the repository root, with the pinned packages of
docs/scripts/requirements.txt installed, see the README):

    python3 docs/scripts/model_figures.py

Every figure is a sketch of one rule of the model drawn from its formula
(the same formulas as crates/model/src/*.rs, on made-up ground), except
model_laws.png, which plots the material laws of the shipped paper cases
(values copied from cases/paper/*.toml). The output is deterministic for a
given matplotlib version: no dates or software names in the PNG metadata.
"""

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

OUT = Path(__file__).resolve().parent.parent / "img"
GROUND = "#d9c59a"
BLOCK = "#b98b4e"
BAND = "#8aa9c9"
BLADE = "#555555"
LINE = "#1f4e79"
ACCENT = "#c0392b"

plt.rcParams.update(
    {
        "font.size": 10,
        "axes.titlesize": 11,
        "savefig.dpi": 150,
        "svg.hashsalt": "soilcut",
    }
)


def save(fig, name):
    fig.savefig(OUT / name, metadata={"Software": None}, bbox_inches="tight")
    plt.close(fig)


def sketch(ax, xlim, ylim, title=None):
    """Equal scales, no axes: a sketch, not a plot."""
    ax.set_aspect("equal")
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_axis_off()
    if title:
        ax.set_title(title)


def pile(x, height=0.35, reach=0.9):
    """A made-up pile in front of the blade: y(x) >= 0, falling to 0."""
    return np.where(x < reach, height * (1 - x / reach) ** 2, 0.0)


def blade(ax, x0, top, depth):
    ax.add_patch(plt.Rectangle((x0 - 0.06, -depth), 0.06, top + depth, color=BLADE))


def mechanism():
    """Candidates, admissibility, the block and the forces of Eq. (1)."""
    d = 1.0
    x = np.linspace(0.0, 2.6, 27)
    y = pile(x) + 0.04 * np.sin(7 * x) * (x < 1.4)
    fig, ax = plt.subplots(figsize=(8, 4.2))
    ax.fill_between(x, -d - 0.3, y, color=GROUND, lw=0)
    j = 16
    line = -d + (y[j] + d) * x / x[j]
    ax.fill_between(x[: j + 1], line[: j + 1], y[: j + 1], color=BLOCK, lw=0)
    ax.plot(x, y, "k.", ms=4)
    for k in (6, 10, 22):
        ax.plot([0, x[k]], [-d, y[k]], "--", color="grey", lw=0.8)
    ax.plot([0, x[j]], [-d, y[j]], color=LINE, lw=2)
    blade(ax, 0.0, 0.8, d)
    ax.annotate("A = (u, -d)", (0, -d), (0.25, -1.2), arrowprops={"arrowstyle": "-"})
    ax.annotate(
        "emergence node j",
        (x[j], y[j]),
        (x[j] + 0.1, 0.5),
        arrowprops={"arrowstyle": "->"},
    )
    beta = math.atan((y[j] + d) / x[j])
    arc = np.linspace(0, beta, 20)
    ax.plot(0.45 * np.cos(arc), -d + 0.45 * np.sin(arc), "k", lw=0.8)
    ax.text(0.5, -d + 0.08, "β", fontsize=12)
    ax.plot([0, 0.7], [-d, -d], "k", lw=0.8)
    cx = x[: j + 1].mean() * 0.7
    ax.annotate("", (cx, -0.35), (cx, 0.05), arrowprops={"arrowstyle": "->", "lw": 1.5})
    ax.text(cx + 0.04, -0.25, "W")
    # The block slides up the face, so the face's friction on it points down.
    ax.annotate(
        "",
        (0.02, -0.45),
        (-0.45, -0.45 + 0.47 * math.tan(math.radians(10))),
        arrowprops={"arrowstyle": "->", "lw": 1.5, "color": ACCENT},
    )
    ax.text(-0.55, -0.3, "P at φw\nbelow the\nface normal", color=ACCENT, ha="center")
    mid = 0.55 * x[j], -d + 0.55 * (y[j] + d)
    # Into the block, tilted by φ against its sliding up the slip line.
    phi = math.radians(30)
    inward = np.array([-math.sin(beta), math.cos(beta)])
    along = np.array([math.cos(beta), math.sin(beta)])
    r = math.cos(phi) * inward - math.sin(phi) * along
    ax.annotate(
        "",
        mid,
        (mid[0] - 0.4 * r[0], mid[1] - 0.4 * r[1]),
        arrowprops={"arrowstyle": "->", "lw": 1.5, "color": ACCENT},
    )
    ax.text(mid[0] + 0.35, mid[1] - 0.45, "R at φ to the\nslip-line normal", color=ACCENT)
    ax.text(1.75, -0.55, "dashed: other candidates\n(one per surface node)", color="grey")
    title = "One candidate mechanism: block above the slip line A→j (§2)"
    sketch(ax, (-0.9, 2.6), (-1.3, 0.9), title)
    save(fig, "model_mechanism.png")


def band():
    """The band of width dB, its vertical thickness e and its footprint."""
    d, beta, dB = 1.0, math.radians(35), 0.16
    t = math.tan(beta)
    e = dB / math.cos(beta)
    x = np.linspace(0.0, 2.2, 45)
    y = pile(x, 0.25, 1.6)
    xj = d / t
    for _ in range(50):  # where the lower boundary meets the surface
        xj = (np.interp(xj, x, y) + d) / t
    fig, ax = plt.subplots(figsize=(8, 4.4))
    ax.fill_between(x, -d - 0.25, y, color=GROUND, lw=0)
    lower, upper = -d + t * x, -d + t * x + e
    top = np.minimum(y, upper)
    inside = x <= xj
    ax.fill_between(x[inside], lower[inside], top[inside], color=BAND, lw=0)
    ax.fill_between(x, np.minimum(upper, y), y, where=upper <= y, color=BLOCK, lw=0)
    ax.plot(x, y, "k.", ms=3)
    ax.plot([0, xj], [-d, -d + t * xj], color=LINE, lw=1.8, label="lower boundary A→j")
    xu = np.linspace(0, xj, 50)
    ax.plot(
        xu,
        -d + t * xu + e,
        color=LINE,
        lw=1.2,
        ls="--",
        label="upper boundary, dB above",
    )
    blade(ax, 0.0, 0.6, d)
    xe = 0.7
    ax.annotate(
        "",
        (xe, -d + t * xe),
        (xe, -d + t * xe + e),
        arrowprops={"arrowstyle": "<->", "color": ACCENT},
    )
    ax.text(xe + 0.25, -d + t * xe - 0.02, "e = dB / cos β", color=ACCENT)
    # footprint: surface nodes between the upper boundary's crossing and j
    cross = x[np.argmax(upper >= y)]
    foot = (x >= cross - 1e-9) & (x <= xj + 1e-9)
    ax.plot(x[foot], y[foot], "o", color=ACCENT, ms=5, label="footprint: nodes j-m..j")
    # velocity profile inside the band, 0 at the lower boundary, v at the upper
    xs = 0.25
    for f in np.linspace(0.25, 1, 4):
        yb = -d + t * xs + f * e
        ax.annotate(
            "",
            (xs + 0.3 * f * math.cos(beta), yb + 0.3 * f * math.sin(beta)),
            (xs, yb),
            arrowprops={"arrowstyle": "->", "color": "k", "lw": 0.9},
        )
    ax.text(
        0.1,
        -0.3,
        "displacement f·v across the band:\n0 at the lower boundary, v above",
        fontsize=9,
    )
    ax.legend(loc="upper right", fontsize=8, frameon=False)
    sketch(ax, (-0.2, 2.2), (-1.15, 0.75), "The shear band of the refined model (§3.2)")
    save(fig, "model_band.png")


def increment():
    """One slip-line increment on the grid Δx = v0: shift, rise, swept triangle."""
    d, dx = 1.0, 0.2
    x = np.arange(0, 2.01, dx)
    y = pile(x, 0.3, 1.2)
    j = 7
    r = (y[j] + d) / j
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6), sharey=True)
    before, after = axes
    for ax in axes:
        sketch(ax, (-0.3, 2.0), (-1.1, 0.85))
    before.fill_between(x, -d, y, color=GROUND, lw=0)
    before.plot(x, y, "k.-", ms=4, lw=0.8)
    before.plot([0, x[j]], [-d, y[j]], color=LINE, lw=1.8)
    blade(before, 0.0, 0.6, d)
    before.set_title("before: blade at node b, slip line to node j")
    new = y.copy()
    new[1 : j + 1] = y[0:j] + r
    new[1] += r
    after.fill_between(x[1:], -d, new[1:], color=GROUND, lw=0)
    after.plot(x[1:], y[1:], ":", color="grey", lw=0.8)
    after.plot(x[1:], new[1:], "k.-", ms=4, lw=0.8)
    tri = np.array([[0, -d], [dx, -d], [dx, -d + r]])
    before.add_patch(plt.Polygon(tri, color=ACCENT, alpha=0.6, lw=0))
    before.text(0.05, -d - 0.1, "swept: ½ v0² tan β", color=ACCENT, fontsize=8)
    blade(after, dx, 0.6, d)
    for i in range(j):
        after.annotate(
            "",
            (x[i + 1], new[i + 1] - (r if i == 0 else 0)),
            (x[i], y[i]),
            arrowprops={"arrowstyle": "->", "color": LINE, "lw": 0.7},
        )
    after.annotate(
        "face node raised a further\nv0 tan β: the swept soil",
        (x[1], new[1]),
        (0.45, 0.65),
        color=ACCENT,
        fontsize=8,
        arrowprops={"arrowstyle": "->", "color": ACCENT},
    )
    after.set_title("after: nodes b..j-1 moved to b+1..j, raised v0 tan β")
    save(fig, "model_increment.png")


def law(ut, initial, peak, residual, up, ur):
    """Fig. 2: piecewise linear in ut (crates/model/src/material.rs)."""
    out = np.empty_like(ut)
    for k, u in enumerate(ut):
        if u < up:
            out[k] = initial + (peak - initial) * u / up
        elif u < ur:
            out[k] = peak + (residual - peak) * (u - up) / (ur - up)
        else:
            out[k] = residual
    return out


def laws():
    """φ(ut) and ψ(ut) of the shipped paper cases (cases/paper/*.toml)."""
    cases = [
        ("Fig. 5", (20, 40, 30), (-5, 10, 0), 2, 4),
        ("Table 1 HS", (20, 35, 30), (-5, 5, 0), 2, 4),
        ("Table 1 S", (35, 35, 30), (0, 5, 0), 0, 4),
        ("original (φp 35°, φr 30°)", (35, 35, 30), (0, 0, 0), 0, 4),
    ]
    ut = np.linspace(0, 6, 601)
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.4))
    for name, phi, psi, up, ur in cases:
        a.plot(ut, law(ut, *phi, up, ur), label=name)
        b.plot(ut, law(ut, *psi, up, ur), label=name)
    a.set(xlabel="accumulated shear ut (mm)", ylabel="φ (degrees)", title="friction φ(ut)")
    b.set(xlabel="accumulated shear ut (mm)", ylabel="ψ (degrees)", title="dilation ψ(ut)")
    b.axhline(0, color="grey", lw=0.6)
    a.legend(fontsize=8, frameon=False)
    for ax in (a, b):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, "model_laws.png")


def avalanche():
    """A slope steeper than θr replaced by a line at θr of the same area."""
    dx, theta = 0.1, math.radians(30)
    s = dx * math.tan(theta)
    x = np.arange(0, 2.01, dx)
    y = np.where(x < 0.8, 0.9, np.where(x < 1.0, 0.9 - 4 * (x - 0.8), 0.1))
    y = np.maximum(y, 0.1)
    w = np.full_like(x, 1.0)
    w[0] = w[-1] = 0.5
    # pool-adjacent-violators on g = y + s i (non-decreasing), trapezoid weights
    g = y + s * np.arange(len(x))
    pools = []
    for i in range(len(x)):
        pools.append([i, 1, w[i], w[i] * g[i]])
        while len(pools) > 1 and pools[-2][3] / pools[-2][2] > pools[-1][3] / pools[-1][2]:
            top = pools.pop()
            pools[-1][1] += top[1]
            pools[-1][2] += top[2]
            pools[-1][3] += top[3]
    new = np.empty_like(y)
    for start, n, wsum, wg in pools:
        for i in range(start, start + n):
            new[i] = wg / wsum - s * i
    fig, ax = plt.subplots(figsize=(7, 3))
    ax.fill_between(x, 0, np.minimum(y, new), color=GROUND, lw=0)
    ax.fill_between(x, new, y, where=y > new, color=ACCENT, alpha=0.5, lw=0, label="removed")
    ax.fill_between(x, y, new, where=new > y, color=BAND, lw=0, label="deposited (same area)")
    ax.plot(x, y, "k:", lw=1, label="after the update")
    ax.plot(x, new, "k.-", ms=4, lw=1, label="relaxed: slope exactly θr")
    ax.legend(fontsize=8, frameon=False, loc="upper right")
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title("Avalanching (§6): steeper than θr = 30° is levelled to θr")
    save(fig, "model_avalanche.png")


def rake():
    """The shear x' = x + (y + d) cot α makes a raked face vertical."""
    d, alpha = 1.0, math.radians(60)
    c = 1 / math.tan(alpha)
    t = math.tan(math.radians(30))
    top = (-d * c, 0.0)
    emergence = (d / t, 0.0)
    soil = [(-1.2, -d - 0.2), (-1.2, -d), (0.0, -d), top, (2.2, 0.0), (2.2, -d - 0.2)]
    block = [(0.0, -d), top, emergence]
    face = [(0.0, -d), (-(d + 0.5) * c, 0.5)]
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.4))
    for ax, shear, title in (
        (a, 0.0, "physical: face at α"),
        (b, c, "grid: x' = x + (y + d) cot α"),
    ):

        def grid(points, shear=shear):
            return [(x + (y + d) * shear, y) for x, y in points]

        ax.add_patch(plt.Polygon(grid(soil), color=GROUND, lw=0))
        ax.add_patch(plt.Polygon(grid(block), color=BLOCK, lw=0))
        (fx0, fy0), (fx1, fy1) = grid(face)
        ax.plot([fx0, fx1], [fy0, fy1], color=BLADE, lw=4)
        (lx0, ly0), (lx1, ly1) = grid([(0.0, -d), emergence])
        ax.plot([lx0, lx1], [ly0, ly1], color=LINE, lw=1.8)
        ax.text(0.3, -d + 0.05, "β" if shear == 0 else "β'")
        sketch(ax, (-1.2, 2.4), (-1.5, 0.6), title)
    b.text(-1.1, -1.45, "tan β' = tan β / (1 + cot α tan β); areas unchanged", fontsize=9)
    save(fig, "model_rake.png")


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    mechanism()
    band()
    increment()
    laws()
    avalanche()
    rake()


if __name__ == "__main__":
    main()
