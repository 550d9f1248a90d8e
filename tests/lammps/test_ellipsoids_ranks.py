#!/usr/bin/python3
"""fix wall/rigid in LAMMPS on ellipsoids: 2 ranks give the run of 1 rank bit for bit, and
a restart continues the uninterrupted run.

The deck: a V-shaped trough (a CYLINDER profile of two LINEs falling 10 mm over 60 mm to a
sharp valley along y at x = 0), gravity -z, law hooke with friction and tangential
history (kn = kt = 1e4, mu 0.3, no damping, see below), starting with one history slot a
particle (`contacts 1`). 12 ellipsoids of three shapes (atom_style ellipsoid, fix
nve/asphere), tilted each its own way, are dropped across the valley moving along x at
0.3 m/s and spinning; those lying across the valley touch both faces, two contacts each,
so every rank grows its slots. The ellipsoids do not touch each other (pair_style none):
each one's path depends on itself and the wall only, so floating point gives the same
bits however the box is split, and the ranks' split at x = 0, the valley, makes them
migrate with their history (LAMMPS's exchange, whose size the fix sets as the slots grow)
and a rank meet a shape first after the start.
- 1 rank against 2 ranks: every dumped value (positions, velocities, angular momenta,
  forces, torques, quaternions) of every ellipsoid at every 500 steps, bit for bit; the
  wall's force (a sum over the ranks, in another order) to 1e-12 relative.
- restart: 3000 steps on 1 rank and write_restart; read_restart on 2 ranks and 3000 steps
  more: every value to 1e-12 relative of the uninterrupted run (the setup of the restarted
  run computes the forces of step 3000 again from the history as it was written, without
  advancing it; a sliding contact's force limited by friction is rebuilt from the limited
  history and rounds differently; the law has no damping, whose force LAMMPS's setup would
  take at the full step's velocity instead of the half step's).
"""
import math

import lmplib as M

DT, STEPS, EVERY = 1.0e-5, 6000, 500
SHAPES = ((0.003, 0.004, 0.008), (0.002, 0.005, 0.006), (0.004, 0.004, 0.007))
TROUGH = ("*SURFACE, TYPE=CYLINDER, NAME=trough\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
          "START, -0.06, 0.01\nLINE, 0, 0\nLINE, 0.06, 0.01\n")
WALL = ("fix w all wall/rigid surface trough.inp law hooke props 1e4 1e4 0 0 0.3 contacts 1 "
        "peratom yes")
BOX = (-0.06, 0.06, -0.06, 0.06, -0.01, 0.06)


def atoms():
    d = ""
    for k in range(12):
        half = SHAPES[k % 3]
        x = (-0.004 if k % 2 else 0.004) + 0.0005 * k
        vx = 0.3 if k % 2 else -0.3
        axis = (math.cos(0.7 * k), math.sin(0.7 * k), 0.3)
        d += M.ellipsoid(k + 1, (x, -0.0275 + 0.005 * k, max(half) + 0.003), half, 2500.0, axis,
                         20.0 + 50.0 * k % 90 if k % 4 else 90.0, (vx, 0.0, -0.1),
                         (1e-7 * k, -2e-7, 3e-7))
    return d


def fixes(tag, every):
    d = "fix grav all gravity 9.81 vector 0 0 -1\n" + WALL + "\n"
    d += "fix integr all nve/asphere\n"
    d += "variable fz equal f_w[3]\nvariable fx equal f_w[1]\nvariable nc equal f_w[7]\n"
    d += M.dump_lines("d", every, tag + ".dump", M.ECOLS + " f_w[1]")
    d += "variable touch atom f_w[1]>0\ncompute nt all reduce sum v_touch\n"
    d += "variable nt equal c_nt\n"
    d += 'fix pr all print 10 "${fx} ${fz} ${nc} ${nt}" screen no file %s.tot\n' % tag
    return d


def head():
    return M.ellipsoid_header(BOX, DT, pre="processors * 1 1\n")


def body(s):
    s.write("trough.inp", TROUGH)
    full = head() + atoms() + fixes("full", EVERY) + "run %d\n" % STEPS
    first = head() + atoms() + fixes("first", EVERY) + \
        "run %d\nwrite_restart half.restart\n" % (STEPS // 2)
    second = ("read_restart half.restart\nneighbor 0.002 bin\nneigh_modify delay 0\n"
              "compute quat all property/atom quatw quati quatj quatk\n" +
              fixes("second", EVERY) + "run %d\n" % (STEPS // 2))

    f1, f2 = M.run_ranks_restart(s, full, first, second)
    s.ck.check("all 12 ellipsoids kept", all(len(f) == 12 for _, f in f1 + f2))
    crossings = M.x_crossings(f1)
    s.ck.check("ellipsoids migrated between the ranks (crossed x = 0)", crossings >= 5,
               "%d crossings between dumps" % crossings)
    t1, t2 = M.read_table(s.path("np1.tot")), M.read_table(s.path("np2.tot"))
    two = max(r[2] - r[3] for r in t1)
    s.ck.check("ellipsoids lie across the valley: more contacts than ellipsoids touching",
               two >= 2, "up to %d more contacts than ellipsoids touching (at most %d touch)"
               % (two, max(r[3] for r in t1)))
    diff = M.exact_frames(f1, f2)
    s.ck.check("2 ranks = 1 rank, every dumped value bit for bit", diff is None,
               "first difference: %s" % (diff,))
    M.check_ranks_sums(s, t1, t2, ((0, "Fx"), (1, "Fz")))

    M.check_restart(s, f1, M.read_dump(s.path("second.dump")), STEPS // 2)


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
