#!/usr/bin/python3
"""A revolved LINE conserves energy and holds every sphere: elastic, frictionless spheres
bouncing inside a drum (the per-sphere path of a revolved LINE, the wall's line path, for every
held contact).

30 Hertz spheres (R = 2 mm) start at random points inside a drum of radius 50 mm about
z, periodic in z, with random velocities of 0.5 m/s in the drum's plane and along z; no
gravity, no sphere-sphere contacts (neigh_modify exclude), restitution 1 (no damping)
and friction 0, so the spheres' kinetic energy plus the elastic energy stored in their
wall contacts (ALLSE, the fix's output 8) is a constant of the motion, which velocity
Verlet keeps up to its error. 100000 steps. Checks, each against
the run's initial energy E0 (no contact at the start):
- no step's energy exceeds E0 by more than 1e-3 E0, and none falls below it by more;
- the energy over the last 2000 steps is E0 within 1e-4 E0 (no drift);
- every sphere stays inside the drum: every 2500 steps its overlap r + R - RC is at most
  Hertz's largest for a normal impact at 0.5 m/s, (15 m v^2 / (16 E* sqrt(R)))^(2/5);
- the spheres hit the wall (contacts seen in at least 50 output steps).
"""
import math
import random

import liglib as L

R, RHO, DT, RC, STEPS, N = 0.002, 2500.0, 1.0e-5, 0.05, 100000, 30
BOX = (-0.055, 0.055, -0.055, 0.055, -0.01, 0.01)


def deck():
    d = L.header(BOX, DT, e=1.0, mu=0.0, boundary="f f p")
    d += "neigh_modify exclude type 1 1\n"
    rng = random.Random(7)
    for k in range(N):
        r = (RC - R - 0.002) * math.sqrt(rng.random())
        phi, th = 2 * math.pi * rng.random(), 2 * math.pi * rng.random()
        z = BOX[4] + (BOX[5] - BOX[4]) * rng.random()
        c = rng.uniform(-1.0, 1.0)
        s = math.sqrt(1 - c * c)
        v = (0.5 * s * math.cos(th), 0.5 * s * math.sin(th), 0.5 * c)
        d += L.sphere(k + 1, (r * math.cos(phi), r * math.sin(phi), z), R, RHO, v=v)
    d += "fix w all wall/rigid surface drum.inp law hertz type 2\n"
    d += "fix integr all nve/sphere\n"
    d += "compute ke all ke\n"
    d += "variable ke equal c_ke\n"
    d += "variable se equal f_w[8]\n"
    d += "variable nc equal f_w[7]\n"
    d += 'fix pr all print 20 "${ke} ${se} ${nc}" screen no file energy.txt\n'
    d += L.dump_lines("d", 2500, "drum.dump")
    d += "run %d\n" % STEPS
    return d


def body(s):
    s.write("drum.inp", L.drum(RC, -1.0, 1.0))
    s.run("drum", deck())
    rows = []
    with open(s.path("energy.txt")) as f:
        for line in f:
            if line.startswith("#"):
                continue
            rows.append([float(w) for w in line.split()])
    e0 = rows[0][0] + rows[0][1]
    s.ck.check("no contact at the start", rows[0][2] == 0, "%g" % rows[0][2])
    worst = max(abs(ke + se - e0) for ke, se, _ in rows) / e0
    s.ck.check("energy within 1e-3 of E0 at every output step", worst <= 1e-3,
               "worst %.3g" % worst)
    tail = rows[-2000 // 20:]
    drift = abs(sum(ke + se for ke, se, _ in tail) / len(tail) - e0) / e0
    s.ck.check("energy over the last 2000 steps within 1e-4 of E0", drift <= 1e-4,
               "%.3g" % drift)
    hits = sum(1 for _, _, nc in rows if nc > 0)
    s.ck.check("the spheres hit the wall", hits >= 50, "%d output steps with contacts" % hits)
    fr = L.read_dump(s.path("drum.dump"))
    rmax = max(math.hypot(a["x"], a["y"]) for _, atoms in fr for a in atoms.values())
    # the materials of L.header: particle 5e7 Pa, 0.3; wall 2e8 Pa, 0.25
    estar = 1.0 / ((1 - 0.3 ** 2) / 5.0e7 + (1 - 0.25 ** 2) / 2.0e8)
    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    dmax = (15.0 * m * 0.5 ** 2 / (16.0 * estar * math.sqrt(R))) ** 0.4
    s.ck.check("every sphere inside the drum at every dump, overlap within Hertz's largest",
               all(len(atoms) == N for _, atoms in fr) and rmax + R - RC <= dmax,
               "%d dumps, largest overlap %.3g m, Hertz's %.3g m" % (len(fr), rmax + R - RC,
                                                                      dmax))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
