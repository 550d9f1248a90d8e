#!/usr/bin/python3
"""The drum analytic against tessellated: the dynamic angle of repose from the bed's
centre of mass against time for both walls (OUTDIR/KIND/angle.txt, written by
examples/drum/angle.py), the steady values, and each run's loop time from its log.

Usage: compare.py OUTDIR. Writes OUTDIR/compare.png and prints a table.
"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_angle(path):
    t, th = [], []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        v = line.split()
        t.append(float(v[0]))
        th.append(float(v[1]))
    return t, th


def loop_time(log):
    times = [float(m) for m in re.findall(r"Loop time of ([0-9.eE+-]+)", open(log).read())]
    return sum(times)


def steady(summary):
    m = re.search(r"centre of mass:\s+([0-9.]+) deg \(std ([0-9.]+)", open(summary).read())
    return (float(m.group(1)), float(m.group(2))) if m else (math.nan, math.nan)


def main():
    out = sys.argv[1]
    fig, ax = plt.subplots(figsize=(8, 5))
    rows = []
    for kind, label in (("analytic", "REVOLUTION (analytic)"),
                        ("mesh", "MESH (14040 triangles)")):
        d = os.path.join(out, kind)
        t, th = read_angle(os.path.join(d, "angle.txt"))
        m, s = steady(os.path.join(d, "angle_summary.txt"))
        lt = loop_time(os.path.join(d, "log_%s.liggghts" % kind))
        ax.plot(t, th, label="%s: %.1f° ± %.1f°, %.0f s" % (label, m, s, lt))
        rows.append((kind, m, s, lt))
    ax.set_xlabel("time (s)")
    ax.set_ylabel("dynamic angle of repose (degrees)")
    ax.set_ylim(-5, 60)
    ax.legend(loc="lower right")
    ax.set_title("Rotating drum: the analytic wall and its tessellation")
    fig.tight_layout()
    png = os.path.join(out, "compare.png")
    fig.savefig(png, dpi=110)
    print("%-9s %18s %14s" % ("wall", "angle of repose", "loop time (s)"))
    for kind, m, s, lt in rows:
        print("%-9s %11.1f ± %3.1f %14.1f" % (kind, m, s, lt))
    print("mesh / analytic loop time: %.2f" % (rows[1][3] / rows[0][3]))
    print("plot: %s" % png)


if __name__ == "__main__":
    main()
