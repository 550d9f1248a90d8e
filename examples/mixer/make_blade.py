#!/usr/bin/python3
"""Writes the mixer's blade as a binary STL: a shaft (a closed cylinder of radius 8 mm
along z) and two paddles (closed boxes, 70 x 30 x 6 mm, pitched 45 degrees about their
radial axis, so that turning they lift the bed), each face tessellated in cells of
about 1.5 mm, so the blade has more than 20000 triangles. Facet normals point out of
the solid parts, where the spheres are.

    make_blade.py OUT.stl [CELL]

CELL (m, default 0.0015) sets the facets' size: 0.0005 gives about 230000 triangles.
"""
import math
import struct
import sys

CELL = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0015


def box(c, ax, ay, az, hx, hy, hz):
    """The faces of the box centre c, half sizes h along unit axes a (right-handed),
    as grids of triangles with outward normals."""
    tris = []
    for n, u, v, hn, hu, hv in ((ax, ay, az, hx, hy, hz), (ay, az, ax, hy, hz, hx),
                                (az, ax, ay, hz, hx, hy)):
        nu = max(1, int(math.ceil(2 * hu / CELL)))
        nv = max(1, int(math.ceil(2 * hv / CELL)))
        for s in (1.0, -1.0):
            def p(i, j):
                a = -hu + 2 * hu * i / nu
                b = -hv + 2 * hv * j / nv
                return tuple(c[k] + s * hn * n[k] + a * u[k] + b * v[k] for k in range(3))
            for i in range(nu):
                for j in range(nv):
                    q = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1))
                    # u x v = n: counter-clockwise seen from +n; flipped on the -n face
                    t = [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
                    if s < 0:
                        t = [(a, cc, b) for a, b, cc in t]
                    tris += t
    return tris


def shaft(r, z0, z1, nth, nz):
    tris = []

    def p(i, z):
        a = 2 * math.pi * i / nth
        return (r * math.cos(a), r * math.sin(a), z)
    for k in range(nz):
        za, zb = z0 + (z1 - z0) * k / nz, z0 + (z1 - z0) * (k + 1) / nz
        for i in range(nth):
            a, b, c, d = p(i, za), p(i + 1, za), p(i + 1, zb), p(i, zb)
            tris += [(a, b, c), (a, c, d)]  # outward
    for i in range(nth):  # end caps
        tris.append(((0, 0, z0), p(i + 1, z0), p(i, z0)))
        tris.append(((0, 0, z1), p(i, z1), p(i + 1, z1)))
    return tris


def main():
    scale = 0.0015 / CELL
    tris = shaft(0.008, 0.004, 0.13, int(96 * scale), int(84 * scale))
    for k in range(2):
        phi = math.pi * k
        er = (math.cos(phi), math.sin(phi), 0.0)
        eh = (-math.sin(phi), math.cos(phi), 0.0)
        tilt = math.radians(45.0)
        # the paddle's height axis and thickness axis, turned 45 degrees about er
        ay = tuple(math.cos(tilt) * (0, 0, 1)[i] + math.sin(tilt) * eh[i] for i in range(3))
        az = (er[1] * ay[2] - er[2] * ay[1], er[2] * ay[0] - er[0] * ay[2],
              er[0] * ay[1] - er[1] * ay[0])  # er x ay: a right-handed box frame
        c = tuple(0.043 * er[i] + (0, 0, 0.016)[i] for i in range(3))
        tris += box(c, er, ay, az, 0.035, 0.015, 0.003)
    with open(sys.argv[1], "wb") as f:
        f.write(b"mixer blade: shaft and two pitched paddles".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<12fH", 0, 0, 0, *t[0], *t[1], *t[2], 0))
    print("%s: %d triangles" % (sys.argv[1], len(tris)))


if __name__ == "__main__":
    main()
