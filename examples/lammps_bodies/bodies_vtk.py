#!/usr/bin/python3
"""LAMMPS's rounded polyhedra as legacy VTK files for ParaView: one polydata file per
frame, OUTDIR/bodies_STEP.vtk, each body drawn as the faces of its polyhedron (the core
of the rounded body, the rounding radius left out) in its current pose, with its id,
type and speed as cell data.

The vertices come from `dump local` of `compute body/local id 1 2 3` (index, id, x, y, z:
each body's vertices in the world frame, in the order of the data file); the faces (up
to 4 vertex indices, -1 padding a triangle) from the data file's Bodies section; the speed
from a `dump custom` of id, type, vx, vy, vz (optional: without it the speed is left out).

Usage: bodies_vtk.py DATA VERTICES_DUMP OUTDIR [BODIES_DUMP]
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from liggghts_out import read_dump  # noqa: E402  (LAMMPS's dump custom is the same format)


def read_faces(path):
    """{id: [face, ...]} from a data file's Bodies section (atom_style body
    rounded/polyhedron: a line "id 3 ndouble", a line "nv ne nf", then the doubles:
    6 inertia, 3 nv coordinates, 2 ne edge indices, 4 nf face indices, the diameter)."""
    with open(path) as f:
        lines = f.read().split("\n")
    try:
        k = next(i for i, l in enumerate(lines) if l.split("#")[0].strip() == "Bodies")
    except StopIteration:
        sys.exit("%s: no Bodies section" % path)
    words = " ".join(lines[k + 1:]).split()
    faces, p = {}, 0
    while p < len(words):
        bid, nd = int(words[p]), int(words[p + 2])
        nv, ne, nf = (int(w) for w in words[p + 3:p + 6])
        vals = [float(w) for w in words[p + 6:p + 6 + nd]]
        if len(vals) != nd or nd != 6 + 3 * nv + 2 * ne + 4 * nf + 1:
            sys.exit("%s: body %d: expected %d values (nv %d ne %d nf %d), found %d"
                     % (path, bid, 6 + 3 * nv + 2 * ne + 4 * nf + 1, nv, ne, nf, len(vals)))
        f0 = 6 + 3 * nv + 2 * ne
        faces[bid] = [[int(c) for c in vals[f0 + 4 * j:f0 + 4 * j + 4] if c >= 0]
                      for j in range(nf)]
        p += 6 + nd
    return faces


def read_local(path):
    """[(step, {id: [(x, y, z), ...]})] from a dump local of index, id, x, y, z."""
    frames = []
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            verts = {}
            for line in lines[i + 9:i + 9 + n]:
                w = line.split()
                verts.setdefault(int(float(w[1])), []).append(tuple(float(c) for c in w[2:5]))
            frames.append((step, verts))
            i += 9 + n
        else:
            i += 1
    return frames


def read_custom(path):
    """{step: {id: {column: value}}} from a dump custom."""
    return dict(read_dump(path))


def write(path, verts, faces, atoms):
    ids = sorted(verts)
    base, pts, polys = {}, [], []
    for b in ids:
        base[b] = len(pts)
        pts += verts[b]
        polys += [(b, [base[b] + c for c in face]) for face in faces[b]]
    with open(path, "w") as f:
        f.write("# vtk DataFile Version 3.0\nrounded polyhedra\nASCII\nDATASET POLYDATA\n")
        f.write("POINTS %d double\n" % len(pts))
        f.writelines("%.9g %.9g %.9g\n" % p for p in pts)
        f.write("POLYGONS %d %d\n" % (len(polys), sum(1 + len(p) for _, p in polys)))
        f.writelines("%d %s\n" % (len(p), " ".join(str(c) for c in p)) for _, p in polys)
        f.write("CELL_DATA %d\n" % len(polys))
        f.write("SCALARS id int 1\nLOOKUP_TABLE default\n")
        f.writelines("%d\n" % b for b, _ in polys)
        if atoms:
            f.write("SCALARS type int 1\nLOOKUP_TABLE default\n")
            f.writelines("%d\n" % atoms[b]["type"] for b, _ in polys)
            f.write("SCALARS speed double 1\nLOOKUP_TABLE default\n")
            f.writelines("%.6g\n" % math.sqrt(sum(atoms[b][c] ** 2 for c in ("vx", "vy", "vz")))
                         for b, _ in polys)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    data, local, out = sys.argv[1:4]
    custom = read_custom(sys.argv[4]) if len(sys.argv) > 4 else {}
    faces = read_faces(data)
    frames = read_local(local)
    for step, verts in frames:
        for b, v in verts.items():
            if b not in faces:
                sys.exit("%s: step %d: body %d is not in %s" % (local, step, b, data))
            need = 1 + max(c for face in faces[b] for c in face)
            if len(v) < need:
                sys.exit("%s: step %d: body %d has %d vertices, its faces use %d"
                         % (local, step, b, len(v), need))
        write(os.path.join(out, "bodies_%d.vtk" % step), verts, faces, custom.get(step))
    print("%d VTK files of the bodies' faces in %s" % (len(frames), out))


if __name__ == "__main__":
    main()
