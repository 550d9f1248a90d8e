#!/usr/bin/python3
"""The standalone driver and fix wall/rigid give a law the same contact block.

One sphere with a prescribed velocity (fix move linear in LIGGGHTS, prescribed nodal
velocity in the driver) approaches and penetrates a wall obliquely, law hertz with
`curvature yes`: the effective radius then comes from the wall's principal curvatures.
Two walls: the inside of a cylinder (curvatures 0 and -1/Rc) and the outside of a
sphere (1/Rs, 1/Rs). The normal and tangential stress histories of the two engines must
agree to 1e-9 relative. Positions are dyadic numbers, so both engines put the sphere at
exactly the same place at every step. An independent answer pins the value as well:
the normal force is LIGGGHTS's Hertz formula with Hertz's equivalent radius of the
elliptical contact, Re = 1/sqrt((1/R + k1)(1/R + k2)).
"""
import argparse
import math
import os
import subprocess
import sys

import liglib as L

R, RHO = 0.005, 2500.0
DT = 2.0 ** -17
YP, NUP, YW, NUW, E, MU = 5.0e7, 0.3, 2.0e8, 0.25, 0.7, 0.5
TRACKING = 0.002   # the header's neighbour skin: the fix's default tracking
TOL = 1e-9


def hertz_normal(delta, vn, reff, m):
    """LIGGGHTS's Hertz wall: Fn = kn delta - gamma_n vn (vn < 0 approaching)."""
    ystar = 1.0 / ((1 - NUP ** 2) / YP + (1 - NUW ** 2) / YW)
    sn = 2.0 * ystar * math.sqrt(reff * delta)
    kn = 4.0 / 3.0 * ystar * math.sqrt(reff * delta)
    beta = math.log(E) / math.sqrt(math.log(E) ** 2 + math.pi ** 2)
    gamma_n = -2.0 * math.sqrt(5.0 / 6.0) * beta * math.sqrt(sn * m)
    return kn * delta - gamma_n * vn


def case(s, ap, name, surf_text, surf_name, x0, v, steps, k1, k2, normal_at):
    s.write(name + ".inp", surf_text)
    box = (-0.08, 0.08, -0.08, 0.08, -0.08, 0.08)
    deck = L.header(box, DT, young=(YP, YW), poisson=(NUP, NUW), e=E, mu=MU)
    deck += L.sphere(1, x0, R, RHO)
    deck += ("fix w all wall/rigid surface %s.inp name %s law hertz type 2 curvature yes "
             "peratom yes\n"
             % (name, surf_name))
    deck += "fix mv all move linear %.17g %.17g %.17g\n" % tuple(v)
    deck += L.dump_lines("d", 1, name + ".dump", cols="id mass x y z f_w[1] f_w[4] f_w[5] f_w[6]")
    deck += "run %d\n" % steps
    s.run(name, deck)
    frames = L.read_dump(s.path(name + ".dump"))
    lig = {step: atoms[1] for step, atoms in frames}
    m = lig[0]["mass"]
    out = subprocess.run(
        [ap.driver, s.path(name + ".inp"), surf_name] +
        ["%.17g" % a for a in (R, m, x0[0], x0[1], x0[2], v[0], v[1], v[2], DT, steps,
                               TRACKING, YP, NUP, YW, NUW, E, MU, 1)],
        capture_output=True, text=True)
    if not s.ck.check(name + ": the driver ran", out.returncode == 0, out.stderr.strip()):
        return
    drv = {}
    for line in out.stdout.splitlines():
        f = line.split()
        drv[int(f[0])] = [float(t) for t in f[1:]]
    s.ck.check(name + ": both engines gave every step", set(drv) == set(lig),
               "%d vs %d steps" % (len(drv), len(lig)))
    # positions: the prescribed motion puts the sphere at x0 + n dt v exactly
    exact = all(lig[n][c] == x0[i] + n * DT * v[i]
                for n in lig for i, c in enumerate(("x", "y", "z")))
    s.ck.check(name + ": LIGGGHTS moved the sphere to x0 + n dt v exactly", exact)
    smax = [max(abs(lig[n][c]) for n in lig) for c in ("f_w[4]", "f_w[5]", "f_w[6]")]
    s.ck.check(name + ": the sphere made contact with normal and tangential stress",
               smax[0] > 0 and smax[1] > 0 and smax[2] > 0, "max |s| %s" % smax)
    worst = [0.0, 0.0, 0.0]
    for n in sorted(set(drv) & set(lig)):
        for c, col in enumerate(("f_w[4]", "f_w[5]", "f_w[6]")):
            d = abs(drv[n][c] - lig[n][col]) / max(smax[c], 1e-300)
            worst[c] = max(worst[c], d)
    s.ck.check(name + ": driver and fix stress histories agree to %g of their peak" % TOL,
               max(worst) <= TOL, "worst s1 %.3g s2 %.3g s3 %.3g" % tuple(worst))
    # the closed form at the last step: delta from rdisp1, vn = v . n
    last = max(lig)
    delta = lig[last]["f_w[1]"]
    p = (lig[last]["x"], lig[last]["y"], lig[last]["z"])
    n = normal_at(p)
    vn = sum(v[i] * n[i] for i in range(3))
    reff = 1.0 / math.sqrt((1.0 / R + k1) * (1.0 / R + k2))
    want = hertz_normal(delta, vn, reff, m)
    got = lig[last]["f_w[4]"]
    s.ck.check(name + ": normal force is Hertz's with Re = 1/sqrt((1/R+k1)(1/R+k2))",
               abs(got - want) <= 1e-9 * abs(want),
               "%.12g vs %.12g (with R instead of Re: %.12g)"
               % (got, want, hertz_normal(delta, vn, R, m)))


