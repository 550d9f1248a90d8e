#!/usr/bin/python3
"""The mixer's outputs: the torque that drives the blade through the bed (-Mz, with Mz
the spheres' moment on the blade about its axis) and the mixing of the bed against
time.

The spheres are coloured by the side of the bowl they sit on (x < 0 or x > 0) when the
blade starts. The mixing index is Lacey's, M = (s0^2 - s^2) / (s0^2 - sr^2): s^2 the
variance of the fraction of one colour over the cells of a 10 mm grid that hold at least
5 spheres (weighted by their counts), s0^2 = p (1 - p) that of the segregated bed and
sr^2 = p (1 - p) / n that of a random mixture with n spheres a cell; 0 segregated, 1
mixed.

Usage: mixing.py OUTDIR [t_start]. Writes OUTDIR/mixer.png and prints the final index.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from liggghts_out import read_dump  # noqa: E402

CELL = 0.01
DT = 4.0e-5


def lacey(atoms, colour):
    cells = {}
    for i, a in atoms.items():
        if i not in colour:
            continue
        k = (math.floor(a["x"] / CELL), math.floor(a["y"] / CELL), math.floor(a["z"] / CELL))
        c = cells.setdefault(k, [0, 0])
        c[0] += 1
        c[1] += colour[i]
    use = [c for c in cells.values() if c[0] >= 5]
    n = sum(c[0] for c in use)
    if n == 0:
        return math.nan
    p = sum(c[1] for c in use) / n
    s2 = sum(c[0] * (c[1] / c[0] - p) ** 2 for c in use) / n
    s0 = p * (1 - p)
    sr = s0 / (n / len(use))
    return (s0 - s2) / (s0 - sr) if s0 > sr else math.nan


def main():
    out = sys.argv[1]
    t_start = float(sys.argv[2]) if len(sys.argv) > 2 else 0.2
    rows = [[float(v) for v in l.split()] for l in open(os.path.join(out, "post", "torque.txt"))
            if l.strip() and not l.startswith("#")]
    colour, tm, mi = None, [], []
    for step, atoms in read_dump(os.path.join(out, "post", "particles.dump")):
        t = step * DT
        if t < t_start - 1e-9:
            continue
        if colour is None:
            colour = {i: (1 if a["x"] < 0 else 0) for i, a in atoms.items()}
        tm.append(t)
        mi.append(lacey(atoms, colour))
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot([r[0] for r in rows], [-1e3 * r[2] for r in rows], color="C0")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("drive torque against the bed, -Mz (mN m)", color="C0")
    bx = ax.twinx()
    bx.plot(tm, mi, "o-", ms=3, color="C3")
    bx.set_ylim(0, 1.05)
    bx.set_ylabel("Lacey mixing index", color="C3")
    ax.axvline(t_start, color="0.6", ls=":")
    ax.set_title("Mixer: MESH blade (STL) in a REVOLUTION bowl")
    fig.tight_layout()
    png = os.path.join(out, "mixer.png")
    fig.savefig(png, dpi=110)
    turning = [-r[2] for r in rows if r[0] > t_start + 0.1]
    print("drive torque while turning: mean %.3g N m" % (sum(turning) / max(1, len(turning))))
    print("mixing index: %.2f at the start, %.2f at the end" % (mi[0], mi[-1]))
    print("plot: %s" % png)


if __name__ == "__main__":
    main()
