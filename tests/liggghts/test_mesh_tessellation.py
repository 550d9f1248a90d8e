#!/usr/bin/python3
"""A tessellated drum is the polygon it tessellates, and converges to the drum.

A sphere (radius 4 mm, Hertz, friction 0.5) starts at rest 30 degrees up the inside of
a drum of radius 50 mm about the z axis, under gravity along -x, and rolls back and
forth for 0.3 s (30000 steps).

Pins:
- Exactness. The drum as an STL of N rectangles (2N triangles, nodes on the circle) and
  the same N-gon as a CYLINDER whose profile is N LINEs are one surface given two ways,
  found by two independent closest-feature codes (src/faceted/ and analytic_surfaces/).
  Across each concave fold the sphere holds two contacts whose shares sum to 1 (the
  rule of docs/conventions.md, "Shares at concave folds"). For N = 360 and 720 the two
  trajectories agree to 1e-9 relative at every output step. (At N = 90 the folds turn the
  path by 4 degrees: a start moved by 1e-15 of itself already moves the velocity by
  about 1e-6, so only a statistical comparison would mean anything there.)
- Convergence. Against the analytic drum (a REVOLUTION), the largest distance between
  the centres over the run falls as N grows: N = 90, 360, 720 give strictly decreasing
  errors, and N = 720's is below a tenth of N = 90's.
- The share in the force. A frictionless sphere settles on the fold line of a shallow V
  (two planes at half a degree each side of the y axis, so that the fold is met with
  overlap), as an STL and as a CYLINDER profile of two LINEs. It holds two contacts, each with
  share 1/2, so the two faces carry one Hertz force between them: the overlap d solves
  4/3 E* sqrt(R) d^1.5 cos(0.5 deg) = m g (with both forces whole it would be 2^(-2/3) of
  that), and the centre rests at z = (R - d) / cos(0.5 deg), to 1e-6; the wall carries
  m g to 1e-6.
"""
import math

import liglib as L
from test_mesh_wall import stl

RC, R, RHO, DT, STEPS = 0.05, 0.004, 2500.0, 1e-5, 30000
ZLO, ZHI = -0.02, 0.02
TOL = 1e-9
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}


def corner(k, n):
    a = 2 * math.pi * k / n
    return RC * math.cos(a), RC * math.sin(a)


def drum_stl(n):
    """N rectangles between consecutive nodes on the circle, normals toward the axis."""
    tris = []
    for k in range(n):
        (x0, y0), (x1, y1) = corner(k, n), corner(k + 1, n)
        a, b, c, d = (x0, y0, ZLO), (x1, y1, ZLO), (x1, y1, ZHI), (x0, y0, ZHI)
        tris += [(a, c, b), (a, d, c)]
    return stl(tris)


def polygon_inp(n):
    """The same N-gon as a CYLINDER along z: travelling counter-clockwise, the normal
    (left of travel) points to the axis."""
    out = ["*SURFACE, TYPE=CYLINDER, NAME=polygon", "0, 0, 0, 1, 0, 0", "0, 0, 1",
           "START, %r, %r" % corner(0, n)]
    out += ["LINE, %r, %r" % corner(k, n) for k in range(1, n + 1)]
    return "\n".join(out) + "\n"


def deck(wall, tag):
    rr = RC - R
    th = math.radians(30.0)
    d = L.header((-0.06, 0.06, -0.06, 0.06, -0.03, 0.03), DT)
    d += L.sphere(1, (-rr * math.cos(th), rr * math.sin(th), 0.0), R, RHO)
    d += "fix grav all gravity 9.81 vector -1 0 0\n"
    d += wall + "\n"
    d += "fix integr all nve/sphere\n"
    d += L.dump_lines("d", 100, tag + ".dump")
    d += "run %d\n" % STEPS
    return d


def frames(s, tag, wall):
    s.run(tag, deck(wall, tag))
    return L.read_dump(s.path(tag + ".dump"))


def largest_distance(fa, fb):
    worst = 0.0
    for (_, a), (_, b) in zip(fa, fb):
        worst = max(worst, math.sqrt(sum((a[1][c] - b[1][c]) ** 2 for c in "xyz")))
    return worst


YOUNG, POISSON = (5.0e7, 2.0e8), (0.3, 0.25)  # liglib.header's materials
HALF = math.radians(0.5)  # each face of the V rises at half a degree from the fold


def v_stl(half_width=0.05):
    """Two rectangles meeting along the y axis, rising at HALF on each side, normals up."""
    h = half_width * math.tan(HALF)
    a, b = (-half_width, -half_width, h), (-half_width, half_width, h)
    c, d = (0.0, -half_width, 0.0), (0.0, half_width, 0.0)
    e, f = (half_width, -half_width, h), (half_width, half_width, h)
    return stl([(a, c, d), (a, d, b), (c, e, f), (c, f, d)])


