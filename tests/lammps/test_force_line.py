#!/usr/bin/python3
"""law lammps on the wall's line path against the staged calls: the same numbers, bit for
bit.

On a REVOLUTION of one LINE (a cylinder's mantle, r = 50 mm about z) the wall takes runs
of spheres that each hold their one contact without the block call, and hands each
contact to LAMMPS's model itself (rs_law.force_one, src/wall/wall_force_line.c); `fused
no` sends every contact through the block call. 300 spheres of two radii (1.5 and 2 mm)
tumble in the mantle turning at 3 rad/s, gravity -y, for 4000 steps: contacts begin, last
and end, spheres fly and land. Each model of law lammps runs both ways, with the per-atom
output of the fix (peratom yes, its 6 columns dumped): hertz/history with damping and
friction (3 history values and the effective radius), the same with `reff exact`,
hooke/history, and granular hertz/material with rolling sds and twisting marshall (the
longest history), and granular jkr (a model that acts across a gap, within its pull-off
distance). Positions, velocities, spins, forces, torques and the fix's per-atom columns
agree bit for bit at every dumped step.
"""
import math
import random

import lmplib as M

R1, R2, RHO, DT, STEPS, N = 0.0015, 0.002, 2500.0, 2.0e-6, 4000, 300
RD = 0.05
MODELS = {
    "hertz": "hertz/history 2e8 NULL 5e8 NULL 0.5 1",
    "hertz_exact": "reff exact hertz/history 2e8 NULL 5e8 NULL 0.5 1",
    "hooke": "hooke/history 2e4 NULL 2e4 NULL 0.4 1",
    "granular": "granular hertz/material 1e8 0.3 0.3 tangential mindlin NULL 1.0 0.4 "
                "rolling sds 1e3 50 0.1 twisting marshall",
    "jkr": "granular jkr 1e7 0.1 0.3 50 tangential mindlin_rescale NULL 1.0 0.5 "
           "damping viscoelastic",
}
COLS = M.COLS + " f_w[1] f_w[2] f_w[3] f_w[4] f_w[5] f_w[6]"


def deck(tag, model, fused):
    d = M.header((-0.055, 0.055, -0.055, 0.055, -0.015, 0.015), DT)
    rng = random.Random(11)
    for k in range(N):
        rad = R1 if k % 2 else R2
        # some touching the mantle, the others up to 0.2 mm off it, falling onto it
        r = RD - rad - rng.uniform(-2e-7, 2e-4)
        phi = -0.5 * math.pi + rng.uniform(-1.2, 1.2)
        p = (r * math.cos(phi), r * math.sin(phi), rng.uniform(-0.012, 0.012))
        v = (rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.02), rng.uniform(-0.02, 0.02))
        d += M.sphere(k + 1, p, rad, RHO, v, (0, 0, rng.uniform(-20, 20)), 1 + k % 2)
    d += "fix grav all gravity 9.81 vector 0 -1 0\n"
    d += ("fix w all wall/rigid surface mantle.inp law lammps %s "
          "rotate origin 0 0 0 axis 0 0 1 omega 3 peratom yes%s\n"
          % (model, "" if fused else " fused no"))
    d += "fix integr all nve/sphere\n"
    d += M.dump_lines("d", 200, tag + ".dump", cols=COLS)
    d += "run %d\n" % STEPS
    return d


def body(s):
    s.write("mantle.inp", M.L.drum(RD, -1.0, 1.0, name="mantle"))
    for name, model in MODELS.items():
        frames = {}
        for fused in (True, False):
            tag = "%s_%s" % (name, "line" if fused else "staged")
            s.run(tag, deck(tag, model, fused))
            frames[fused] = M.read_dump(s.path(tag + ".dump"))
        diff = M.exact_frames(frames[True], frames[False])
        touching = sum(1 for _, atoms in frames[True] for a in atoms.values()
                       if a["f_w[1]"] > 0.0)
        s.ck.check("%s: the line path and fused no bit for bit (%d spheres, %d frames, %d "
                   "sphere-frames touching)" % (name, N, len(frames[True]), touching),
                   diff is None and touching > 0, "first difference: %s" % (diff,))


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
