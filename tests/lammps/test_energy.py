#!/usr/bin/python3
"""Elastic frictionless spheres in a turning drum: the wall adds no energy and lets no
sphere through.

200 spheres (R = 1.5 mm) that touch only the wall fly about inside the drum of
examples/lammps_drum (a REVOLUTION about z: mantle, end caps and the 4 mm fillets between
them), which turns at 3 rad/s about its own axis, gravity -y; 50000 steps (0.1 s), each sphere
hitting the wall about 6 times. The contacts are elastic and frictionless, by LAMMPS's
own model (law lammps hertz/history with no damping and xmu = 0) and by rigidsurf's
(law hertz, restitution 1 and friction 0). A frictionless wall turning about its own axis
does no work, so each sphere keeps its own energy m v^2/2 + I w^2/2 + m g y: whenever it
touches nothing (the fix's per-atom overlap is 0), it equals its energy at the start to
1e-3 of m (g Rdrum + v0^2/2) (the time step's error over a collision of about 40 steps,
of either sign; measured up to 4.5e-4), and its mean change over all spheres and frames is
not a gain above 2e-5 (measured 1e-6); no sphere is ever outside the drum.

Each contact of law lammps keeps the effective radius where it began: a sphere sliding
from the mantle onto a fillet, whose curvature is 12 times the mantle's, would otherwise
leave with up to 7 % more energy than it came with (measured here when the radius
followed the contact point).
"""
import math
import random

import lmplib as M

R, RHO, DT, STEPS, N = 0.0015, 2500.0, 2.0e-6, 50000, 200
RD, HL, FIL = 0.05, 0.012, 0.004
DRUM = ("*SURFACE, TYPE=REVOLUTION, NAME=drum, FILLET RADIUS=%r\n0, 0, 0,  0, 0, 1\n"
        "START, 0.0, %r\nLINE, %r, %r\nLINE, %r, %r\nLINE, 0.0, %r\n"
        % (FIL, -HL, RD, -HL, RD, HL, HL))
LAWS = {"lammps": "law lammps hertz/history 2e8 NULL 0 0 0 0",
        "hertz": "law hertz youngsModulus 1.5e8 1.5e8 poissonsRatio 0.3 0.3 "
                 "coefficientRestitution 1 1 coefficientFriction 0 0"}
V0 = 2.0


def deck(tag, law):
    d = M.header((-0.055, 0.055, -0.055, 0.055, -0.015, 0.015), DT)
    rng = random.Random(7)
    placed = []
    while len(placed) < N:
        r, phi = math.sqrt(rng.random()) * (RD - 4 * R), rng.random() * 2 * math.pi
        p = (r * math.cos(phi), r * math.sin(phi), rng.uniform(-HL + 2 * R, HL - 2 * R))
        if all(sum((a - b) ** 2 for a, b in zip(p, q)) > (2.2 * R) ** 2 for q in placed):
            placed.append(p)
    for k, p in enumerate(placed):
        u = [rng.gauss(0, 1) for _ in range(3)]
        n = math.sqrt(sum(c * c for c in u))
        w = [rng.uniform(-50, 50) for _ in range(3)]
        d += M.sphere(k + 1, p, R, RHO, [V0 * c / n for c in u], w)
    d += "fix grav all gravity 9.81 vector 0 -1 0\n"
    d += ("fix w all wall/rigid surface drum.inp %s peratom yes "
          "rotate origin 0 0 0 axis 0 0 1 omega 3\n" % law)
    d += "fix integr all nve/sphere\n"
    d += M.dump_lines("d", 20, tag + ".dump", cols="id x y z vx vy vz omegax omegay omegaz "
                      "mass f_w[1]")
    d += "run %d\n" % STEPS
    return d


def energy(a):
    m = a["mass"]
    v2 = a["vx"] ** 2 + a["vy"] ** 2 + a["vz"] ** 2
    w2 = a["omegax"] ** 2 + a["omegay"] ** 2 + a["omegaz"] ** 2
    return 0.5 * m * v2 + 0.5 * 0.4 * m * R * R * w2 + m * 9.81 * a["y"]


def inside(a):
    """The centre's distance inside the drum's profile (mantle and caps, fillets ignored:
    they only cut the corners, so this is an upper bound)."""
    rho = math.hypot(a["x"], a["y"])
    return min(RD - rho, HL - abs(a["z"]))


def body(s):
    s.write("drum.inp", DRUM)
    for name, law in LAWS.items():
        s.run(name, deck(name, law))
        frames = M.read_dump(s.path(name + ".dump"))
        e0 = {i: energy(a) for i, a in frames[0][1].items()}
        scale = {i: a["mass"] * (9.81 * RD + 0.5 * V0 * V0) for i, a in frames[0][1].items()}
        worst, hits, gain, nfree = 0.0, 0, 0.0, 0
        touching = {i: False for i in e0}
        for _, f in frames[1:]:
            for i, a in f.items():
                if a["f_w[1]"] != 0.0:
                    hits += not touching[i]
                    touching[i] = True
                    continue
                touching[i] = False
                de = (energy(a) - e0[i]) / scale[i]
                worst, gain, nfree = max(worst, abs(de)), gain + de, nfree + 1
        s.ck.check("%s: the spheres hit the wall, about 6 times each" % name,
                   hits >= 5 * N, "%d hits" % hits)
        s.ck.check("%s: each sphere's energy off contact equals its start to 1e-3" % name,
                   worst <= 1e-3, "worst %.3g" % worst)
        s.ck.check("%s: no gain on average (mean change off contact below 2e-5)" % name,
                   gain / nfree <= 2e-5, "%.3g" % (gain / nfree))
        low = min(inside(a) for _, f in frames for a in f.values())
        s.ck.check("%s: every sphere's centre stays inside the drum" % name,
                   low > 0 and all(len(f) == N for _, f in frames),
                   "closest %.3g m inside" % low)


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