def v_inp(half_width=0.05):
    """The same V as a CYLINDER along y: profile in (x, z), travelling +x, normal up."""
    h = half_width * math.tan(HALF)
    return ("*SURFACE, TYPE=CYLINDER, NAME=vee\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
            "START, %r, %r\nLINE, 0, 0\nLINE, %r, %r\n" % (-half_width, h, half_width, h))


def rest_on_fold(s, law="law hertz"):
    """The frictionless sphere at rest on the V's fold line, with law (the law's words
    of the fix line)."""
    mass = RHO * 4.0 / 3.0 * math.pi * R ** 3
    g = 9.81
    estar = 1.0 / sum((1 - nu * nu) / e for e, nu in zip(YOUNG, POISSON))
    d = (mass * g / math.cos(HALF) / (4.0 / 3.0 * estar * math.sqrt(R))) ** (2.0 / 3.0)
    z_rest = (R - d) / math.cos(HALF)
    limit = math.sqrt(2 * d / R)
    s.ck.check("the fold is met with overlap: the angle is below sqrt(2 d / R)",
               2 * HALF < limit, "%.3g rad against %.3g" % (2 * HALF, limit))
    s.write("vee.stl", v_stl())
    s.write("vee.inp", v_inp())
    for tag, surf in (("fold_mesh", "inline mesh vee.stl"), ("fold_profile", "vee.inp")):
        deck = L.header((-0.06, 0.06, -0.06, 0.06, -0.01, 0.05), DT, e=0.3, mu=0.0)
        deck += L.sphere(1, (0.0, 0.0, z_rest + 0.0005), R, RHO)
        deck += "fix grav all gravity %r vector 0 0 -1\n" % g
        deck += "fix w all wall/rigid surface %s %s type 2\n" % (surf, law)
        deck += "fix integr all nve/sphere\n"
        deck += ("variable fz equal f_w[3]\nvariable nc equal f_w[7]\n"
                 "variable x equal x[1]\nvariable z equal z[1]\nrun 40000\n"
                 'print "REST ${fz} ${nc} ${x} ${z}"\n')
        rc, out = s.run(tag, deck, expect_ok=False)
        rest = [l.split()[1:] for l in out.splitlines() if l.startswith("REST ")]
        if not s.ck.check(tag + ": the run ends", rc == 0 and rest, "exit %s" % rc):
            continue
        fz, nc, x, z = (float(v) for v in rest[-1])
        s.ck.check(tag + ": two touching contacts on the fold line",
                   nc == 2.0 and abs(x) < 1e-9, "%g contacts, x = %.3g" % (nc, x))
        s.ck.check(tag + ": the wall carries m g to 1e-6",
                   abs(abs(fz) - mass * g) <= 1e-6 * mass * g,
                   "%.10g vs %.10g" % (abs(fz), mass * g))
        s.ck.check(tag + ": at rest at the closed-form height of shares 1/2, to 1e-6",
                   abs(z - z_rest) <= 1e-6 * z_rest, "%.10g vs %.10g" % (z, z_rest))


def body(s):
    rest_on_fold(s)
    s.write("drum.inp", L.drum(RC, ZLO, ZHI))
    exact = frames(s, "analytic", "fix w all wall/rigid surface drum.inp law hertz type 2")
    s.ck.check("the sphere rolled: it crossed the bottom of the drum",
               min(a[1]["y"] for _, a in exact) < 0.0 < max(a[1]["y"] for _, a in exact))
    errors = {}
    for n in (90, 360, 720):
        s.write("drum%d.stl" % n, drum_stl(n))
        s.write("polygon%d.inp" % n, polygon_inp(n))
        fm = frames(s, "mesh%d" % n,
                    "fix w all wall/rigid surface inline mesh drum%d.stl law hertz type 2" % n)
        errors[n] = largest_distance(fm, exact)
        if n == 90:
            continue
        fp = frames(s, "polygon%d" % n,
                    "fix w all wall/rigid surface polygon%d.inp law hertz type 2" % n)
        worst = L.compare_frames(fm, fp, SCALES)
        if not s.ck.check("N = %d: same frames" % n, worst is not None,
                          "%d vs %d frames" % (len(fm), len(fp))):
            continue
        fld, (d, step, i) = max(worst.items(), key=lambda kv: kv[1][0])
        s.ck.check("N = %d: the mesh drum is the polygon CYLINDER to %g" % (n, TOL),
                   d <= TOL, "worst %s rel %.3g at step %d" % (fld, d, step))
    s.ck.check("the error against the analytic drum falls with N",
               errors[90] > errors[360] > errors[720],
               "N = 90, 360, 720: %.3g, %.3g, %.3g m" % (errors[90], errors[360], errors[720]))
    s.ck.check("N = 720 is within a tenth of N = 90's error",
               errors[720] < 0.1 * errors[90],
               "%.3g against %.3g m" % (errors[720], errors[90]))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