def body(s, ap):
    # 1. inside a cylinder of radius 0.05 about z: the sphere moves out radially (x),
    #    along the generator (z) and round the hoop (y).
    rc = 0.05
    x0 = (0.04296875, 0.0, 0.0)          # 11/256: gap 0.00203125 > tracking
    v = (0.125, 0.03125, 0.0625)
    case(s, ap, "cylinder_inside", L.drum(rc, -0.07, 0.07), "mantle", x0, v, 2300,
         0.0, -1.0 / rc,
         lambda p: tuple(-c / math.hypot(p[0], p[1]) for c in (p[0], p[1])) + (0.0,))
    # 2. outside a sphere of radius 0.03 about the origin: a half circle from the top
    #    pole to the bottom one, revolved; its normal points outward.
    rs = 0.03
    sph = ("*SURFACE, TYPE=REVOLUTION, NAME=ball\n0, 0, 0, 0, 0, 1\n"
           "START, 0, %r\nCIRCL, %r, 0, 0, 0\nCIRCL, 0, %r, 0, 0\n" % (rs, rs, -rs))
    x0 = (0.03515625, 0.0, 0.0)          # 9/256: gap 0.00015625 inside the tracking
    v = (-0.125, 0.0625, 0.03125)
    case(s, ap, "sphere_outside", sph, "ball", x0, v, 250, 1.0 / rs, 1.0 / rs,
         lambda p: tuple(c / math.sqrt(sum(q * q for q in p)) for c in p))


if __name__ == "__main__":
    ap = argparse.ArgumentParser(add_help=False)
    ap.add_argument("--driver", default=os.environ.get("RS_DRIVER_HERTZ"),
                    help="the driver_hertz program (default: $RS_DRIVER_HERTZ)")
    known, rest = ap.parse_known_args()
    if not known.driver:
        sys.exit("test_driver_equivalence.py: give --driver or set RS_DRIVER_HERTZ")
    sys.argv = [sys.argv[0]] + rest
    sess = L.Session(__doc__)
    L.main_guard(sess, lambda s: body(s, known))
