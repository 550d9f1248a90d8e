"""LAMMPS's regions as exact wall/rigid surfaces (part of rigidsurf-migrate;
docs/migration.md, *LAMMPS walls*).

What a `fix wall/gran/region` pushes on is the region's surface as LAMMPS 29Sep2021
computes its contacts (region_*.cpp): a particle whose centre lies inside the region
(`side in`) or outside it (`side out`) meets each face within reach; with an `open` face
the region is two-sided (Region::match accepts every point, and Region::surface adds the
exterior contacts to the interior ones). Each becomes:

- plane: a CYLINDER of one LINE facing the region's side;
- cylinder, cone, sphere: a REVOLUTION whose profile is the solid's outline in (r, z),
  one chain per run of faces left by `open` (faces 1 and 2 the end caps at lo and hi, 3
  the side), an INF end without its cap;
- block, prism: a closed triangle mesh (or with its open faces left out), written beside
  the deck;
- union or intersect of coaxial cylinders and cones and planes normal to their axis: the
  REVOLUTION of the solid's outline (its radius the largest, or smallest, of its
  members' at each height); of planes whose normals are normal to one direction: a
  CYLINDER (an extrusion) of the outline of the half-planes' union or intersection; of
  members that are all open: each member's surfaces (LAMMPS then keeps every member's
  contacts, as separate walls do).

A surface faces the region's side (`sides 2` where the region is two-sided). What the
tool cannot express exactly raises Unmigratable with the reason.
"""
import math

BIG = 1.0e20   # LAMMPS's INF


class Unmigratable(Exception):
    """A region that no exact wall/rigid surface reproduces: why."""


class Surf:
    """One wall/rigid surface: kind 'plane' (point, normal), 'revolution' (origin, axis,
    items), 'extrusion' (a, b, c, items), 'mesh' (triangles); two_sided; curvature (a set
    of 'cyl', 'cone', 'sphere': the curved faces, LAMMPS's radius of curvature for
    each), beta (the largest half-angle of a cone face, degrees)."""

    def __init__(self, kind, **kw):
        self.kind, self.two_sided, self.curvature, self.beta = kind, False, set(), 0.0
        self.__dict__.update(kw)


# ---- vectors ------------------------------------------------------------------------

def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def scale(a, s):
    return [x * s for x in a]


def unit(a):
    n = math.sqrt(dot(a, a))
    return [x / n for x in a]


def rotation(axis, angle):
    """Rodrigues' matrix for a turn by angle about the unit axis."""
    x, y, z = axis
    c, s = math.cos(angle), math.sin(angle)
    C = 1.0 - c
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]


def matvec(m, v):
    return [dot(row, v) for row in m]


# ---- one region's values -------------------------------------------------------------

class Context:
    """What a region's numbers need: the lattice spacings (or why they are not known),
    the box (lo, hi per axis, or None) and L, the half-length of a LINE that reaches past
    the box."""

    def __init__(self, lattice, box, L):
        self.lattice, self.box, self.L = lattice, box, L


def values(reg, ctx, number):
    """The region's numbers as LAMMPS scales them (units lattice: times the lattice
    spacing of each value's axis); INF as +-BIG, EDGE as the box's bound."""
    if reg.units == "lattice":
        if isinstance(ctx.lattice, str):
            raise Unmigratable("region %s is in lattice units, and %s" % (reg.id,
                                                                         ctx.lattice))
        sc = ctx.lattice
    else:
        sc = (1.0, 1.0, 1.0)
    axes = AXES[reg.style](reg.values)
    out = []
    for k, (w, ax) in enumerate(zip(reg.values, axes)):
        if ax is None:
            out.append(w)
            continue
        if w in ("INF", "EDGE"):
            lo = k % 2 == 0 if reg.style in ("block", "prism") else \
                k == len(reg.values) - 2
            if w == "INF":
                out.append(-BIG if lo else BIG)
            elif ctx.box is None:
                raise Unmigratable("region %s: EDGE, and the box's bounds are not known"
                                   % reg.id)
            else:
                out.append(ctx.box[ax][0 if lo else 1])
            continue
        v = number(w)
        if v is None:
            raise Unmigratable("region %s: '%s' is not a number the tool knows" % (reg.id,
                                                                                  w))
        out.append(v * sc[ax])
    return out


