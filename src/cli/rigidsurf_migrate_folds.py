"""The concave folds of a mesh within contact reach (part of rigidsurf-migrate; the NOTE
of docs/migration.md, *Folds*).

A fold is an edge between two faces whose normals differ by θ > 0; a mesh that acts on
both sides (LIGGGHTS's mesh walls, and wall/rigid's default for STL, OBJ, OFF and PLY)
meets it as a concave fold from one side. A sphere of radius R that overlaps both faces
by δ touches them in two discs of radius a = √(2Rδ − δ²) whose centres lie
2 (R − δ) sin(θ/2) apart: they are one patch when that is at most 2a, which for
δ = 1 % of R is θ ≤ 16.4°. There LIGGGHTS gives each face a whole contact and
wall/rigid one patch shared between the two (docs/conventions.md, *Shares at concave
folds*).

The reader takes ASCII and binary STL, OBJ (v and f lines), OFF and ASCII PLY; it welds
nodes that coincide to 1e-9 of the mesh's size.
"""
import math
import struct

OVERLAP = 0.01  # δ / R of the reach
REACH = 2.0 * math.degrees(math.asin(math.sqrt(2 * OVERLAP - OVERLAP ** 2) / (1 - OVERLAP)))
FLAT = 1e-9     # radians: below it two faces are one plane


def read_triangles(path):
    """The mesh's triangles as ((x, y, z), (x, y, z), (x, y, z)); polygons fanned; None for
    a file the reader does not take."""
    with open(path, "rb") as f:
        data = f.read()
    low = path.lower()
    if low.endswith(".stl"):
        if len(data) >= 84:
            n = struct.unpack("<I", data[80:84])[0]
            if 84 + 50 * n == len(data):
                return [tuple(struct.unpack("<3f", data[84 + 50 * k + 12 * (j + 1):
                                                          84 + 50 * k + 12 * (j + 2)])
                              for j in range(3)) for k in range(n)]
        vals = [float(x) for line in data.decode("latin-1").splitlines()
                for x in line.split()[1:4] if line.split()[:1] == ["vertex"]]
        pts = [tuple(vals[i:i + 3]) for i in range(0, len(vals), 3)]
        return [tuple(pts[i:i + 3]) for i in range(0, len(pts) - 2, 3)]
    lines = data.decode("latin-1").splitlines()
    if low.endswith(".obj"):
        pts, faces = [], []
        for line in lines:
            w = line.split()
            if w[:1] == ["v"]:
                pts.append(tuple(float(x) for x in w[1:4]))
            elif w[:1] == ["f"]:
                faces.append([int(x.split("/")[0]) for x in w[1:]])
        faces = [[i - 1 if i > 0 else len(pts) + i for i in f] for f in faces]
        return fan(pts, faces)
    if low.endswith(".off"):
        toks = [t for line in lines for t in line.split("#")[0].split()]
        if not toks or not toks[0].endswith("OFF"):
            return None
        nv, nf = int(toks[1]), int(toks[2])
        k = 4
        pts = [tuple(float(x) for x in toks[k + 3 * i:k + 3 * i + 3]) for i in range(nv)]
        k += 3 * nv
        faces = []
        for _ in range(nf):
            n = int(toks[k])
            faces.append([int(x) for x in toks[k + 1:k + 1 + n]])
            k += 1 + n
        return fan(pts, faces)
    if low.endswith(".ply") and lines[:1] == ["ply"] and "format ascii 1.0" in lines[1]:
        nv = nf = 0
        end = lines.index("end_header")
        for line in lines[:end]:
            w = line.split()
            if w[:2] == ["element", "vertex"]:
                nv = int(w[2])
            elif w[:2] == ["element", "face"]:
                nf = int(w[2])
        body = lines[end + 1:]
        pts = [tuple(float(x) for x in body[i].split()[:3]) for i in range(nv)]
        faces = [[int(x) for x in body[nv + i].split()[1:]] for i in range(nf)]
        return fan(pts, faces)
    return None


def fan(pts, faces):
    return [(pts[f[0]], pts[f[j]], pts[f[j + 1]]) for f in faces for j in range(1, len(f) - 1)]


def folds(tris):
    """(the number of edges two faces share, the fold angles θ in degrees of those that
    are not flat)."""
    lo = [min(p[d] for t in tris for p in t) for d in range(3)]
    hi = [max(p[d] for t in tris for p in t) for d in range(3)]
    tol = 1e-9 * math.sqrt(sum((h - l) ** 2 for h, l in zip(hi, lo))) or 1e-300
    nodes, faces, normals = {}, [], []
    for t in tris:
        ids = tuple(nodes.setdefault(tuple(round(c / tol) for c in p), len(nodes)) for p in t)
        u = [t[1][d] - t[0][d] for d in range(3)]
        v = [t[2][d] - t[0][d] for d in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        ln = math.sqrt(sum(x * x for x in n))
        if len(set(ids)) < 3 or ln == 0.0:
            continue
        faces.append(ids)
        normals.append([x / ln for x in n])
    edges = {}
    for k, f in enumerate(faces):
        for j in range(3):
            edges.setdefault(tuple(sorted((f[j], f[(j + 1) % 3]))), []).append(k)
    shared, angles = 0, []
    for fs in edges.values():
        if len(fs) != 2:
            continue
        shared += 1
        a, b = normals[fs[0]], normals[fs[1]]
        cross = math.sqrt(sum(x * x for x in (a[1] * b[2] - a[2] * b[1],
                                              a[2] * b[0] - a[0] * b[2],
                                              a[0] * b[1] - a[1] * b[0])))
        th = math.atan2(cross, abs(sum(x * y for x, y in zip(a, b))))
        if th > FLAT:
            angles.append(math.degrees(th))
    return shared, angles


def note(path):
    """The NOTE's text for the mesh at path, or None when it has no fold within reach
    (or the reader does not take the file)."""
    try:
        tris = read_triangles(path)
    except (OSError, ValueError, IndexError, struct.error):
        tris = None
    if not tris:
        return None
    shared, angles = folds(tris)
    near = [a for a in angles if a <= REACH]
    if not near:
        return None
    return ("%d of its %d inner edges are folds of %.2g to %.2g degrees, within %.1f "
            "(a sphere pressed into both faces by 1 %% of its radius touches them as one "
            "patch): LIGGGHTS gives each face a whole contact there, wall/rigid one patch "
            "shared between them (docs/migration.md, Folds)"
            % (len(near), shared, min(near), max(near), REACH))
