"""VUINTER's facet arguments on a faceted master (tests/liggghts/routines/
vuinter_facets.f reports them through XPLB_ABQERR).

An Abaqus rigid part, one R3D4 and one R3D3 element (nodes 11-15), slides along x under
two spheres that rest on it at their equilibrium overlap (a penalty normal law, no
shear). On increments 1 and N each contact reports nFacNod = 4 (the part has a quad; the
triangle is padded with its first node), nMstNod = 5 (the block's distinct nodes), and
per facet node its label, its shape function at the contact point and its current
coordinates. Expected, in closed form: the labels in element order, the unit square's
bilinear functions and the triangle's barycentric coordinates at the sphere's position
relative to the part, and the nodes moved by v t. On an analytic plane the same routine
sees nFacNod = nMstNod = 0.
"""
import math
import os
import re

import liglib

HERE = os.path.dirname(os.path.abspath(__file__))
ROUTINE = os.path.join(HERE, "routines", "vuinter_facets.f")

R, RHO, G, K = 0.005, 2500.0, 9.81, 2.0e4
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
H = MASS * G / K
DT, V, N = 1e-5, 0.01, 400
NODES = {11: (0.0, 0.0), 12: (0.02, 0.0), 13: (0.02, 0.02), 14: (0.0, 0.02), 15: (0.04, 0.01)}
PART = ("*SURFACE, TYPE=MESH, NAME=plate\n*NODE\n"
        + "".join("%d, %r, %r, 0\n" % (k, x, y) for k, (x, y) in sorted(NODES.items()))
        + "*ELEMENT, TYPE=R3D4\n1, 11, 12, 13, 14\n*ELEMENT, TYPE=R3D3\n2, 12, 15, 13\n")
SPHERES = {1: (0.007, 0.012), 2: (0.026, 0.01)}


def expected(tag, shift):
    """(labels, shapes) of the facet under sphere tag, the part moved by shift along x."""
    x, y = SPHERES[tag]
    x -= shift
    if tag == 1:  # the unit square [0, 0.02]^2, nodes 11 12 13 14
        u, v = x / 0.02, y / 0.02
        return [11, 12, 13, 14], [(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v]
    # the triangle 12 15 13, padded with its first node
    (x1, y1), (x2, y2), (x3, y3) = NODES[12], NODES[15], NODES[13]
    det = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1)
    l2 = ((x - x1) * (y3 - y1) - (x3 - x1) * (y - y1)) / det
    l3 = ((x2 - x1) * (y - y1) - (x - x1) * (y2 - y1)) / det
    return [12, 15, 13, 12], [1 - l2 - l3, l2, l3, 0.0]


def deck(s, surf_line):
    text = liglib.header((-0.05, 0.08, -0.05, 0.05, -0.01, 0.05), DT)
    for tag, (x, y) in sorted(SPHERES.items()):
        text += liglib.sphere(tag, (x, y, R - H), R, RHO)
    text += ("fix grav all gravity %r vector 0 0 -1\n" % G
             + surf_line
             + "fix integr all nve/sphere\n"
             + "run %d\n" % N)
    return text


def body(s):
    ck = s.ck
    os.environ["RIGIDSURF_CACHE"] = s.path("cache")
    s.write("plate.inp", PART)
    rc, out = s.run("facets", deck(s, "fix w all wall/rigid surface plate.inp law vuinter %s "
                                   "props %r %d move linear %r 0 0\n" % (ROUTINE, K, N, V)))
    facet = {}
    nodes = {}
    for m in re.finditer(r"\(XPLB_ABQERR\): facet (\d+) (\d+) (\d+) (\d+)", out):
        facet[(int(m.group(1)), int(m.group(2)))] = (int(m.group(3)), int(m.group(4)))
    pat = (r"\(XPLB_ABQERR\): node (\d+) (\d+) (\d+) label (\d+) shape (\S+) at (\S+) (\S+) "
           r"(\S+)")
    for m in re.finditer(pat, out):
        key = (int(m.group(1)), int(m.group(2)), int(m.group(3)))
        nodes[key] = (int(m.group(4)),) + tuple(float(m.group(i)) for i in range(5, 9))
    for tag in SPHERES:
        for kinc in (1, N):
            got = facet.get((tag, kinc))
            ck.check("sphere %d, increment %d: nFacNod 4, nMstNod 5" % (tag, kinc),
                     got == (4, 5), "reported %s" % (got,))
            shift = V * kinc * DT
            labels, shapes = expected(tag, shift)
            worst_shape = worst_xyz = 0.0
            ok_labels = True
            for i in range(4):
                row = nodes.get((tag, kinc, i + 1))
                if row is None:
                    ok_labels = False
                    continue
                ok_labels &= row[0] == labels[i]
                worst_shape = max(worst_shape, abs(row[1] - shapes[i]))
                x0, y0 = NODES[labels[i]]
                worst_xyz = max(worst_xyz, abs(row[2] - (x0 + shift)), abs(row[3] - y0),
                                abs(row[4]))
            ck.check("sphere %d, increment %d: labels %s" % (tag, kinc, labels), ok_labels,
                     str([nodes.get((tag, kinc, i + 1), (None,))[0] for i in range(4)]))
            ck.check("sphere %d, increment %d: shape functions" % (tag, kinc),
                     worst_shape < 1e-9, "largest error %.3g" % worst_shape)
            ck.check("sphere %d, increment %d: node coordinates moved by v t" % (tag, kinc),
                     worst_xyz < 1e-12, "largest error %.3g" % worst_xyz)

    surf = s.write("floor.inp", liglib.plane_z(0.0, half=1.0))
    rc, out = s.run("analytic", deck(s, "fix w all wall/rigid surface %s law vuinter %s "
                                     "props %r %d\n" % (surf, ROUTINE, K, N)))
    got = re.findall(r"\(XPLB_ABQERR\): facet 1 1 (\d+) (\d+)", out)
    ck.check("analytic master: nFacNod 0, nMstNod 0", got[:1] == [("0", "0")], str(got))


liglib.main_guard(liglib.Session(__doc__), body)