def _dims(axis):
    """The axes of c1, c2 of a cylinder or cone along axis, and of its radius."""
    return {"x": (1, 2, 1), "y": (0, 2, 0), "z": (0, 1, 0)}[axis]


def _cyl_axes(v, cone=False):
    a = _dims(v[0])
    ax = "xyz".index(v[0])
    return [None, a[0], a[1], a[2]] + ([a[2]] if cone else []) + [ax, ax]


AXES = {"block": lambda v: [0, 0, 1, 1, 2, 2],
        "prism": lambda v: [0, 0, 1, 1, 2, 2, 0, 0, 1],
        "plane": lambda v: [0, 1, 2, 0, 1, 2],
        "sphere": lambda v: [0, 1, 2, 0],
        "cylinder": lambda v: _cyl_axes(v),
        "cone": lambda v: _cyl_axes(v, cone=True)}


def frame(axis, c1, c2):
    """A cylinder's or cone's axis: the origin (its point at 0 along the axis) and the
    direction."""
    o = [0.0, 0.0, 0.0]
    d1, d2, _ = _dims(axis)
    o[d1], o[d2] = c1, c2
    e = [0.0, 0.0, 0.0]
    e["xyz".index(axis)] = 1.0
    return o, e


# ---- profiles in (r, z) ----------------------------------------------------------------

def chains(points, faces, open_faces):
    """The runs of a closed outline's segments left when the open faces go: points
    [(r, z)], faces[k] the face number of segment k (points k to k + 1); zero-length
    segments dropped."""
    out, cur = [], []
    for k in range(len(points) - 1):
        p, q = points[k], points[k + 1]
        if faces[k] in open_faces or p == q:
            if len(cur) > 1:
                out.append(cur)
            cur = []
            continue
        if not cur:
            cur = [p]
        cur.append(q)
    if len(cur) > 1:
        out.append(cur)
    return out


def merge_collinear(pts):
    out = [pts[0]]
    for q in pts[1:]:
        if q == out[-1]:
            continue
        if len(out) >= 2:
            a, b = out[-2], out[-1]
            if abs((b[0] - a[0]) * (q[1] - b[1]) - (b[1] - a[1]) * (q[0] - b[0])) <= \
                    1e-14 * (abs(b[0] - a[0]) + abs(b[1] - a[1])) * \
                    (abs(q[0] - b[0]) + abs(q[1] - b[1])) and \
                    (b[0] - a[0]) * (q[0] - b[0]) + (b[1] - a[1]) * (q[1] - b[1]) > 0:
                out[-1] = q
                continue
        out.append(q)
    return out


def line_items(pts):
    return [("START",) + tuple(pts[0])] + [("LINE",) + tuple(p) for p in pts[1:]]


def profile_curvature(pts):
    """The curved faces of a polyline in (r, z): 'cyl' (r constant), 'cone', and the
    largest half-angle of the cones (degrees)."""
    kinds, beta = set(), 0.0
    for (r0, z0), (r1, z1) in zip(pts, pts[1:]):
        if z0 == z1:
            continue
        if r0 == r1:
            kinds.add("cyl")
        else:
            kinds.add("cone")
            beta = max(beta, math.degrees(math.atan2(abs(r1 - r0), abs(z1 - z0))))
    return kinds, beta


def revolutions(chain_list, origin, axis, two_sided, reverse):
    out = []
    for pts in chain_list:
        pts = merge_collinear(list(reversed(pts)) if reverse else pts)
        if len(pts) < 2:
            continue
        kinds, beta = profile_curvature(pts)
        out.append(Surf("revolution", origin=origin, axis=axis, items=line_items(pts),
                        two_sided=two_sided, curvature=kinds, beta=beta))
    return out


# ---- the styles --------------------------------------------------------------------

