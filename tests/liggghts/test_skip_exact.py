#!/usr/bin/python3
"""The distance bounds of fix wall/rigid skip no contact.

On a wall that stays in place, a sphere that holds no contact and whose distance bound
keeps it beyond the tracking thickness is not queried (docs/fix_wall_rigid.md). A wall
given `rotate ... axis 1 0 0 omega 0` moves in name only (about an axis it is not
invariant under, at zero speed): no bound holds for a moving wall, so every candidate is
queried every step. 60 spheres with random velocities bounce in a closed drum under gravity
(hertz, tangential history, default tracking 0), and the two runs must give the same
trajectories, forces and wall totals to the last bit, over 8000 steps that include many
impacts, flights inside the skin (8 mm, so that spheres are skipped for long) and
rebuilds of the neighbour lists; one sphere dropped on the bottom from 5 mm, skipped
while it falls and caught at the step it touches; and one sphere rolling on the bottom,
lifted 1 mm and stopped between two runs (displace_atoms, set) while it holds its
contact: the second run must see that contact leave at its first step, not carry its
slip and stress to the landing. Both for the REVOLUTION drum (bounds
from the query's look-ahead) and for the same drum as a MESH (an STL of 96 x 8 quads and
capped ends; bounds from the candidate lists' nearest triangles).
"""
import math
import random

import liglib as L

R, RHO, DT, RC, SKIN = 0.002, 2500.0, 1e-5, 0.03, 0.008
COLS = "id x y z vx vy vz fx fy fz omegax omegay omegaz"
SURF = ["surface drum.inp"]  # the wall's surface words of the case being run


def drum_stl(n=96, nz=8, zlo=-0.02, zhi=0.02):
    """The drum as facets, normals inward: a mantle of n x nz quads, nodes on the circle
    of radius RC, and two fans of caps."""
    ring = [(RC * math.cos(2 * math.pi * i / n), RC * math.sin(2 * math.pi * i / n))
            for i in range(n)]
    tris = []
    for i in range(n):
        (x0, y0), (x1, y1) = ring[i], ring[(i + 1) % n]
        for k in range(nz):
            za, zb = zlo + (zhi - zlo) * k / nz, zlo + (zhi - zlo) * (k + 1) / nz
            a, b, c, d = (x0, y0, za), (x0, y0, zb), (x1, y1, zb), (x1, y1, za)
            tris += [(a, b, c), (a, c, d)]
        tris.append(((0.0, 0.0, zlo), (x0, y0, zlo), (x1, y1, zlo)))  # bottom, normal +z
        tris.append(((0.0, 0.0, zhi), (x1, y1, zhi), (x0, y0, zhi)))  # top, normal -z
    out = ["solid drum"]
    for t in tris:
        out.append(" facet normal 0 0 0\n  outer loop")
        out += ["   vertex %.17g %.17g %.17g" % p for p in t]
        out.append("  endloop\n endfacet")
    return "\n".join(out + ["endsolid drum"]) + "\n"


def deck(extra, drop=False, lift=False):
    d = L.header((-0.035, 0.035, -0.035, 0.035, -0.035, 0.035), DT)
    d += "neighbor %r bin\n" % SKIN  # a wide skin: long skips between rebuilds
    if drop:
        # one sphere dropped on the drum's bottom cap from a gap of 5 mm, at rest
        return d + L.sphere(1, (0.0, 0.0, -0.02 + R + 0.005), R, RHO) + tail(extra, 5000)
    if lift:
        # one sphere rolling on the bottom cap, pressed into it, lifted while it holds
        # its contact and stopped: it falls straight back, so its distance bound lets it
        # be skipped until it touches, and lands after about 1400 steps of the second
        # run, where the tangential stress of a contact carried over would differ
        d += L.sphere(1, (-0.01, 0.0, -0.02 + R - 1e-6), R, RHO, v=(0.1, 0.03, 0.0))
        return d + tail(extra, 1000, "displace_atoms all move 0 0 0.001\n"
                        "set atom 1 vx 0 vy 0 vz 0 omegax 0 omegay 0 omegaz 0\n"
                        "run 3000\n")
    rng = random.Random(7)
    for k in range(60):
        while True:
            p = (rng.uniform(-0.024, 0.024), rng.uniform(-0.024, 0.024),
                 rng.uniform(-0.015, 0.015))
            if p[0] ** 2 + p[1] ** 2 < 0.024 ** 2:
                break
        v = tuple(rng.uniform(-0.5, 0.5) for _ in range(3))
        d += L.sphere(k + 1, p, R * (1.0 + 0.2 * (k % 3)) / 1.2, RHO, v=v)
    return d + tail(extra, 8000)


def tail(extra, steps, more=""):
    d = "fix g all gravity 9.81 vector 0 %s\n" % ("-1 0" if steps == 8000 else "0 -1")
    d += "fix w all wall/rigid %s law hertz type 2%s\n" % (SURF[0], extra)
    d += "fix integr all nve/sphere\n"
    d += L.dump_lines("d", 1000, "traj.dump", COLS)
    d += ('variable fw equal f_w[1]+f_w[2]+f_w[3]\n'
          'fix pr all print 100 "${fw}" file wall.txt screen no\n')
    d += "run %d\n" % steps + more
    return d


def body(s):
    s.write("drum.inp", L.drum(RC, -0.02, 0.02, caps=True))
    s.write("drum.stl", drum_stl())
    for kind, surf in (("revolution", "surface drum.inp"), ("mesh", "surface inline mesh drum.stl")):
        SURF[0] = surf
        for case, drop, lift, nd in (("bed", False, False, 9), ("drop", True, False, 6),
                                     ("lift", False, True, 5)):
            name = kind + " " + case
            out = {}
            for tag, extra in (("static", ""),
                               ("moving", " rotate origin 0 0 0 axis 1 0 0 omega 0")):
                s.run(kind + "_" + case + "_" + tag, deck(extra, drop, lift))
                out[tag] = (open(s.path("traj.dump")).read(), open(s.path("wall.txt")).read())
                nsnap = out[tag][0].count("ITEM: TIMESTEP")
                s.ck.check("%s, %s: dump written" % (name, tag), nsnap == nd,
                           "%d snapshots" % nsnap)
            st, mv = out["static"], out["moving"]
            s.ck.check(name + ": trajectories and forces identical to the last bit",
                       st[0] == mv[0], why="the dumps differ")
            s.ck.check(name + ": wall force totals identical to the last bit", st[1] == mv[1],
                       why="the wall totals differ")
            fw = [float(l) for l in st[1].splitlines() if l.strip() and not l.startswith("#")]
            s.ck.check(name + ": the wall carried forces", any(abs(f) > 0 for f in fw),
                       "%d samples" % len(fw))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
