#!/usr/bin/python3
"""Speeds of spheres running down the arc of the curved chute, against energy balance.

A sphere released from rest at angle phi0 (from the bottom) on the inside of a circular
arc of radius Rc moves its centre on the circle of radius Rp = Rc - r. At angle phi:
- sliding without friction, it does not spin:      v^2 = 2 g Rp (cos phi - cos phi0)
- rolling without slipping (I = 2/5 m r^2, v = w r): v^2 = 10/7 g Rp (cos phi - cos phi0)
Checks, at the bottom of the arc (x = 0, interpolated between dump frames):
- speed within 0.5 % of the closed form (the Hertz contact stores a little elastic
  energy and its damping takes a little),
- rolling spheres: slip |v - w r| / v below 1 %; sliding spheres: |w| r / v below 1e-3.
Usage: check.py OUTDIR. Writes OUTDIR/chute_speed.png, prints a table and PASS/FAIL.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from liggghts_out import read_dump  # noqa: E402

G, RC, R = 9.81, 0.2, 0.002
RP = RC - R
TOL_V, TOL_SLIP, TOL_SPIN = 0.005, 0.01, 1e-3


def angle(a):
    return math.atan2(-a["x"], RC - a["y"])


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    frames = [atoms for _, atoms in read_dump(os.path.join(out, "post", "spheres.dump"))]
    fig, ax = plt.subplots(figsize=(8, 5))
    ok = True
    print("%-8s %6s %12s %12s %8s %10s" % ("sphere", "phi0", "v_bottom", "closed form",
                                           "error", "slip/spin"))
    for sid in sorted(frames[0]):
        typ = int(frames[0][sid]["type"])
        rolling = typ == 1
        c = 10.0 / 7.0 if rolling else 2.0
        phi0 = angle(frames[0][sid])
        phis, vs = [], []
        bottom = None
        for prev, cur in zip(frames, frames[1:]):
            if sid not in cur:
                break
            a, b = prev[sid], cur[sid]
            if b["x"] < 0:
                phis.append(math.degrees(angle(b)))
                vs.append(math.hypot(b["vx"], b["vy"]))
            if a["x"] < 0 <= b["x"] and bottom is None:
                s = -a["x"] / (b["x"] - a["x"])
                bottom = {k: a[k] + s * (b[k] - a[k]) for k in ("vx", "vy", "omegaz")}
        if bottom is None:
            print("sphere %d never reached the bottom of the arc" % sid)
            ok = False
            continue
        v = math.hypot(bottom["vx"], bottom["vy"])
        v_th = math.sqrt(c * G * RP * (1.0 - math.cos(phi0)))
        err = (v - v_th) / v_th
        if rolling:
            # moving +x on a floor below the centre, rolling means omega_z = -v / r
            slip = abs(bottom["vx"] + bottom["omegaz"] * R) / v
            good = abs(err) <= TOL_V and slip <= TOL_SLIP
        else:
            slip = abs(bottom["omegaz"]) * R / v
            good = abs(err) <= TOL_V and slip <= TOL_SPIN
        ok = ok and good
        print("%-8s %5.0f° %10.4f m/s %8.4f m/s %+7.2f%% %10.2e %s"
              % ("%d %s" % (sid, "roll" if rolling else "slide"), math.degrees(phi0), v, v_th,
                 100 * err, slip, "ok" if good else "FAIL"))
        col = "C0" if rolling else "C3"
        ax.plot(phis, vs, ".", ms=3, color=col)
        grid = [phi0 * (1 - j / 100.0) for j in range(101)]
        ax.plot([math.degrees(p) for p in grid],
                [math.sqrt(max(0.0, c * G * RP * (math.cos(p) - math.cos(phi0)))) for p in grid],
                "-", lw=0.8, color=col)
    ax.plot([], [], ".", color="C0", label="rolling (friction 0.8), fix wall/rigid")
    ax.plot([], [], "-", color="C0", label="v² = 10/7 g Rp (cos φ − cos φ0)")
    ax.plot([], [], ".", color="C3", label="sliding (friction 0), fix wall/rigid")
    ax.plot([], [], "-", color="C3", label="v² = 2 g Rp (cos φ − cos φ0)")
    ax.invert_xaxis()
    ax.set_xlabel("angle φ from the bottom of the arc (degrees)")
    ax.set_ylabel("speed (m/s)")
    ax.set_title("Spheres on the curved chute (CYLINDER, arc profile)")
    ax.legend(fontsize=9)
    fig.tight_layout()
    png = os.path.join(out, "chute_speed.png")
    fig.savefig(png, dpi=110)
    print("plot: %s" % png)
    print("chute energy balance: %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