def cylinder_or_cone(reg, v, L):
    axis, c1, c2 = v[0], v[1], v[2]
    if reg.style == "cylinder":
        rlo = rhi = v[3]
        lo, hi = v[4], v[5]
    else:
        rlo, rhi, lo, hi = v[3], v[4], v[5], v[6]
        if abs(lo) >= BIG or abs(hi) >= BIG:
            raise Unmigratable("region %s: a cone with an INF end (LAMMPS interpolates its "
                               "radius between the ends)" % reg.id)
        if axis == "y" and not (1 in reg.open and 2 in reg.open):
            # region_cone.cpp sets delz, not dely, for a y cone's end caps
            raise Unmigratable("region %s: the end caps of LAMMPS's cone along y push "
                               "along z (RegCone::surface_interior sets delz for them): no "
                               "wall has that force; open faces 1 and 2, or turn the cone "
                               "to x or z" % reg.id)
    if hi <= lo:
        raise Unmigratable("region %s: its hi is not above its lo" % reg.id)
    origin, e = frame(axis, c1, c2)
    zlo, zhi = max(lo, -L), min(hi, L)
    rad = lambda z: rlo + (z - lo) * (rhi - rlo) / (hi - lo) if hi > lo else rlo  # noqa
    pts = [(0.0, zlo), (rad(zlo), zlo), (rad(zhi), zhi), (0.0, zhi)]
    faces = [1 if lo > -BIG else "inf", 3, 2 if hi < BIG else "inf"]
    opened = set(reg.open) | {"inf"}
    two = bool(reg.open)
    return revolutions(chains(pts, faces, opened), origin, e, two,
                       reverse=reg.side == "out" and not two)


def sphere(reg, v):
    x, y, z, R = v
    if R <= 0.0:
        raise Unmigratable("region %s: a sphere of radius 0" % reg.id)
    items = [("START", 0.0, -R), ("CIRCL", R, 0.0, 0.0, 0.0), ("CIRCL", 0.0, R, 0.0, 0.0)]
    two = bool(reg.open)
    if reg.side == "out" and not two:
        items = [("START", 0.0, R), ("CIRCL", R, 0.0, 0.0, 0.0),
                 ("CIRCL", 0.0, -R, 0.0, 0.0)]
    return [Surf("revolution", origin=[x, y, z], axis=[0.0, 0.0, 1.0], items=items,
                 two_sided=two, curvature={"sphere"})]


def plane(reg, v):
    p, n = v[:3], v[3:]
    if dot(n, n) == 0.0:
        raise Unmigratable("region %s: a plane without a normal" % reg.id)
    n = unit(n)
    two = bool(reg.open)
    if reg.side == "out" and not two:
        n = scale(n, -1.0)
    return [Surf("plane", point=p, normal=n, two_sided=two)]


# LAMMPS's block faces 1-6 (xlo xhi ylo yhi zlo zhi) as corner indices of the box
# (corner i: x from bit 0, y from bit 1, z from bit 2), each quad in cyclic order
BLOCK_FACES = {1: (0, 2, 6, 4), 2: (1, 3, 7, 5), 3: (0, 1, 5, 4), 4: (2, 3, 7, 6),
               5: (0, 1, 3, 2), 6: (4, 5, 7, 6)}


def polyhedron(reg, v, L):
    """A block or prism as triangles facing the region's side, without its open faces
    (and a block's INF faces)."""
    if reg.style == "block":
        lo = [max(v[0], -L), max(v[2], -L), max(v[4], -L)]
        hi = [min(v[1], L), min(v[3], L), min(v[5], L)]
        a, b, c = [hi[0] - lo[0], 0.0, 0.0], [0.0, hi[1] - lo[1], 0.0], \
            [0.0, 0.0, hi[2] - lo[2]]
        infinite = {k + 1 for k in range(6) if abs(v[k]) >= BIG}
    else:
        if any(abs(x) >= BIG for x in v[:6]):
            raise Unmigratable("region %s: a prism with an INF bound" % reg.id)
        lo = [v[0], v[2], v[4]]
        a, b, c = [v[1] - v[0], 0.0, 0.0], [v[6], v[3] - v[2], 0.0], \
            [v[7], v[8], v[5] - v[4]]
        infinite = set()
    if a[0] <= 0.0 or b[1] <= 0.0 or c[2] <= 0.0:
        raise Unmigratable("region %s: an empty %s" % (reg.id, reg.style))
    corners = [add(lo, add(scale(a, i & 1), add(scale(b, (i >> 1) & 1),
                                               scale(c, (i >> 2) & 1))))
               for i in range(8)]
    centre = scale([sum(p[d] for p in corners) for d in range(3)], 1.0 / 8.0)
    two = bool(reg.open)
    inward = reg.side == "in" or two
    tris = []
    for face, quad in sorted(BLOCK_FACES.items()):
        if face in reg.open or face in infinite:
            continue
        q = [corners[i] for i in quad]
        n = cross(sub(q[1], q[0]), sub(q[2], q[0]))
        if (dot(n, sub(centre, q[0])) > 0.0) != inward:
            q = list(reversed(q))
        tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    return [Surf("mesh", triangles=tris, two_sided=two)]


