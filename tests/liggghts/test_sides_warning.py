#!/usr/bin/python3
"""A one-sided surface with particles behind it says so: one WARNING, with the count and
the surface's name; a surface that holds its particles says nothing.

A one-sided surface pushes a particle that reaches it from behind through to its front
(the side its normal points to), so spheres inside a hopper whose profile runs the wrong
way, or inside a closed mesh wound outward and given `sides 1`, fall out. Pins:

- hopper: a REVOLUTION hopper (floor and cone, NAME=hopper) with its profile written
  top to bottom, its normal outward, with spheres inside: exactly one WARNING, naming
  `'hopper'` and the number of spheres whose centres lie within reach of its back at the
  start (their radius plus the neighbor skin: 3 placed 0.5 mm above the floor, the others
  more than 20 mm from the surface, counted here from the geometry); spheres are lost.
  The same on two ranks (the count is summed over the ranks, printed once).
- hopper written bottom to top (normal inward): no WARNING, and every sphere is still
  inside it at the end.
- a closed cube of 12 triangles wound outward, `sides 1`, spheres inside (4 within reach
  of a face at the start): exactly one WARNING naming the fix's surface and the count 4;
  spheres are lost.
- the same cube with the default sides (both, as LIGGGHTS's mesh walls): no WARNING,
  and every sphere stays inside.
"""
import math
import re

import liglib as L

R, RHO, DT = 0.004, 2500.0, 1.0e-5
SKIN = 0.002          # liglib.header's neighbor skin
STEPS = 30000         # 0.3 s: what passes a floor leaves the box
HALF = 0.04           # the cube [-HALF, HALF]^3


def hopper(right):
    """Floor r <= 0.02 at z = 0 and a cone to r = 0.08 at z = 0.1. Written bottom to top
    the normal is n = (-t_z, t_r): +z on the floor, inward and up on the cone."""
    pts = [(0.0, 0.0), (0.02, 0.0), (0.08, 0.1)]
    if not right:
        pts.reverse()
    prof = "START, %r, %r\n" % pts[0] + "".join("LINE, %r, %r\n" % p for p in pts[1:])
    return "*SURFACE, TYPE=REVOLUTION, NAME=hopper\n0, 0, 0, 0, 0, 1\n" + prof


def hopper_distance(p):
    """Distance from a point to the hopper's profile (floor segment and cone segment) in
    the (r, z) plane."""
    r, z = math.hypot(p[0], p[1]), p[2]
    pts = [(0.0, 0.0), (0.02, 0.0), (0.08, 0.1)]
    best = float("inf")
    for (a, b), (c, d) in zip(pts, pts[1:]):
        ux, uz = c - a, d - b
        t = max(0.0, min(1.0, ((r - a) * ux + (z - b) * uz) / (ux * ux + uz * uz)))
        best = min(best, math.hypot(r - a - t * ux, z - b - t * uz))
    return best


def hopper_spheres():
    near = [(x, 0.0, R + 0.0005) for x in (-0.01, 0.0, 0.01)]
    far = [(x, y, z) for z in (0.04, 0.06, 0.08) for x in (-0.012, 0.0, 0.012)
           for y in (-0.012, 0.0, 0.012)]
    return near + far


def cube_spheres():
    g = HALF - R - 0.0005
    near = [(0.0, 0.0, -g), (0.02, 0.0, -g), (g, 0.02, 0.01), (0.0, -g, 0.02)]
    far = [(x, y, z) for x in (-0.015, 0.0, 0.015) for y in (-0.015, 0.0, 0.015)
           for z in (-0.012, 0.003)]
    far = [p for p in far if all(math.dist(p, q) > 2 * R for q in near)]
    return near + far


def cube_distance(p):
    return min(HALF - abs(c) for c in p)


def deck(box, spheres, wall, inside):
    d = L.header(box, DT)
    for n, p in enumerate(spheres, 1):
        d += L.sphere(n, p, R, RHO)
    d += "fix grav all gravity 9.81 vector 0 0 -1\n"
    d += wall + "\n"
    d += "fix integr all nve/sphere\n"
    d += "thermo_modify lost ignore norm no\nthermo 5000\n"
    d += "run %d\n" % STEPS
    d += "region inside %s\nvariable nin equal count(all,inside)\n" % inside
    d += 'print "INSIDE ${nin}"\n'
    return d


