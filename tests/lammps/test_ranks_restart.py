#!/usr/bin/python3
"""fix wall/rigid in LAMMPS: 2 ranks give the run of 1 rank bit for bit, and a restart
continues the uninterrupted run.

The deck: a drum (REVOLUTION about z, mantle and two end caps meeting at sharp corners)
turning at 20 rad/s, gravity -y, law lammps granular (hertz/material, mindlin, rolling
sds, twisting marshall: 7 history values per contact; no damping, see below), starting
with one history slot per sphere (`contacts 1`). 368 spheres in four rings touch the mantle, moving round the hoop at
0.8 m/s while the mantle moves at 1 m/s; the outer rings start touching a cap too, so
their spheres hold two contacts and every rank grows its slots. The spheres do not touch each
other (pair_style none): each sphere's path depends on itself and the wall only, so
floating point gives the same bits however the box is split, and the ranks' split at
x = 0 makes spheres migrate with their history (LAMMPS's exchange, whose size the fix
sets as the slots grow).
- 1 rank against 2 ranks: every dumped value (positions, velocities, spins, forces,
  torques) of every sphere at every 200 steps, bit for bit; the wall's force and moment
  (sums over the ranks, in another order) to 1e-12 relative; the drum's angle exactly.
- restart: 1000 steps on 1 rank and write_restart; read_restart on 2 ranks and 1000
  steps more: every value to 1e-12 relative of the uninterrupted run and the drum's angle
  exactly. The setup of the restarted run computes the forces of step 1000 again from the
  history as it was written, without advancing it, as LAMMPS's own walls do; where a
  contact slides, LAMMPS's models rebuild the force limited by friction from the limited
  history, which rounds differently from the force of the step that limited it (1e-15),
  so a restart is not bit for bit. The models have no damping: LAMMPS's setup after
  read_restart evaluates every velocity-dependent force with the step's velocity, where
  the step itself took the half step's, so a damped contact's force at the restart step
  differs at the size of its damping term, for stock's fix wall/gran/region as well
  (measured on this deck with tsuji damping: stock's small tangential forces change sign).
"""
import math

import lmplib as M

R, RHO, DT, RC, H, STEPS = 0.0015, 2500.0, 1.0e-5, 0.05, 0.015, 2000
LAW = ("law lammps granular hertz/material 1e7 0 0.3 tangential mindlin NULL 0 0.5 "
       "rolling sds 1e3 0 0.1 twisting marshall damping velocity")
WALL = ("fix w all wall/rigid surface drum.inp %s contacts 1 "
        "rotate origin 0 0 0 axis 0 0 1 omega 20" % LAW)
DRUM = ("*SURFACE, TYPE=REVOLUTION, NAME=drum\n0, 0, 0, 0, 0, 1\n"
        "START, 0, %r\nLINE, %r, %r\nLINE, %r, %r\nLINE, 0, %r\n" % (-H, RC, -H, RC, H, H))
OUT = "variable a equal f_w[18]\nvariable fx equal f_w[1]\nvariable fy equal f_w[2]\n" \
      "variable mz equal f_w[6]\nvariable nc equal f_w[7]\n"


def atoms():
    d = ""
    r0 = RC - R + 1e-6
    nring = int(2 * math.pi * r0 / (2.2 * R))
    k = 0
    for z in (-H + R - 1e-6, -0.005, 0.005, H - R + 1e-6):
        for j in range(nring):
            phi = 2 * math.pi * (j + 0.5 * (k % 2)) / nring + 0.01
            d += "create_atoms 1 single %r %r %r units box\n" % (
                r0 * math.cos(phi), r0 * math.sin(phi), z)
        k += 1
    d += "set group all diameter %r density %r\n" % (2 * R, RHO)
    d += "variable vx0 atom -0.8*y/sqrt(x*x+y*y)\nvariable vy0 atom 0.8*x/sqrt(x*x+y*y)\n"
    d += "velocity all set v_vx0 v_vy0 0 units box\n"
    return d


def fixes(tag, every):
    d = "fix grav all gravity 9.81 vector 0 -1 0\n" + WALL + "\n"
    d += "fix integr all nve/sphere\n" + OUT
    d += M.dump_lines("d", every, tag + ".dump")
    d += 'fix pr all print %d "${a} ${fx} ${fy} ${mz} ${nc}" screen no file %s.tot\n' % (
        every, tag)
    return d


def head():
    return M.header((-0.055, 0.055, -0.055, 0.055, -0.02, 0.02), DT,
                    pre="processors * 1 1\n")


def body(s):
    s.write("drum.inp", DRUM)
    full = head() + atoms() + fixes("full", 200) + "run %d\n" % STEPS
    first = head() + atoms() + fixes("first", 200) + "run %d\nwrite_restart half.restart\n" \
        % (STEPS // 2)
    second = ("read_restart half.restart\nneighbor 0.002 bin\nneigh_modify delay 0\n"
              "comm_modify vel yes\n" + fixes("second", 200) + "run %d\n" % (STEPS // 2))

    f1, f2 = M.run_ranks_restart(s, full, first, second)
    n0 = len(f1[0][1])
    s.ck.check("the drum holds a few hundred spheres, all kept", 300 <= n0 <= 500
               and all(len(f) == n0 for _, f in f1 + f2), "%d" % n0)
    first_f, last_f = f1[0][1], f1[-1][1]
    crossed = sum(1 for i in first_f if first_f[i]["x"] * last_f[i]["x"] < 0)
    s.ck.check("spheres migrated between the ranks (crossed x = 0)", crossed >= 10,
               "%d crossed" % crossed)
    diff = M.exact_frames(f1, f2)
    s.ck.check("2 ranks = 1 rank, every dumped value bit for bit", diff is None,
               "first difference: %s" % (diff,))
    t1, t2 = M.read_table(s.path("np1.tot")), M.read_table(s.path("np2.tot"))
    s.ck.check("at the start the corner rings touch mantle and cap: two contacts a sphere",
               t1[0][4] == n0 + n0 // 2 and t2[0][4] == t1[0][4], "%d contacts" % t1[0][4])
    s.ck.check("the drum's angle, 2 ranks = 1 rank", [r[0] for r in t1] == [r[0] for r in t2]
               and abs(t1[-1][0] - 20 * STEPS * DT) < 1e-12, "%.17g" % t1[-1][0])
    M.check_ranks_sums(s, t1, t2, ((1, "Fx"), (2, "Fy"), (3, "Mz")))

    fr = M.read_dump(s.path("second.dump"))
    cont = [(st, f) for st, f in f1 if st >= STEPS // 2]
    worst = M.L.compare_frames(cont, fr, M.scales(R))
    if s.ck.check("the restarted run's frames line up with the uninterrupted run's",
                  worst is not None, "%d vs %d" % (len(cont), len(fr))):
        fld, (d, step, i) = max(worst.items(), key=lambda kv: kv[1][0])
        s.ck.check("restart (1 rank, then 2 ranks) = the uninterrupted run to 1e-12",
                   d <= 1e-12, "worst %s rel %.3g at step %d atom %d" % (fld, d, step, i))
    tr = M.read_table(s.path("second.tot"))
    s.ck.check("the drum's angle carries over the restart", tr[-1][0] == t1[-1][0],
               "%.17g vs %.17g" % (tr[-1][0], t1[-1][0]))


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
