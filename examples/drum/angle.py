#!/usr/bin/python3
"""Dynamic angle of repose of the rotating drum, from the outputs of in.drum.

Two independent estimates, in the x-y plane (normal to the drum axis z):
- centre of mass: the bed is a circular segment cut by a flat free surface, and such
  a segment is symmetric about the radius normal to its chord, so its centre of mass
  lies on that radius: the surface angle is atan2(x_com, -y_com). The end caps do not
  change this (they are normal to the axis).
- free-surface fit: the highest sphere top in each 4 mm wide strip along x, kept where
  it lies at least 8 mm from the mantle, fitted by a straight line y = a + b x; the
  angle is atan(b). This sees the middle of the surface only.

Usage: angle.py OUTDIR [t_start_of_rotation]
Writes OUTDIR/angle_of_repose.png and OUTDIR/angle.txt, prints the steady value.
Exit status 1 if the angle has not settled (the two halves of the averaging window
differ by more than 2 degrees) or the two estimates disagree by more than 5 degrees.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from liggghts_out import read_dump  # noqa: E402

R_DRUM = 0.05
STRIP = 0.004
MARGIN = 0.008


def read_com(path):
    t, th, om = [], [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = [float(x) for x in line.split()]
            t.append(v[0])
            th.append(math.degrees(math.atan2(v[1], -v[2])))
            om.append(v[3])
    return t, th, om


def surface_fit(pts):
    """Slope angle (degrees) of the free surface and the points used, or None."""
    top = {}
    for x, y, r in pts:
        k = int(math.floor(x / STRIP))
        if k not in top or y + r > top[k][1]:
            top[k] = (x, y + r)
    use = [p for p in top.values() if math.hypot(p[0], p[1]) < R_DRUM - MARGIN]
    if len(use) < 4:
        return None, use
    n = len(use)
    mx = sum(p[0] for p in use) / n
    my = sum(p[1] for p in use) / n
    sxx = sum((p[0] - mx) ** 2 for p in use)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in use)
    b = sxy / sxx
    return math.degrees(math.atan(b)), (use, my - b * mx, b)


def mean_std(v):
    m = sum(v) / len(v)
    return m, math.sqrt(sum((x - m) ** 2 for x in v) / len(v))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    dt = 3.0e-5
    t_rot = float(sys.argv[2]) if len(sys.argv) > 2 else None
    t, th, om = read_com(os.path.join(out, "post", "com.txt"))
    frames = [(step, [(a["x"], a["y"], a["radius"]) for a in atoms.values()])
              for step, atoms in read_dump(os.path.join(out, "post", "particles.dump"))]
    tf, thf, last_fit = [], [], None
    for step, pts in frames:
        a, fit = surface_fit(pts)
        if a is not None:
            tf.append(step * dt)
            thf.append(a)
            last_fit = (pts, fit)

    # Averaging window: the last 40 % of the time the drum turns at full speed.
    wmax = max(om)
    full = [ti for ti, w in zip(t, om) if w >= 0.999 * wmax]
    t0 = full[0] if t_rot is None else t_rot
    t_end = t[-1]
    tw = t_end - 0.4 * (t_end - t0)
    win = [a for ti, a in zip(t, th) if ti >= tw]
    winf = [a for ti, a in zip(tf, thf) if ti >= tw]
    m, s = mean_std(win)
    mf, sf = mean_std(winf)
    half = len(win) // 2
    drift = abs(mean_std(win[:half])[0] - mean_std(win[half:])[0])

    with open(os.path.join(out, "angle.txt"), "w") as f:
        f.write("# t angle_com_deg omega\n")
        for row in zip(t, th, om):
            f.write("%.5f %.4f %.4f\n" % row)

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 5),
                                 gridspec_kw={"width_ratios": [1.6, 1]})
    ax.plot(t, th, "-", color="C0", label="from the centre of mass")
    ax.plot(tf, thf, "o", ms=3, color="C1", label="straight fit of the free surface")
    ax.axhline(m, color="k", ls="--", lw=1,
               label="steady %.1f° ± %.1f° (t ≥ %.2f s)" % (m, s, tw))
    ax.axvspan(tw, t_end, color="0.9")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("dynamic angle of repose (degrees)")
    ax.set_ylim(-5, max(60, max(th) + 5))
    ax2 = ax.twinx()
    ax2.plot(t, om, ":", color="C2")
    ax2.set_ylabel("drum speed (rad/s)", color="C2")
    ax2.set_ylim(0, 2.5 * wmax)
    ax.legend(loc="upper left", fontsize=9)
    ax.set_title("Rotating drum, fix wall/rigid (REVOLUTION), %d spheres" % len(frames[-1][1]))

    pts, (use, a0, b) = last_fit
    bx.add_patch(plt.Circle((0, 0), R_DRUM, fill=False, color="k"))
    bx.scatter([p[0] for p in pts], [p[1] for p in pts], s=2, c="0.6")
    bx.plot([p[0] for p in use], [p[1] for p in use], "o", ms=3, color="C1")
    xs = [min(p[0] for p in use), max(p[0] for p in use)]
    bx.plot(xs, [a0 + b * x for x in xs], "-", color="C3",
            label="fit: %.1f°" % math.degrees(math.atan(b)))
    bx.set_aspect("equal")
    bx.set_xlim(-0.055, 0.055)
    bx.set_ylim(-0.055, 0.055)
    bx.set_title("last frame, t = %.2f s (x-y plane)" % (frames[-1][0] * dt))
    bx.legend(loc="upper left", fontsize=9)
    fig.tight_layout()
    png = os.path.join(out, "angle_of_repose.png")
    fig.savefig(png, dpi=110)

    print("dynamic angle of repose, steady (t >= %.2f s):" % tw)
    print("  centre of mass:   %.1f deg (std %.1f, halves differ by %.1f)" % (m, s, drift))
    print("  free-surface fit: %.1f deg (std %.1f)" % (mf, sf))
    print("plot: %s" % png)
    ok = drift <= 2.0 and abs(m - mf) <= 5.0
    print("steady: %s" % ("yes" if ok else "NO"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
