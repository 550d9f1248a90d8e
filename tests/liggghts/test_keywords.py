#!/usr/bin/python3
"""Keywords of fix wall/rigid whose effect no other test pins, each against a closed form.

- area A / area projected: a sphere held at overlap h on a plane with law
  linear_softening (stress = k h): the wall's force is -A k h n, A = the constant or pi R^2.
- curvature yes: a sphere held at overlap d inside a drum of radius Rc with law hertz
  (no velocity, so no damping): |F| = 4/3 Y* sqrt(reff d) d with reff = R (curvature no)
  or reff = 1/sqrt((1/R + k1)(1/R + k2)), k1 = 0 along the generator, k2 = -1/Rc (hoop,
  concave).
- tracking D: a sphere hovering at gap g is a tracked contact (per-atom rdisp1 = -g) when
  g <= D, and no contact (0) when g > D. Without the keyword the thickness is the law's
  reach: 0 for hertz and linear_softening, the neighbor skin for bonded_interface.
- vtk FILE N with move linear V: the surface written at step s lies at z = V s dt.
- peratom yes|no: with yes the per-atom array holds the contact's rdisp1 (= h, the
  overlap) and stress1 (hertz: 4/3 Y* sqrt(R h) h, unit area); without it (the default)
  LIGGGHTS refuses a dump that reads the array, and the wall's force is the same, bit for
  bit; a value other than yes or no is an error naming the keyword.
Spheres have no integrator, so positions are exact.
"""
import math
import os
import re

import liglib as L

R, RHO, DT = 0.001, 2500.0, 1.0e-5
YP, YW, NUP, NUW = 5.0e7, 2.0e8, 0.3, 0.25     # liglib.header's particle / wall materials
BOX = (-0.06, 0.06, -0.06, 0.06, -0.06, 0.06)


def print_fix(var_expr, fname):
    return ("variable fv equal %s\n"
            'fix pr all print 1 "${fv}" file %s screen no\n' % (var_expr, fname))


def area_case(s, tag, area, k, h):
    d = L.header(BOX, DT) + L.sphere(1, (0.0, 0.0, R - h), R, RHO)
    d += "fix w all wall/rigid surface plane.inp law linear_softening props %r area %s type 2\n" % (k, area)
    d += print_fix("f_w[3]", tag + ".txt") + "run 2\n"
    s.run(tag, d)
    return L.read_table(s.path(tag + ".txt"))[-1][0]


def peratom_case(s, tag, peratom, h):
    """A sphere pressed into the plane by h with hertz, held there 2 steps: the wall's
    force f_w[3] and, with peratom yes, the dump of rdisp1 and stress1."""
    d = L.header(BOX, DT) + L.sphere(1, (0.0, 0.0, R - h), R, RHO)
    d += "fix w all wall/rigid surface plane.inp law hertz type 2%s\n" % peratom
    d += print_fix("f_w[3]", tag + ".txt")
    if "yes" in peratom:
        d += L.dump_lines("d", 1, tag + ".dump", "id f_w[1] f_w[4]")
    return d + "run 2\n"


def drum_case(s, tag, curvature, rc, delta):
    d = L.header(BOX, DT) + L.sphere(1, (rc - R + delta, 0.0, 0.0), R, RHO)
    d += "fix w all wall/rigid surface drum.inp law hertz type 2 curvature %s\n" % curvature
    d += print_fix("f_w[1]", tag + ".txt") + "run 2\n"
    s.run(tag, d)
    return L.read_table(s.path(tag + ".txt"))[-1][0]


def tracking_case(s, tag, tracking, gap, law="hertz type 2"):
    d = L.header(BOX, DT) + L.sphere(1, (0.0, 0.0, R + gap), R, RHO)
    d += "fix w all wall/rigid surface plane.inp law %s%s peratom yes\n" % (
        law, "" if tracking is None else " tracking %r" % tracking)
    d += L.dump_lines("d", 1, tag + ".dump", "id f_w[1]") + "run 2\n"
    s.run(tag, d)
    return L.read_dump(s.path(tag + ".dump"))[-1][1][1]["f_w[1]"]


