#!/usr/bin/python3
"""A rotating drum on 2 MPI ranks gives the run of 1 rank.

What is deterministic: the spheres do not touch each other (neigh_modify exclude type
1 1), so each sphere's path depends on itself and the wall only, and floating point
gives the same bits however the box is split. Only the wall totals are sums over
ranks, whose order differs. So:
- per-sphere positions and velocities agree to 1e-12 (scaled by R and 1 m/s),
- the atom count is the same and nothing is lost,
- the total wall force and the energy totals ALLSE, ALLFD, ALLVD agree to 1e-6 relative
  (floor: 1e-3 of the quantity's largest value in the run, since a net force near zero
  is a sum of large terms of both signs).
The drum (REVOLUTION about z, periodic in z) turns at 20 rad/s with gravity -y; the
ranks split at x = 0. The spheres start on a ring touching the mantle (3.3 um gap),
nine layers deep in z, moving round the hoop at 0.8 m/s while the mantle moves at
1 m/s: friction speeds them up (ALLFD), the centrifugal load (~13 g) keeps them on the
mantle all round, so every sphere is in contact every step, and those near x = 0
migrate between the ranks with their contact history. 2000 steps.
"""
import math

import liglib as L

R, RHO, DT, RC, STEPS = 0.0015, 2500.0, 1.0e-5, 0.05, 2000
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
WALL = "fix w all wall/rigid surface drum.inp law hertz type 2 rotate origin 0 0 0 axis 0 0 1 omega 20"
# global output: 1-3 force on the wall, 7 active contacts, 8 ALLSE, 9 ALLFD, 11 ALLVD
TOTALS = {"Fx": 1, "Fy": 2, "Fz": 3, "contacts": 7, "ALLSE": 8, "ALLFD": 9, "ALLVD": 11}


def deck(tag, wall):
    d = L.header((-0.055, 0.055, -0.055, 0.055, -0.015, 0.015), DT, boundary="f f p",
                 pre="processors * 1 1\n")
    d += "neigh_modify exclude type 1 1\n"
    # One create_atoms per sphere so that atom ids do not depend on the decomposition.
    r0 = RC - R - 3.3e-6
    nring = int(2 * math.pi * r0 / (2.2 * R))
    for k in range(9):
        for j in range(nring):
            phi = 2 * math.pi * (j + 0.5 * (k % 2)) / nring + 0.01
            d += "create_atoms 1 single %r %r %r units box\n" % (
                r0 * math.cos(phi), r0 * math.sin(phi), -0.015 + (k + 0.5) * 0.030 / 9)
    d += "set group all diameter %r density %r\n" % (2 * R, RHO)
    # 0.8 m/s round the hoop, counter-clockwise like the drum
    d += "variable vx0 atom -0.8*y/sqrt(x*x+y*y)\n"
    d += "variable vy0 atom 0.8*x/sqrt(x*x+y*y)\n"
    d += "velocity all set v_vx0 v_vy0 0 units box\n"
    d += "fix grav all gravity 9.81 vector 0 -1 0\n"
    d += wall + "\n"
    d += "fix integr all nve/sphere\n"
    d += "variable n equal count(all)\n"
    cols = ["${n}"]
    for k, i in TOTALS.items():
        d += "variable t%s equal f_w[%d]\n" % (k, i)
        cols.append("${t%s}" % k)
    d += 'fix pr all print 100 "%s" screen no file %s.tot\n' % (" ".join(cols), tag)
    d += L.dump_lines("d", STEPS, tag + ".dump")
    d += "run %d\n" % STEPS
    return d


def body(s):
    s.write("drum.inp", L.drum(RC, -1.0, 1.0))
    s.run("np1", deck("np1", WALL))
    s.run("np2", deck("np2", WALL), np=2)
    f1, f2 = L.read_dump(s.path("np1.dump")), L.read_dump(s.path("np2.dump"))
    n0 = len(f1[0][1])
    s.ck.check("drum holds a few hundred spheres", 300 <= n0 <= 2000, "%d" % n0)
    s.ck.check("same spheres on 1 and 2 ranks at the end",
               set(f1[-1][1]) == set(f2[-1][1]) and len(f1[-1][1]) == n0,
               "%d vs %d of %d" % (len(f1[-1][1]), len(f2[-1][1]), n0))
    first, last = f1[0][1], f1[-1][1]
    crossed = sum(1 for i in first if i in last and first[i]["x"] * last[i]["x"] < 0)
    s.ck.check("spheres migrated between the ranks (crossed x = 0)", crossed >= 5,
               "%d crossed" % crossed)
    worst = L.compare_frames(f1, f2, SCALES)
    if s.ck.check("dumps line up", worst is not None):
        fld, (d, step, i) = max(worst.items(), key=lambda kv: kv[1][0])
        s.ck.check("per-sphere state, 2 ranks = 1 rank to 1e-12", d <= 1e-12,
                   "worst %s rel %.3g at step %d atom %d" % (fld, d, step, i))
    t1, t2 = L.read_table(s.path("np1.tot")), L.read_table(s.path("np2.tot"))
    if not s.ck.check("totals printed every 100 steps", len(t1) == len(t2) == STEPS // 100,
                      "%d and %d rows" % (len(t1), len(t2))):
        return
    s.ck.check("atom count per output step equal", all(a[0] == b[0] == n0 for a, b in zip(t1, t2)))
    s.ck.check("at the end every sphere touches the wall; friction and damping dissipated",
               t1[-1][1 + list(TOTALS).index("contacts")] == n0
               and t1[-1][1 + list(TOTALS).index("ALLFD")] > 0
               and t1[-1][1 + list(TOTALS).index("ALLVD")] > 0)
    for j, k in enumerate(TOTALS):
        col = 1 + j
        floor = 1e-3 * max(abs(r[col]) for r in t1 + t2)
        d = max(L.rel_diff(a[col], b[col], floor) for a, b in zip(t1, t2))
        s.ck.check("total %s, 2 ranks = 1 rank to 1e-6" % k, d <= 1e-6, "worst rel %.3g" % d)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
