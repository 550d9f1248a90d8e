#!/usr/bin/python3
"""fix wall/rigid warns once when the time step exceeds 0.2 of its law's critical step.

The critical steps are computed here from their closed forms, independently of the
code: the Rayleigh time pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = Y / (2 (1 + nu)),
for hertz (LIGGGHTS's material properties of the smallest sphere), and 2 sqrt(m / K)
for the spring laws (hooke: K = max(kn, 7 kt / 2); linear_softening with a projected
area: K = k pi R^2). Each deck has two spheres of different radii, so the check must
take the smallest step over the particles. A step 10 times over the limit warns, with
the critical step printed to 1e-5; a step under it does not.
"""
import math
import re

import liglib as L

RHO = 2500.0
RADII = (0.004, 0.002)
YOUNG, POISSON = 5.0e7, 0.3


def rayleigh(r):
    m = RHO * 4.0 / 3.0 * math.pi * r ** 3
    g = YOUNG / (2.0 * (1.0 + POISSON))
    rho = 3.0 * m / (4.0 * math.pi * r ** 3)
    return math.pi * r * math.sqrt(rho / g) / (0.1631 * POISSON + 0.8766)


def spring(r, k):
    return 2.0 * math.sqrt(RHO * 4.0 / 3.0 * math.pi * r ** 3 / k)


def deck(dt, law):
    d = L.header((-0.1, 0.1, -0.1, 0.1, -0.05, 0.2), dt, young=(YOUNG, 2.0e8),
                 poisson=(POISSON, 0.25))
    d += L.sphere(1, (0.0, 0.0, 0.02), RADII[0], RHO)
    d += L.sphere(2, (0.05, 0.0, 0.02), RADII[1], RHO)
    d += "fix w all wall/rigid surface plane.inp %s\n" % law
    d += "fix integr all nve/sphere\nrun 2\nrun 2\n"
    return d


def body(s):
    s.write("plane.inp", L.plane_z(0.0, 1.0))
    kn, kt, k_area = 2.0e4, 1.0e4, 3.0e8
    cases = [
        ("hertz", "law hertz type 2", min(rayleigh(r) for r in RADII)),
        ("hooke", "law hooke props %g %g 0 0 0.5 type 2" % (kn, kt),
         min(spring(r, max(kn, 3.5 * kt)) for r in RADII)),
        ("linear_softening", "law linear_softening props %g area projected type 2" % k_area,
         min(spring(r, k_area * math.pi * r * r) for r in RADII)),
    ]
    for name, law, tcrit in cases:
        for factor, warn in ((10.0, True), (0.5, False)):
            dt = factor * 0.2 * tcrit
            rc, out = s.run("%s_%g" % (name, factor), deck(dt, law))
            lines = [l for l in out.splitlines()
                     if l.startswith("WARNING") and "critical step" in l]
            tag = "%s, dt = %g x 0.2 t_crit" % (name, factor)
            if not warn:
                s.ck.check(tag + ": no warning", not lines, "; ".join(lines))
                continue
            if not s.ck.check(tag + ": one warning over two runs", len(lines) == 1,
                              "%d" % len(lines), why=out[-600:]):
                continue
            m = re.search(r"of the critical step ([0-9.eE+-]+) of law '(\w+)'", lines[0])
            got = float(m.group(1)) if m else float("nan")
            s.ck.check(tag + ": the critical step is the closed form",
                       m is not None and m.group(2) == name
                       and abs(got - tcrit) <= 1e-5 * tcrit,
                       "%.6g vs %.6g" % (got, tcrit), why=lines[0])


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