def body(s):
    ck = s.ck
    s.write("plane.inp", L.plane_z(0.0, 1.0))
    k, h = 3.0e6, 2.0e-5
    for area, a_val in (("2.5", 2.5), ("projected", math.pi * R * R), ("node", 1.0)):
        fz = area_case(s, "area_" + area, area, k, h)
        expect = -a_val * k * h
        ck.check("area %s: wall force -A k h" % area, L.rel_diff(fz, expect, 0) <= 1e-12,
                 "%.17g vs %.17g" % (fz, expect))

    rc, delta = 0.05, 2.0e-5
    s.write("drum.inp", L.drum(rc, -0.05, 0.05))
    ystar = 1.0 / ((1 - NUP ** 2) / YP + (1 - NUW ** 2) / YW)
    for curv, reff in (("no", R), ("yes", 1.0 / math.sqrt((1.0 / R) * (1.0 / R - 1.0 / rc)))):
        fx = drum_case(s, "curv_" + curv, curv, rc, delta)
        expect = 4.0 / 3.0 * ystar * math.sqrt(reff * delta) * delta  # the wall is pushed +x
        ck.check("curvature %s: |F| = 4/3 Y* sqrt(reff d) d, reff = %.6g" % (curv, reff),
                 L.rel_diff(fx, expect, 0) <= 1e-12, "%.17g vs %.17g" % (fx, expect))

    gap = 2.0e-4
    for tr, expect in ((3.0e-4, -gap), (1.0e-4, 0.0)):
        r1 = tracking_case(s, "tracking_%g" % tr, tr, gap)
        ck.check("tracking %g, gap %g: per-atom rdisp1 = %g" % (tr, gap, expect),
                 abs(r1 - expect) <= 1e-15, "%.17g" % r1)
    # default tracking: the law's reach. hertz and linear_softening act on touching
    # contacts only (reach 0: no contact at a gap); bonded_interface acts across a gap
    # and keeps the neighbor skin (2 mm, liglib.header): a tracked contact at rdisp1 = -g.
    bonded = "bonded_interface props 1e-4 1e7 0.3 1e9 0 1e-3 10 type 2"
    for law, expect in (("hertz type 2", 0.0), ("linear_softening props 1e6 type 2", 0.0),
                        (bonded, -gap)):
        r1 = tracking_case(s, "tracking_default_" + law.split()[0], None, gap, law)
        ck.check("default tracking, law %s, gap %g: per-atom rdisp1 = %g"
                 % (law.split()[0], gap, expect), abs(r1 - expect) <= 1e-15, "%.17g" % r1)

    h = 1.0e-5
    ystar = 1.0 / ((1 - NUP ** 2) / YP + (1 - NUW ** 2) / YW)
    s.run("peratom_yes", peratom_case(s, "peratom_yes", " peratom yes", h))
    s.run("peratom_no", peratom_case(s, "peratom_no", "", h))
    fy = L.read_table(s.path("peratom_yes.txt"))[-1][0]
    fn = L.read_table(s.path("peratom_no.txt"))[-1][0]
    ck.check("peratom: the wall's force is the same with and without it", fy == fn,
             "%.17g vs %.17g" % (fy, fn))
    row = L.read_dump(s.path("peratom_yes.dump"))[-1][1][1]
    s1 = 4.0 / 3.0 * ystar * math.sqrt(R * h) * h
    ck.check("peratom yes: rdisp1 = h and stress1 = 4/3 Y* sqrt(R h) h",
             L.rel_diff(row["f_w[1]"], h, 0) <= 1e-9 and
             L.rel_diff(row["f_w[4]"], s1, 0) <= 1e-9,
             "rdisp1 %.17g, stress1 %.17g vs %.17g" % (row["f_w[1]"], row["f_w[4]"], s1))
    d = peratom_case(s, "peratom_dump", "", h).replace("run 2\n", "")
    d += L.dump_lines("d", 1, "peratom_dump.dump", "id f_w[1]") + "run 2\n"
    rc_, out = s.run("peratom_dump", d, expect_ok=False)
    err = L.error_lines(out)
    ck.check("peratom no: LIGGGHTS refuses a dump of the per-atom array",
             rc_ != 0 and any("per-atom" in l for l in err), repr(err[-1:]))
    rc_, out = s.run("peratom_bad", peratom_case(s, "peratom_bad", " peratom maybe", h),
                     expect_ok=False)
    err = L.error_lines(out)
    ck.check("peratom maybe: an error naming the keyword and its values",
             rc_ != 0 and any("'peratom' expects 'yes' or 'no', got 'maybe'" in l
                              for l in err), repr(err[-1:]))

    v, nsteps, every = 0.1, 20, 10
    d = L.header(BOX, DT) + L.sphere(1, (0.0, 0.0, 0.02), R, RHO)
    d += ("fix w all wall/rigid surface plane.inp law hertz type 2 move linear 0 0 %r "
          "vtk wall_*.vtk %d\nrun %d\n" % (v, every, nsteps))
    s.run("vtk", d)
    for step in range(0, nsteps + 1, every):
        path = s.path("wall_%d.vtk" % step)
        if not ck.check("vtk: wall_%d.vtk written" % step, os.path.isfile(path)):
            continue
        text = open(path).read()
        m = re.search(r"POINTS (\d+) \w+\n", text)
        npts = int(m.group(1)) if m else 0
        vals = text[m.end():].split()[:3 * npts] if m else []
        zs = [float(z) for z in vals[2::3]]
        z_expect = v * step * DT
        ck.check("vtk: step %d, all %d points at z = V t = %g" % (step, npts, z_expect),
                 npts > 0 and all(abs(z - z_expect) <= 1e-15 for z in zs),
                 "z in [%g, %g]" % (min(zs), max(zs)) if zs else "no points")


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