# ---- unions and intersections ------------------------------------------------------

def combined(reg, members, regions, ctx, number):
    """A union or intersect region's surfaces (members: its Region objects)."""
    flat = []
    for m in members:
        if m.move or m.rotate:
            raise Unmigratable("region %s: its member %s moves: the tool migrates unions "
                               "and intersections that stand still" % (reg.id, m.id))
        if m.open:
            raise Unmigratable("region %s: its member %s has open faces (LAMMPS's %s then "
                               "keeps contacts inside it)" % (reg.id, m.id, reg.style))
        if m.style == reg.style and m.side == "in":
            flat += combined(m, [regions[x] for x in m.members], regions, ctx, number)
            continue
        if m.style in ("union", "intersect", "block", "prism", "sphere"):
            raise Unmigratable("region %s: its member %s is a %s%s: the tool migrates "
                               "unions and intersections of coaxial cylinders, cones and "
                               "planes normal to their axis, or of planes normal to one "
                               "direction" % (reg.id, m.id, m.style,
                                              " with side out" if m.side == "out" else ""))
        flat.append((m, values(m, ctx, number)))
    return flat


def union_or_intersect(reg, regions, ctx, number):
    if reg.open:
        raise Unmigratable("region %s: a %s with open faces" % (reg.id, reg.style))
    subs = [regions[x] for x in reg.members]
    if all(m.open for m in subs):
        return open_members(reg, subs, regions, ctx, number)
    members = combined(reg, subs, regions, ctx, number)
    union = reg.style == "union"
    if all(m.style == "plane" for m, _ in members):
        return extrusion(reg, members, union, ctx.L)
    return coaxial(reg, members, union, ctx.L)


def open_members(reg, subs, regions, ctx, number):
    """A union or intersection whose members are all open: each member's faces, as its own
    two-sided surfaces. An open member matches every point (Region::match), so the union
    (intersection) holds every particle and keeps every member's contacts (RegUnion and
    RegIntersect::surface_interior drop a contact only inside a member that is not open):
    each member acts as it would alone, as each wall/rigid does."""
    if reg.side == "out":
        raise Unmigratable("region %s: a %s of open members with side out, which holds "
                           "no particle in LAMMPS (its members match every point)" % (
                               reg.id, reg.style))
    out = []
    for m in subs:
        if m.move or m.rotate:
            raise Unmigratable("region %s: its member %s moves: the tool migrates unions "
                               "and intersections that stand still" % (reg.id, m.id))
        out += surfaces(m, regions, ctx, number)
    return out


