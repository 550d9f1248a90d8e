#!/usr/bin/python3
"""The primitive-wall replacements of docs/migration.md are LIGGGHTS's primitive walls.

The fenced blocks of docs/migration.md that follow a `<!-- tested: ...test_primitive_walls`
marker hold pairs of lines with one fix ID: `fix ID ... wall/gran ... primitive type T
KIND args` and its `fix ID ... wall/rigid` replacement. The page says every replacement
acts on the particles' side (the inside of the packing tutorial's box, the inside of a
cylinder) and that `sides 2`, written before `profile`, makes it act on both sides, as
LIGGGHTS's primitive walls do. For each pair, in the same deck and executable:
- as written: a sphere on the particles' side hits the wall;
- with `sides 2`: that sphere and one on the other side;
and the trajectories equal those against LIGGGHTS's wall. Where the spheres go comes
from the LIGGGHTS line alone (plane position, cylinder radius and axis with c1, c2 in
LIGGGHTS's cyclic order), so a replacement on the wrong side or at the wrong place, or a
primitive the page leaves out, fails.

On a plane the spheres hit obliquely, spinning, and agree to 1e-9 relative. On a
cylinder a normal impact agrees to 1e-9; an oblique, spinning one to 1e-6: as the
sphere moves, the normal turns by an angle a per step, and LIGGGHTS projects the shear
history onto the new tangent plane (shortening it by 1 - cos a) where rigidsurf carries
it with the frame (docs/conventions.md, LIGGGHTS Hertz wall model).
"""
import math
import os
import re

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
TOL = 1e-9  # 1e-6 for oblique impacts on a cylinder (see above)
GAP = 2.13e-4  # not a whole number of steps of travel (see test_wall_equivalence.py)
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.2)
# The particles' side of a plane is that of the packing tutorial's box centre.
BOX_CENTRE = (0.0, 0.0, 0.075)
KINDS = ("xplane", "yplane", "zplane", "xcylinder", "ycylinder", "zcylinder")
DOC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs",
                   "migration.md")


def doc_pairs(path):
    """{fix ID: (LIGGGHTS line, rigidsurf line)} from the marked blocks of the page."""
    text = open(path).read()
    lines = []
    for m in re.finditer(r"<!-- tested: [^>]*test_primitive_walls[^>]*-->\s*```\n(.*?)```",
                         text, re.S):
        lines += m.group(1).replace("&\n", " ").splitlines()
    pairs = {}
    for ln in lines:
        w = ln.split()
        if len(w) > 3 and w[0] == "fix":
            slot = 0 if w[3] == "wall/gran" else 1 if w[3] == "wall/rigid" else None
            if slot is not None:
                pairs.setdefault(w[1], [None, None])[slot] = " ".join(w)
    return pairs


def wall_geometry(lig):
    """(kind, params) of a LIGGGHTS primitive line."""
    w = lig.split()
    i = next(k for k, x in enumerate(w) if x in KINDS)
    n = 1 if w[i].endswith("plane") else 3
    return w[i], [float(x) for x in w[i + 1:i + 1 + n]]


def spheres(kind, par, both, oblique):
    """Atoms that hit the wall at 1 m/s: one on the particles' side and, with both, one
    on the other; oblique: also 0.3 and 0.4 m/s along the wall, spinning. Returns the
    atoms and, per atom, the unit direction pointing away from the wall on its side."""
    k = "xyz".index(kind[0])
    j, l = (k + 1) % 3, (k + 2) % 3  # LIGGGHTS's cyclic order of the other two axes
    out = []
    for side in ((1, -1) if both else (1,)):
        pos, vel, away = [0.0] * 3, [0.0] * 3, [0.0] * 3
        if kind.endswith("plane"):
            inside = 1.0 if BOX_CENTRE[k] > par[0] else -1.0
            s = inside * side
            pos = list(BOX_CENTRE)
            pos[k] = par[0] + s * (R + GAP)
            pos[j] += 0.02 * side  # the two spheres pass the wall 4 radii apart
            away[k] = s
        else:
            rc, c1, c2 = par
            th = 0.7 if side > 0 else 0.7 + math.pi / 2
            rad = rc - R - GAP if side > 0 else rc + R + GAP
            e = [0.0] * 3
            e[j], e[l] = math.cos(th), math.sin(th)
            pos[j], pos[l] = c1 + rad * e[j], c2 + rad * e[l]
            pos[k] = 0.01 * side
            away = [-side * x for x in e]
        for d in range(3):
            vel[d] = -away[d] * 1.0
        if not oblique:
            pass
        elif kind.endswith("plane"):
            vel[j] += 0.3
            vel[l] += 0.4 * side
        else:
            vel[j] -= 0.3 * e[l]
            vel[l] += 0.3 * e[j]
            vel[k] += 0.4 * side
        out.append((pos, vel, away))
    spin = (40.0, -90.0, 25.0) if oblique else (0.0, 0.0, 0.0)
    atoms = "".join(L.sphere(i + 1, p, R, RHO, v=v, omega=spin)
                    for i, (p, v, _) in enumerate(out))
    return atoms, [a for _, _, a in out]


def body(s):
    pairs = doc_pairs(DOC)
    seen = {wall_geometry(p[0])[0] for p in pairs.values() if p[0]}
    s.ck.check("docs/migration.md replaces every primitive wall",
               all(p[0] and p[1] for p in pairs.values()) and seen == set(KINDS),
               "%d pairs: %s" % (len(pairs), " ".join(sorted(seen))),
               why="want a wall/gran line and a wall/rigid line per fix ID, covering "
               + " ".join(KINDS))
    for fid, (lig, ours) in sorted(pairs.items()):
        if not (lig and ours):
            continue
        kind, par = wall_geometry(lig)
        two = re.sub(r" profile ", " sides 2 profile ", ours, count=1)
        plane = kind.endswith("plane")
        cases = [("", True, TOL)] if plane else [("", False, TOL), ("_oblique", True, 1e-6)]
        for what, oblique, tol in cases:
            for tag, line, both in ((fid, ours, False), (fid + "_sides2", two, True)):
                atoms, away = spheres(kind, par, both, oblique)

                def bounced(frames, away=away):
                    last = frames[-1][1]
                    return all(sum(last[i + 1][c] * away[i][d] for d, c in
                                   enumerate(("vx", "vy", "vz"))) > 0
                               for i in range(len(away)))
                L.compare_walls(s, "%s_%s%s" % (tag, kind, what), line, lig, atoms, 500,
                                False, "nve/sphere", BOX, bounced, DT, SCALES, tol,
                                head={"ntypes": 1}, ref_tag="gran")


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
