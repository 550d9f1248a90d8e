#!/usr/bin/python3
"""A sphere in the apex of a 12-facet cone (an STL, normals inward) holds one contact
per facet, 12, more than the 4 history slots a fix starts with: the slots grow, the run
goes on, and the sphere comes to rest where Hertz's law puts it.

Pins: the run ends without error with 12 touching contacts (f_w[7]); the wall carries
the sphere's weight, m g, to 1e-6 relative, with lateral force below 1e-9 m g; and the
sphere, frictionless so that its rest is unique, rests on the axis at the closed-form
height. Each facet's plane lies at angle
a = atan(tan 30 deg cos 15 deg) to the axis, so a point on the axis at height z is
z sin(a) from it; the 12 equal Hertz forces F = 4/3 E* sqrt(R) d^1.5 (LIGGGHTS's wall:
E* of the particle and wall materials, radius R) carry m g through their vertical
parts F sin(a), so the centre rests at z = (R - d) / sin(a).
The same holds with 'contacts 1' (the slots grow from one).

Then the cone, placed with its apex at x = -0.01, moves (move linear 0.2 0 0) while
turning about its axis (5 rad/s), and drags the sphere with its 12 contacts
across the boundary between two ranks (processors 2 1 1): the atom arrives at a rank
whose fix still has 4 slots, which grows to take them. Its path with -np 2 equals the
-np 1 path to 1e-6.
"""
import math

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
YOUNG, POISSON = (5.0e7, 2.0e8), (0.3, 0.25)
HALF = math.radians(30.0)


def cone_stl(n=12, height=0.05):
    r = height * math.tan(HALF)
    ring = [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n), height)
            for k in range(n)]
    out = ["solid cone"]
    for k in range(n):
        for tri in (((0.0, 0.0, 0.0), ring[k], ring[(k + 1) % n]),):
            out.append(" facet normal 0 0 0\n  outer loop")
            out += ["   vertex %.17g %.17g %.17g" % p for p in tri]
            out.append("  endloop\n endfacet")
    out.append("endsolid cone")
    return "\n".join(out) + "\n"


def body(s):
    s.write("cone.stl", cone_stl())
    mass = RHO * 4.0 / 3.0 * math.pi * R ** 3
    g = 9.81
    a = math.atan(math.tan(HALF) * math.cos(math.pi / 12))
    estar = 1.0 / sum((1 - nu * nu) / e for e, nu in zip(YOUNG, POISSON))
    f = mass * g / (12 * math.sin(a))
    d = (f / (4.0 / 3.0 * estar * math.sqrt(R))) ** (2.0 / 3.0)
    z_rest = (R - d) / math.sin(a)
    for tag, extra in (("default", ""), ("from_one", " contacts 1")):
        deck = L.header((-0.04, 0.04, -0.04, 0.04, -0.01, 0.06), DT, e=0.3, mu=0.0)
        deck += L.sphere(1, (0.0, 0.0, z_rest + 0.002), R, RHO)
        deck += "fix grav all gravity %r vector 0 0 -1\n" % g
        deck += ("fix w all wall/rigid surface inline mesh cone.stl law hertz type 2%s\n"
                 % extra)
        deck += "fix integr all nve/sphere\n"
        deck += ("variable fx equal f_w[1]\nvariable fy equal f_w[2]\n"
                 "variable fz equal f_w[3]\nvariable nc equal f_w[7]\n"
                 "variable z equal z[1]\nvariable vz equal vz[1]\n")
        deck += "run 30000\n"
        deck += ('print "REST ${fx} ${fy} ${fz} ${nc} ${z} ${vz}"\n')
        rc, out = s.run(tag, deck, expect_ok=False)
        if not s.ck.check(tag + ": the run ends without error", rc == 0, "exit %s" % rc,
                          why="\n".join(out.splitlines()[-5:])):
            continue
        rest = [l.split()[1:] for l in out.splitlines() if l.startswith("REST ")]
        fx, fy, fz, nc, z, vz = (float(v) for v in rest[-1])
        s.ck.check(tag + ": 12 touching contacts", nc == 12.0, "%g" % nc)
        s.ck.check(tag + ": the wall carries m g to 1e-6", abs(-fz - mass * g) <= 1e-6 * mass * g
                   or abs(fz - mass * g) <= 1e-6 * mass * g, "%.10g vs %.10g" % (fz, mass * g))
        s.ck.check(tag + ": no lateral force (1e-9 m g)",
                   math.hypot(fx, fy) <= 1e-9 * mass * g, "%.3g" % math.hypot(fx, fy))
        s.ck.check(tag + ": at rest at the closed-form height to 1e-6",
                   abs(z - z_rest) <= 1e-6 * z_rest, "%.10g vs %.10g (vz %.2g)" % (z, z_rest, vz))

    # the moving pocket, one and two ranks
    ends = {}
    for np in (1, 2):
        deck = L.header((-0.04, 0.04, -0.04, 0.04, -0.01, 0.06), DT, mu=0.4,
                        pre="processors 2 1 1\n" if np == 2 else "")
        deck += L.sphere(1, (-0.01, 0.0, z_rest), R, RHO)
        deck += "fix grav all gravity %r vector 0 0 -1\n" % g
        deck += ("fix w all wall/rigid surface inline mesh cone.stl place -0.01 0 0 "
                 "0.99 0 0 -0.01 1 0 law hertz type 2 move linear 0.2 0 0 "
                 "rotate origin -0.01 0 0 axis 0 0 1 omega 5\n"
                 "fix integr all nve/sphere\n")
        deck += ("variable nc equal f_w[7]\nvariable x equal x[1]\nvariable y equal y[1]\n"
                 "variable z equal z[1]\nrun 10000\n"
                 'print "END ${nc} ${x} ${y} ${z}"\n')
        rc, out = s.run("moving_np%d" % np, deck, np=np, expect_ok=False)
        s.ck.check("moving np %d: the run ends without error" % np, rc == 0, "exit %s" % rc,
                   why="\n".join(out.splitlines()[-5:]))
        end = [l.split()[1:] for l in out.splitlines() if l.startswith("END ")]
        ends[np] = [float(v) for v in end[-1]] if end else None
    if ends[1] and ends[2]:
        s.ck.check("moving: the sphere crossed the rank boundary x = 0 in its pocket",
                   ends[1][1] > 0.005 and ends[1][0] >= 5, "nc %g, x %.4g" % tuple(ends[1][:2]))
        worst = max(abs(a - b) / max(abs(a), R) for a, b in zip(ends[1][1:], ends[2][1:]))
        s.ck.check("moving: -np 2 equals -np 1 to 1e-6", worst <= 1e-6, "%.3g" % worst)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