def coaxial(reg, members, union, L):
    """Coaxial cylinders and cones and planes normal to their axis: the radius R(z) of
    the union (largest) or intersection (smallest)."""
    axis_key, pieces, halves = None, [], []
    for m, v in members:
        if m.style == "plane":
            halves.append((m, v))
            continue
        key = (v[0], v[1], v[2])
        if axis_key is not None and key != axis_key:
            raise Unmigratable("region %s: its members %s do not share one axis (%s %g %g "
                               "and %s %g %g)" % (reg.id, m.id, axis_key[0], axis_key[1],
                                                  axis_key[2], key[0], key[1], key[2]))
        if m.side == "out":
            raise Unmigratable("region %s: its member %s has side out" % (reg.id, m.id))
        axis_key = key
        if m.style == "cylinder":
            rlo = rhi = v[3]
            lo, hi = v[4], v[5]
        else:
            rlo, rhi, lo, hi = v[3], v[4], v[5], v[6]
            if m.values[0] == "y":
                raise Unmigratable("region %s: its member %s is a cone along y, whose end "
                                   "caps LAMMPS pushes along z" % (reg.id, m.id))
        lo, hi = max(lo, -L), min(hi, L)
        pieces.append((lo, hi, rlo, (rhi - rlo) / (v[-1] - v[-2]) if v[-1] > v[-2] else 0.0,
                       v[-2]))
    if axis_key is None:
        raise Unmigratable("region %s: no cylinder or cone" % reg.id)
    origin, e = frame(*axis_key)
    k = "xyz".index(axis_key[0])
    for m, v in halves:
        n = unit(v[3:])
        if abs(abs(n[k]) - 1.0) > 1e-12:
            raise Unmigratable("region %s: its plane %s is not normal to the axis of its "
                               "cylinders and cones" % (reg.id, m.id))
        up = (n[k] > 0) == (m.side == "in")
        c = v[k]
        pieces.append((c, L, L, 0.0, c) if up else (-L, c, L, 0.0, c))
    rad = lambda p, z: p[2] + (z - p[4]) * p[3]  # noqa: E731
    cuts = sorted({p[0] for p in pieces} | {p[1] for p in pieces})
    for i, p in enumerate(pieces):
        for q in pieces[i + 1:]:
            if p[3] != q[3]:
                # where r = p2 + (z - p4) p3 and r = q2 + (z - q4) q3 cross
                cuts.append((q[2] - p[2] + p[3] * p[4] - q[3] * q[4]) / (p[3] - q[3]))
    lo_all = max(p[0] for p in pieces) if not union else min(p[0] for p in pieces)
    hi_all = min(p[1] for p in pieces) if not union else max(p[1] for p in pieces)
    cuts = sorted({z for z in cuts if lo_all <= z <= hi_all})
    pick = max if union else min
    out, cur = [], []
    for za, zb in zip(cuts, cuts[1:]):
        if zb <= za:
            continue
        act = [p for p in pieces if p[0] <= za and p[1] >= zb]
        if not union and len(act) < len(pieces):
            act = []
        if not act:
            if cur:
                cur.append((0.0, za))
                out.append(cur)
                cur = []
            continue
        ra, rb = pick(rad(p, za) for p in act), pick(rad(p, zb) for p in act)
        if not cur:
            cur = ([(0.0, za)] if za > -L else []) + [(ra, za)]
        elif cur[-1] != (ra, za):
            cur.append((ra, za))
        cur.append((rb, zb))
    if cur:
        if cur[-1][1] < L:
            cur.append((0.0, cur[-1][1]))
        out.append(cur)
    # a half-space's radius L is no face: the segments at r = L go
    out = [run for pts in out for run in chains(pts, [
        "far" if p[0] >= L and q[0] >= L else 0 for p, q in zip(pts, pts[1:])], {"far"})]
    if not out:
        raise Unmigratable("region %s: the %s is empty" % (reg.id, reg.style))
    return revolutions(out, origin, e, False, reverse=reg.side == "out")


