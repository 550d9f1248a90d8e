#!/usr/bin/python3
"""The rounded polyhedra of in.bodies as a LAMMPS data file (atom_style body
rounded/polyhedron): cubes and bricks (boxes of 2:1:1) with rounded edges, on a loose
lattice filling the drum's cross-section below a height, each with a small random
velocity and angular momentum (a fixed seed: the same file every time). Lengths are in
mm, masses in g and times in ms, as in.bodies takes them (units lj read that way: forces in
N, speeds in m/s, energies in mJ).

Each body is given in its own principal axes (its box axes along x, y, z; a brick's long
axis along one of them, drawn at random), so its inertia tensor is diagonal: LAMMPS
diagonalises the tensor it reads and keeps the body in the principal axes it finds, and a
turned cube's tensor, isotropic up to off-diagonal terms of rounding size, comes out in
axes where its hull has no volume left (docs/lammps.md). Its mass and moments are those of
the solid box of its outer size (core plus rounding), density RHO.

The rounding radius is about a quarter of a body's smallest core half-extent. LAMMPS's
pair body/rounded/polyhedron (29Sep2021) is not reliable with rounder bodies: of 20 random
impacts of two cubes rounded by 0.42 of their half-side (damped, 0.3 m/s), 7 left with
more kinetic energy than a plastic impact keeps, 3 with more than came in (up to 3 times);
rounded by 0.25, none of 44.

Usage: make_bodies.py OUT.data [N]   (at most N bodies; default: one on every lattice point)
Prints the number of bodies and their sizes.
"""
import math
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from lammps_bodies import box_body  # noqa: E402

RHO = 2.5e-3                          # g/mm^3 (2500 kg/m^3)
R_DRUM, HALF_LEN = 35.0, 15.0         # the drum of drum.inp: radius, half its length
ROUND = 0.5                           # rounding radius of every body
CUBE = (2.2, 2.2, 2.2)                # core half-extents of a cube (outer 5.4 mm)
BRICK = (3.3, 1.65, 1.65)             # ... of a brick (outer 7.6 x 4.3 x 4.3 mm)
SPACING = 8.5                         # lattice spacing (larger than a brick's length)
CLEAR = 5.5                           # lattice points this far inside the mantle
TOP = 12.0                            # highest lattice row (y), drum centre at 0


def body(core, r):
    """Vertices, edges, faces, mass and the diagonal inertia of a box of core half-extents
    core rounded by r (mass and moments of the solid box of the outer size)."""
    V, E, F = box_body(core)
    a, b, c = (h + r for h in core)
    m = RHO * 8 * a * b * c
    inertia = (m / 3 * (b * b + c * c), m / 3 * (a * a + c * c), m / 3 * (a * a + b * b))
    return V, E, F, m, inertia


def lattice():
    pts = []
    n = int(R_DRUM / SPACING) + 1
    nz = int(2 * (HALF_LEN - CLEAR) / SPACING + 1e-6) + 1
    zs = [(k - 0.5 * (nz - 1)) * SPACING for k in range(nz)]
    for j in range(-n, n + 1):
        for i in range(-n, n + 1):
            x, y = (i + 0.5 * (j % 2)) * SPACING, j * SPACING
            if y <= TOP and math.hypot(x, y) <= R_DRUM - CLEAR:
                pts += [(x, y, z) for z in zs]
    pts.sort(key=lambda p: (p[1], p[0], p[2]))   # lowest first
    return pts


def main():
    out = sys.argv[1]
    nmax = int(sys.argv[2]) if len(sys.argv) > 2 else None
    rng = random.Random(20261207)
    pts = lattice()[:nmax]
    lines_atoms, lines_vel, lines_body = [], [], []
    kinds = {"cube": 0, "brick": 0}
    for k, p in enumerate(pts):
        if rng.random() < 0.5:
            core, kind = CUBE, "cube"
        else:
            axis = rng.randrange(3)              # the brick's long axis
            core = tuple(BRICK[(j - axis) % 3] for j in range(3))
            kind = "brick"
        kinds[kind] += 1
        V, E, F, m, inertia = body(core, ROUND)
        v = [rng.uniform(-0.05, 0.05) for _ in range(3)]
        L = [rng.uniform(-0.1, 0.1) for _ in range(3)]
        lines_atoms.append("%d %d 1 %.10g %.10g %.10g %.10g"
                           % (k + 1, 1 if kind == "cube" else 2, m, p[0], p[1], p[2]))
        lines_vel.append("%d %s" % (k + 1, " ".join("%.6g" % c for c in v + L)))
        vals = list(inertia) + [0.0, 0.0, 0.0] + [c for q in V for c in q] + \
            [c for e in E for c in e] + [c for f in F for c in f] + [2 * ROUND]
        lines_body.append("%d 3 %d\n%d %d %d\n%s" % (
            k + 1, len(vals), len(V), len(E), len(F),
            "\n".join(" ".join(w for w in (("%d" % x) if isinstance(x, int) else
                                           ("%.10g" % x) for x in vals[i:i + 8]))
                      for i in range(0, len(vals), 8))))
    m = R_DRUM + 2.5
    with open(out, "w") as f:
        f.write("Rounded cubes and bricks in a drum (examples/lammps_bodies/make_bodies.py)"
                "\n\n%d atoms\n%d bodies\n2 atom types\n" % (len(pts), len(pts)))
        f.write("%g %g xlo xhi\n%g %g ylo yhi\n%g %g zlo zhi\n\n"
                % (-m, m, -m, m, -(HALF_LEN + 2.0), HALF_LEN + 2.0))
        f.write("Atoms # body\n\n" + "\n".join(lines_atoms) + "\n\n")
        f.write("Velocities\n\n" + "\n".join(lines_vel) + "\n\n")
        f.write("Bodies\n\n" + "\n".join(lines_body) + "\n")
    print("%d bodies (%d cubes of outer side %.1f mm, %d bricks %.1f x %.1f x %.1f mm), "
          "rounding radius %.1f mm: %s"
          % (len(pts), kinds["cube"], 2 * (CUBE[0] + ROUND), kinds["brick"],
             2 * (BRICK[0] + ROUND), 2 * (BRICK[1] + ROUND), 2 * (BRICK[2] + ROUND),
             ROUND, out))


if __name__ == "__main__":
    main()
