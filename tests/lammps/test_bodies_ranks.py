#!/usr/bin/python3
"""fix wall/rigid in LAMMPS on rounded polyhedra (atom_style body rounded/polyhedron): 2
ranks give the run of 1 rank bit for bit, and a restart continues the uninterrupted run.

The deck: a V-shaped trough (a CYLINDER profile of two LINEs falling 10 mm over 60 mm to a
sharp valley along y at x = 0), gravity -z, law hooke with friction and tangential history
(kn = kt = 1e4, mu 0.3, no damping), starting with one history slot a particle
(`contacts 1`). 10 rounded polyhedra of three shapes (cubes, flat boxes, hexagonal
prisms; fix nve/body), tilted each its own way, are dropped across the valley moving along
x at 0.3 m/s and spinning; a body landing on an edge or a face holds two to four contacts,
and across the valley more, so every rank grows its slots. The bodies do not touch each
other (pair_style none): each one's path depends on itself
and the wall only, so floating point gives the same bits however the box is split, and the
ranks' split at x = 0, the valley, makes them migrate with their history (LAMMPS's
exchange, whose size the fix sets as the slots grow), and a rank may meet a shape first after
the start.
- 1 rank against 2 ranks: every dumped value (positions, velocities, angular momenta,
  forces, torques, quaternions) of every body at every 500 steps, bit for bit.
- restart: 3000 steps on 1 rank and write_restart; read_restart on 2 ranks and 3000 steps
  more: every value to 1e-12 of its column's largest in the uninterrupted run (the
  restarted run's setup computes the forces of step 3000 again from the history as it was
  written, without advancing it; a sliding contact's force limited by friction is rebuilt
  from the limited history and rounds differently).
"""
import math

import lmplib as M

DT, STEPS, EVERY = 1.0e-5, 6000, 500
TROUGH = ("*SURFACE, TYPE=CYLINDER, NAME=trough\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
          "START, -0.06, 0.01\nLINE, 0, 0\nLINE, 0.06, 0.01\n")
WALL = ("fix w all wall/rigid surface trough.inp law hooke props 1e4 1e4 0 0 0.3 contacts 1 "
        "peratom yes")
BOX = (-0.06, 0.06, -0.06, 0.06, -0.01, 0.06)
MASS = 0.005


def inertia(diag, axis, angle):
    """The world-frame tensor (ixx iyy izz ixy ixz iyz) of principal moments diag about the
    body axes turned by angle degrees about axis."""
    if diag[0] == diag[1] == diag[2]:
        # isotropic: the same tensor in every frame (LAMMPS's Jacobi on this tensor turned
        # and rounded, off-diagonals of 1e-23, returns axes that are not orthogonal, and
        # the body's stored vertices collapse towards a plane)
        return (diag[0], diag[1], diag[2], 0.0, 0.0, 0.0)
    cols = [M.rotate(e, axis, angle) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    t = [[sum(diag[k] * cols[k][i] * cols[k][j] for k in range(3)) for j in range(3)]
         for i in range(3)]
    return (t[0][0], t[1][1], t[2][2], t[0][1], t[0][2], t[1][2])


def shape(k):
    if k % 3 == 0:
        h = 0.004
        V, E, F = M.box_body((h, h, h))
        diag = (2 * MASS * h * h / 3,) * 3
    elif k % 3 == 1:
        h = (0.005, 0.004, 0.002)
        V, E, F = M.box_body(h)
        diag = (MASS / 3 * (h[1] ** 2 + h[2] ** 2), MASS / 3 * (h[0] ** 2 + h[2] ** 2),
                MASS / 3 * (h[0] ** 2 + h[1] ** 2))
    else:
        rc, hl = 0.004, 0.003
        V, E, F = M.prism_body(6, rc, hl)  # axis along y
        ia = MASS * rc * rc * 5 / 12  # a regular hexagon's polar moment
        it = ia / 2 + MASS * hl * hl / 3
        diag = (it, ia, it)
    return V, E, F, diag


def bodies():
    out = []
    for k in range(10):
        V, E, F, diag = shape(k)
        axis = (math.cos(0.7 * k), math.sin(0.7 * k), 0.3)
        angle = 20.0 + 50.0 * k % 90 if k % 4 else 90.0
        x = (-0.004 if k % 2 else 0.004) + 0.0005 * k
        out.append({"V": [M.rotate(p, axis, angle) for p in V], "E": E, "F": F,
                    "r": 0.0005 + 0.0002 * (k % 3), "m": MASS, "I": inertia(diag, axis, angle),
                    "x": (x, -0.05 + 0.011 * k, 0.012), "v": (0.3 if k % 2 else -0.3, 0, -0.1),
                    "L": (1e-9 * k, -2e-9, 3e-9)})
    return out


def fixes(tag):
    d = "fix grav all gravity 9.81 vector 0 0 -1\n" + WALL + "\nfix integr all nve/body\n"
    d += "variable nc equal f_w[7]\nvariable touch atom f_w[1]>0\n"
    d += "compute nt all reduce sum v_touch\nvariable nt equal c_nt\n"
    d += 'fix pr all print 10 "${nc} ${nt}" screen no file %s.tot\n' % tag
    d += M.dump_lines("d", EVERY, tag + ".dump", M.BCOLS)
    return d


def body(s):
    s.write("trough.inp", TROUGH)
    b = bodies()
    s.write("bodies.data", M.body_data(b, BOX))
    head = M.body_header("bodies.data", DT, M.body_nmax(b), pre="processors * 1 1\n",
                         pair=False)
    full = head + fixes("full") + "run %d\n" % STEPS
    first = head + fixes("first") + "run %d\nwrite_restart half.restart\n" % (STEPS // 2)
    second = ("read_restart half.restart\nneighbor 0.002 bin\nneigh_modify delay 0\n"
              "pair_style none\n"
              "comm_modify vel yes\n"
              "compute quat all property/atom quatw quati quatj quatk\n" +
              fixes("second") + "run %d\n" % (STEPS // 2))

    f1, f2 = M.run_ranks_restart(s, full, first, second)
    s.ck.check("all 10 bodies kept", all(len(f) == 10 for _, f in f1 + f2))
    crossings = M.x_crossings(f1)
    s.ck.check("bodies migrated between the ranks (crossed x = 0)", crossings >= 4,
               "%d crossings between dumps" % crossings)
    t1 = M.read_table(s.path("np1.tot"))
    most = max(r[0] - r[1] for r in t1)
    s.ck.check("bodies touch with several points: more contacts than bodies touching",
               most >= 2, "up to %d more contacts than bodies touching (at most %d touch)"
               % (most, max(r[1] for r in t1)))
    diff = M.exact_frames(f1, f2)
    s.ck.check("2 ranks = 1 rank, every dumped value bit for bit", diff is None,
               "first difference: %s" % (diff,))

    M.check_restart(s, f1, M.read_dump(s.path("second.dump")), STEPS // 2)


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