def extrusion(reg, members, union, L):
    """Planes whose normals are normal to one direction d: the outline of their half-
    planes' intersection (a union: the complement's, reversed) in the plane normal to d,
    extruded along d."""
    normals = []
    for m, v in members:
        n = unit(v[3:])
        normals.append((m, v[:3], n if m.side == "in" else scale(n, -1.0)))
    d = None
    for _, _, n in normals:
        for _, _, q in normals:
            c = cross(n, q)
            if dot(c, c) > 1e-20:
                d = unit(c)
                break
        if d:
            break
    if d is None:   # parallel planes: any direction normal to them
        n = normals[0][2]
        t = [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0]
        d = unit(cross(n, t))
    for m, _, n in normals:
        if abs(dot(n, d)) > 1e-12:
            raise Unmigratable("region %s: its planes' normals are not all normal to one "
                               "direction (plane %s): their outline is no extruded profile"
                               % (reg.id, m.id))
    a = normals[0][1]
    xh = unit(cross(d, normals[0][2]))    # along the first plane's line
    yh = cross(d, xh)
    halfplanes = []
    for m, p, n in normals:
        nu, nv = dot(n, xh), dot(n, yh)
        c = dot(n, sub(p, a))
        halfplanes.append((-nu, -nv, -c) if union else (nu, nv, c))
    poly = [(-L, -L, True), (L, -L, True), (L, L, True), (-L, L, True)]
    for nu, nv, c in halfplanes:
        poly = clip(poly, nu, nv, c)
        if not poly:
            break
    if not poly:
        raise Unmigratable("region %s: the %s of its planes is %s" % (
            reg.id, reg.style, "everything" if union else "empty"))
    runs = edge_runs(poly)
    if not runs:
        raise Unmigratable("region %s: the %s of its planes has no face in the box" % (
            reg.id, reg.style))
    out = []
    b, c = add(a, xh), add(a, d)
    for pts in runs:
        if union:
            pts = list(reversed(pts))
        if reg.side == "out":
            pts = list(reversed(pts))
        out.append(Surf("extrusion", a=a, b=b, c=c, items=line_items(merge_collinear(pts))))
    return out


def clip(poly, nu, nv, c):
    """Sutherland-Hodgman: the part of the convex polygon [(u, v, box)] where
    nu u + nv v >= c; box tells whether the edge from that vertex lies on the box (no
    face) or on a plane (a face, as the new edge along the cut line is)."""
    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        fp, fq = nu * p[0] + nv * p[1] - c, nu * q[0] + nv * q[1] - c
        if fp >= 0.0:
            out.append(p)
        if (fp >= 0.0) != (fq >= 0.0):
            t = fp / (fp - fq)
            x = (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
            out.append((x[0], x[1], False if fp >= 0.0 else p[2]))
    return out


def edge_runs(poly):
    """The polygon's runs of real edges (not on the box), each as its points."""
    n = len(poly)
    real = [not poly[i][2] for i in range(n)]
    if all(real):
        pts = [(p[0], p[1]) for p in poly]
        return [pts + [pts[0]]]
    start = next(i for i in range(n) if not real[i])
    runs, cur = [], []
    for k in range(1, n + 1):
        i = (start + k) % n
        if real[i]:
            if not cur:
                cur = [(poly[i][0], poly[i][1])]
            j = (i + 1) % n
            cur.append((poly[j][0], poly[j][1]))
        elif cur:
            runs.append(cur)
            cur = []
    if cur:
        runs.append(cur)
    return runs


# ---- a region's surfaces -------------------------------------------------------------

def surfaces(reg, regions, ctx, number):
    """The region's wall/rigid surfaces in its pose as defined (before move and rotate)."""
    if reg.variable_shape():
        raise Unmigratable("region %s: its shape changes with %s: wall/rigid surfaces keep "
                           "their shape" % (reg.id, " ".join(reg.variable_shape())))
    if reg.style in ("union", "intersect"):
        return union_or_intersect(reg, regions, ctx, number)
    v = values(reg, ctx, number)
    if reg.style in ("cylinder", "cone"):
        return cylinder_or_cone(reg, v, ctx.L)
    if reg.style == "sphere":
        return sphere(reg, v)
    if reg.style == "plane":
        return plane(reg, v)
    return polyhedron(reg, v, ctx.L)


def place(surfs, P, theta, axis, D):
    """The surfaces turned by theta about the unit axis through P, then moved by D (a
    region's pose: Region::forward_transform)."""
    R = rotation(axis, theta)
    pt = lambda x: add(add(P, matvec(R, sub(x, P))), D)  # noqa: E731
    for s in surfs:
        if s.kind == "plane":
            s.point, s.normal = pt(s.point), matvec(R, s.normal)
        elif s.kind == "revolution":
            s.origin, s.axis = pt(s.origin), matvec(R, s.axis)
        elif s.kind == "extrusion":
            s.a, s.b, s.c = pt(s.a), pt(s.b), pt(s.c)
        else:
            s.triangles = [tuple(pt(p) for p in t) for t in s.triangles]
    return surfs
