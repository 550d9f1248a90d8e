#!/usr/bin/python3
"""The three runs of in.slide (built-in coulomb, C law, Fortran VUINTER) against each
other and against the closed forms of a sphere on an incline of angle theta.

- Equivalence: the C law and the VUINTER do the built-in's operations in the same
  order, so every position, velocity and spin in the dumps must agree with the
  built-in run to 1e-12 (relative to r, 1 m/s and 1/r); the difference is printed.
- Rolling (mu = 0.3 >= 2/7 tan theta): a = 5/7 g sin theta, omega_z = -v / r,
  no frictional dissipation.
- Sliding (mu = 0.1 < 2/7 tan theta): a = g (sin theta - mu cos theta),
  omega_z = -5/2 mu g cos theta t / r, and the frictional dissipation is mu N times
  the slip distance, ALLFD = 4 mu m g cos theta * g (sin theta - 7/2 mu cos theta) t^2 / 2
  for the four spheres.
Closed forms within 0.5 %. Usage: compare.py OUTDIR. Prints PASS/FAIL with the numbers.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from liggghts_out import read_dump  # noqa: E402

G, R, RHO, THETA, DT = 9.81, 0.002, 2500.0, math.radians(30.0), 1.0e-5
MU = {1: 0.3, 2: 0.1}
LAWS = ("builtin", "c", "vuinter")
TOL_EQ, TOL = 1e-12, 5e-3


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out"
    runs = {law: read_dump(os.path.join(out, "post", "slide_%s.dump" % law)) for law in LAWS}
    ok = True

    scale = {"x": R, "y": R, "vx": 1.0, "vy": 1.0, "omegaz": 1.0 / R}
    ref = runs["builtin"]
    for law in LAWS[1:]:
        worst, where = 0.0, ""
        same_shape = len(runs[law]) == len(ref)
        for (s1, a1), (s2, a2) in zip(ref, runs[law]):
            same_shape = same_shape and s1 == s2 and set(a1) == set(a2)
            for i in a1:
                for c, sc in scale.items():
                    d = abs(a1[i][c] - a2[i][c]) / sc
                    if d > worst:
                        worst, where = d, "%s of sphere %d at step %d" % (c, i, s1)
        good = same_shape and worst <= TOL_EQ
        ok = ok and good
        print("%-4s law %-8s = built-in coulomb: largest difference %.3g %s (%d frames)"
              % ("PASS" if good else "FAIL", law, worst, ("(" + where + ")") if where else "",
                 len(ref)))

    step, last = ref[-1]
    t = step * DT
    first = ref[0][1]
    s, c = math.sin(THETA), math.cos(THETA)
    for typ, name in ((1, "rolling"), (2, "sliding")):
        mu = MU[typ]
        if typ == 1:
            a, w_of = 5.0 / 7.0 * G * s, (lambda v: -v / R)
        else:
            a, w_of = G * (s - mu * c), (lambda v: -2.5 * mu * G * c * t / R)
        for i in sorted(k for k in last if int(last[k]["type"]) == typ):
            dx = last[i]["x"] - first[i]["x"]
            v = last[i]["vx"]
            e_x = dx / (0.5 * a * t * t) - 1.0
            e_v = v / (a * t) - 1.0
            e_w = last[i]["omegaz"] / w_of(a * t) - 1.0
            good = max(abs(e_x), abs(e_v), abs(e_w)) <= TOL
            ok = ok and good
            print("%-4s sphere %d %s (mu %.1f), t = %.2f s: x %.6f m (closed form %.6f, %+.2e), "
                  "v %.5f m/s (%+.2e), omega_z %.3f rad/s (%+.2e)"
                  % ("PASS" if good else "FAIL", i, name, mu, t, dx, 0.5 * a * t * t, e_x, v,
                     e_v, last[i]["omegaz"], e_w))

    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    with open(os.path.join(out, "log_builtin.liggghts")) as f:
        fd = re.search(r"ALLFD rough (\S+) smooth (\S+)", f.read())
    fd_rough, fd_smooth = float(fd.group(1)), float(fd.group(2))
    mu = MU[2]
    fd_th = 4 * mu * m * G * c * 0.5 * G * (s - 3.5 * mu * c) * t * t
    good = abs(fd_smooth / fd_th - 1.0) <= TOL and abs(fd_rough) <= 1e-3 * fd_th
    ok = ok and good
    print("%-4s frictional dissipation (ALLFD): sliding %.5e J (closed form %.5e, %+.2e), "
          "rolling %.2e J (no slip)" % ("PASS" if good else "FAIL", fd_smooth, fd_th,
                                          fd_smooth / fd_th - 1.0, fd_rough))
    print("user laws: %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
