#!/usr/bin/python3
"""Discharge rate of the conical hopper, from the outputs of in.hopper.

- The mass above the outlet exit, m(t), is printed every 200 steps. The discharge rate
  is W = -dm/dt: a moving 40 ms difference for the plot, and the slope of a straight
  fit of m(t) from 0.1 s after the opening to the end for the steady value.
- Beverloo's correlation (Beverloo, Leniger and van de Velde 1961; Nedderman, Statics
  and kinematics of granular materials, 1992):
      W = C rho_b sqrt(g) (D0 - k d)^(5/2),  C = 0.58, k = 1.5,
  with rho_b the bulk density measured in a frustum of the cone before the opening, d
  the number-mean diameter and D0 the outlet diameter. Beverloo is for flat-bottomed
  bins; for a cone of half-angle theta the Rose and Tanaka factor
  F = (tan theta tan phi_d)^(-0.35), with the stagnant-zone angle phi_d = 45 degrees,
  is applied. D0/d = 6 here, the lower end of where the correlation is used.
- Static check before the opening: the hopper and the plug together carry the weight
  of the bed (sum of the wall forces Fz = -m g, to 2 %).

Usage: flow.py OUTDIR. Writes OUTDIR/discharge.png, prints the numbers; exit status 1
if the static check fails or the rate is not within a factor 1.5 of Beverloo.
"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from liggghts_out import read_table  # noqa: E402

G = 9.81
D0 = 0.015                      # outlet diameter (hopper.inp)
THETA = math.radians(30.0)      # cone half-angle from the vertical (hopper.inp)
RADII = (0.00115, 0.00135)      # the two sphere sizes, 50 % of the mass each (in.hopper)
FRUSTUM = (0.0103868, 0.0219338, 0.020)   # region frustum: r_lo, r_hi, height
C_BEV, K_BEV = 0.58, 1.5


def fit_line(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    b = sum((a - mx) * (c - my) for a, c in zip(x, y)) / sxx
    res = [c - (my + b * (a - mx)) for a, c in zip(x, y)]
    return my - b * mx, b, math.sqrt(sum(r * r for r in res) / n)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    rows = read_table(os.path.join(out, "post", "mass.txt"))
    with open(os.path.join(out, "log_hopper.liggghts")) as f:
        t_open = float(re.search(r"OPEN at t = ([0-9.eE+-]+)", f.read()).group(1))
    t = [r[0] for r in rows]
    m = [r[1] for r in rows]

    # Static check and bulk density: the last rows before the opening.
    before = [r for r in rows if t_open - 0.03 <= r[0] <= t_open]
    m0 = before[-1][1]
    fz = before[-1][4] + before[-1][5]
    plug_share = before[-1][5] / fz if fz else float("nan")
    static_err = abs(fz + m0 * G) / (m0 * G)
    r1, r2, h = FRUSTUM
    v_frustum = math.pi * h * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0
    rho_b = sum(r[3] for r in before) / len(before) / v_frustum

    # Number-mean diameter of the two sizes mixed 50/50 by mass.
    w = [0.5 / r ** 3 for r in RADII]
    d = 2.0 * sum(wi * r for wi, r in zip(w, RADII)) / sum(w)

    # Steady rate: fit of m(t) from 0.1 s after the opening.
    sel = [(a, b) for a, b in zip(t, m) if a >= t_open + 0.1]
    a0, slope, rms = fit_line([p[0] for p in sel], [p[1] for p in sel])
    w_sim = -slope
    w_bev = C_BEV * rho_b * math.sqrt(G) * (D0 - K_BEV * d) ** 2.5
    f_cone = (math.tan(THETA) * math.tan(math.radians(45.0))) ** -0.35
    w_bev_cone = w_bev * f_cone
    ratio = w_sim / w_bev_cone

    # Moving-difference rate for the plot.
    lag = 0.04
    tw, ww = [], []
    for i, ti in enumerate(t):
        j = next((k for k in range(i, len(t)) if t[k] >= ti + lag), None)
        if j is None:
            break
        tw.append(0.5 * (ti + t[j]))
        ww.append(-(m[j] - m[i]) / (t[j] - ti))

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.8))
    ax.plot(t, [1e3 * v for v in m], color="C0", label="mass above the outlet")
    xs = [sel[0][0], sel[-1][0]]
    ax.plot(xs, [1e3 * (a0 + slope * x) for x in xs], "--", color="C3",
            label="fit: W = %.1f g/s" % (1e3 * w_sim))
    ax.axvline(t_open, color="0.5", ls=":", label="outlet opened")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("mass (g)")
    ax.legend()
    ax.set_title("Conical hopper, fix wall/rigid (REVOLUTION)")
    bx.plot(tw, [1e3 * v for v in ww], color="C0", label="-dm/dt (40 ms difference)")
    bx.axhline(1e3 * w_sim, color="C3", ls="--", label="steady fit %.1f g/s" % (1e3 * w_sim))
    bx.axhline(1e3 * w_bev_cone, color="k", ls="-.",
               label="Beverloo x cone factor %.1f g/s" % (1e3 * w_bev_cone))
    bx.axhline(1e3 * w_bev, color="0.5", ls=":",
               label="Beverloo, flat bottom %.1f g/s" % (1e3 * w_bev))
    bx.axvline(t_open, color="0.5", ls=":")
    bx.set_xlabel("time (s)")
    bx.set_ylabel("discharge rate (g/s)")
    bx.set_ylim(bottom=min(0.0, min(ww) * 1e3))
    bx.legend(loc="lower right", fontsize=9)
    fig.tight_layout()
    png = os.path.join(out, "discharge.png")
    fig.savefig(png, dpi=110)

    print("before opening: bed %.2f g, hopper + plug Fz = %.4f N, -m g = %.4f N "
          "(error %.2f %%), plug carries %.0f %%"
          % (1e3 * m0, fz, -m0 * G, 100 * static_err, 100 * plug_share))
    print("bulk density in the cone %.0f kg/m3 (solid fraction %.3f), d = %.3f mm, "
          "D0/d = %.1f" % (rho_b, rho_b / 2500.0, 1e3 * d, D0 / d))
    print("discharge rate (fit from t = %.2f s): %.2f g/s (rms of fit %.2f g)"
          % (t_open + 0.1, 1e3 * w_sim, 1e3 * rms))
    print("Beverloo (C = %.2f, k = %.1f): flat bottom %.2f g/s, with the cone factor "
          "%.3f: %.2f g/s" % (C_BEV, K_BEV, 1e3 * w_bev, f_cone, 1e3 * w_bev_cone))
    print("simulation / Beverloo (cone) = %.2f" % ratio)
    print("plot: %s" % png)
    ok_static = static_err <= 0.02
    ok_bev = 1 / 1.5 <= ratio <= 1.5
    print("static balance: %s; rate within a factor 1.5 of Beverloo: %s"
          % ("PASS" if ok_static else "FAIL", "PASS" if ok_bev else "FAIL"))
    return 0 if ok_static and ok_bev else 1


if __name__ == "__main__":
    sys.exit(main())