def warnings(out):
    return [l for l in out.splitlines() if l.startswith("WARNING")]


def inside_count(out):
    rows = [l.split() for l in out.splitlines() if l.startswith("INSIDE ")]
    return int(float(rows[-1][1])) if rows else -1


def body(s):
    ck = s.ck
    s.write("hopper_wrong.inp", hopper(False))
    s.write("hopper_right.inp", hopper(True))
    s.write("cube.stl", L.stl_text(L.cube_triangles(HALF), "cube"))
    reach = R + SKIN

    hs = hopper_spheres()
    dists = [hopper_distance(p) for p in hs]
    n_near = sum(d <= reach for d in dists)
    ck.check("hopper deck: the spheres are either within reach or clearly beyond",
             n_near == 3 and all(d <= reach - 0.001 or d >= reach + 0.01 for d in dists),
             "%d within %.4g m" % (n_near, reach))
    hbox = (-0.09, 0.09, -0.09, 0.09, -0.05, 0.15)
    # inside the hopper: the cone's interior above the floor
    hin = "cone z 0 0 0.02 0.08 0 0.1 units box"
    for np_ in (1, 2):
        tag = "hopper_wrong" + ("_np2" if np_ > 1 else "")
        _, out = s.run(tag, deck(hbox, hs, "fix w all wall/rigid surface hopper_wrong.inp "
                                 "law hertz type 2", hin), np=np_)
        w = warnings(out)
        behind = [l for l in w if "back of the one-sided surface" in l]
        ck.check(tag + ": exactly one WARNING", len(w) == 1 and len(behind) == 1,
                 "%d warnings" % len(w), why="\n  ".join(w))
        ck.check(tag + ": it names the surface and the %d spheres within reach" % n_near,
                 bool(behind) and "'hopper'" in behind[0]
                 and re.search(r"\b%d particle\(s\)" % n_near, behind[0]) is not None,
                 behind[0][:160] if behind else "")
        ck.check(tag + ": spheres fall through it", 0 <= inside_count(out) < len(hs),
                 "%d of %d inside" % (inside_count(out), len(hs)))
    _, out = s.run("hopper_right", deck(hbox, hs, "fix w all wall/rigid surface "
                                        "hopper_right.inp law hertz type 2", hin))
    ck.check("hopper_right: no WARNING", not warnings(out), why="\n  ".join(warnings(out)))
    ck.check("hopper_right: holds every sphere", inside_count(out) == len(hs),
             "%d of %d inside" % (inside_count(out), len(hs)))

    cs = cube_spheres()
    dists = [cube_distance(p) for p in cs]
    n_near = sum(d <= reach for d in dists)
    ck.check("cube deck: the spheres are either within reach or clearly beyond",
             n_near == 4 and all(d <= reach - 0.001 or d >= reach + 0.01 for d in dists),
             "%d within %.4g m" % (n_near, reach))
    cbox = (-0.06, 0.06, -0.06, 0.06, -0.06, 0.06)
    cin = "block %r %r %r %r %r %r units box" % (-HALF, HALF, -HALF, HALF, -HALF, HALF)
    _, out = s.run("cube_sides1", deck(cbox, cs, "fix box all wall/rigid surface inline "
                                       "mesh cube.stl sides 1 law hertz type 2", cin))
    w = warnings(out)
    behind = [l for l in w if "back of the one-sided surface" in l]
    ck.check("cube_sides1: exactly one WARNING", len(w) == 1 and len(behind) == 1,
             "%d warnings" % len(w), why="\n  ".join(w))
    ck.check("cube_sides1: it names the surface and the %d spheres within reach" % n_near,
             bool(behind) and "'box'" in behind[0]
             and re.search(r"\b%d particle\(s\)" % n_near, behind[0]) is not None,
             behind[0][:160] if behind else "")
    ck.check("cube_sides1: spheres fall through it", 0 <= inside_count(out) < len(cs),
             "%d of %d inside" % (inside_count(out), len(cs)))
    _, out = s.run("cube_default", deck(cbox, cs, "fix box all wall/rigid surface inline "
                                        "mesh cube.stl law hertz type 2", cin))
    ck.check("cube_default: no WARNING", not warnings(out), why="\n  ".join(warnings(out)))
    ck.check("cube_default: holds every sphere", inside_count(out) == len(cs),
             "%d of %d inside" % (inside_count(out), len(cs)))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
