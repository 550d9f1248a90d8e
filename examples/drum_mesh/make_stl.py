#!/usr/bin/python3
"""Writes the drum of examples/drum/drum.inp tessellated, as a binary STL.

The profile in (r, z): the back cap from the axis, a 4 mm fillet, the mantle (r = 50 mm),
a 4 mm fillet and the front cap back to the axis, with the normal inward. Lines are cut
in pieces of at most DS, each fillet in NARC arcs (chords), and the profile is revolved
in NHOOP steps. Each step of a piece is a planar quad (two triangles, wound so that
their normals point inward, where the spheres are); at the axis, one triangle.

    make_stl.py OUT.stl [NHOOP [NARC [DS]]]
"""
import math
import struct
import sys

R, H, RF = 0.05, 0.012, 0.004


def profile(narc, ds):
    pts = []

    def line(a, b):
        n = max(1, int(math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) / ds)))
        for k in range(n):
            pts.append((a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n))

    def arc(c, a0, a1):
        for k in range(narc):
            a = a0 + (a1 - a0) * k / narc
            pts.append((c[0] + RF * math.cos(a), c[1] + RF * math.sin(a)))

    line((0.0, -H), (R - RF, -H))
    arc((R - RF, -H + RF), -math.pi / 2, 0.0)
    line((R, -H + RF), (R, H - RF))
    arc((R - RF, H - RF), 0.0, math.pi / 2)
    line((R - RF, H), (0.0, H))
    pts.append((0.0, H))
    return pts


def main():
    out = sys.argv[1]
    nhoop = int(sys.argv[2]) if len(sys.argv) > 2 else 180
    narc = int(sys.argv[3]) if len(sys.argv) > 3 else 8
    ds = float(sys.argv[4]) if len(sys.argv) > 4 else 0.005
    prof = profile(narc, ds)

    def p3(rz, j):
        a = 2 * math.pi * j / nhoop
        return (rz[0] * math.cos(a), rz[0] * math.sin(a), rz[1])

    tris = []
    for i in range(len(prof) - 1):
        a, b = prof[i], prof[i + 1]
        for j in range(nhoop):
            # the quad (a_j, b_j, b_j+1, a_j+1): its normal (b - a) x hoop points to the
            # left of the profile's travel, inward, as drum.inp's does
            qa, qb = p3(a, j), p3(b, j)
            qc, qd = p3(b, j + 1), p3(a, j + 1)
            if a[0] == 0.0:
                tris.append((qa, qb, qc))
            elif b[0] == 0.0:
                tris.append((qa, qb, qd))
            else:
                tris += [(qa, qb, qc), (qa, qc, qd)]
    with open(out, "wb") as f:
        f.write(b"drum_mesh: examples/drum/drum.inp tessellated".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<12fH", 0, 0, 0, *t[0], *t[1], *t[2], 0))
    print("%s: %d triangles (%d profile pieces x %d hoop steps)"
          % (out, len(tris), len(prof) - 1, nhoop))


if __name__ == "__main__":
    main()
