#!/usr/bin/python3
"""Writes an ASCII STL cylinder about the z axis for the LIGGGHTS mesh-wall benchmark.

    make_stl.py OUT.stl RADIUS ZLO ZHI NTHETA NZ

2 * NTHETA * NZ triangles (200 x 10 gives 4000). The vertices sit on the circle of
radius RADIUS / cos(pi / NTHETA), so every facet's mid-line touches the circle of
radius RADIUS and no point of the mesh lies inside it. Facet normals point to the axis
(the side the particles are on); the node order follows them by the right-hand rule.
"""
import math
import sys


def main():
    if len(sys.argv) != 7:
        sys.exit(__doc__)
    out = sys.argv[1]
    radius, zlo, zhi = (float(v) for v in sys.argv[2:5])
    nth, nz = int(sys.argv[5]), int(sys.argv[6])
    if not (radius > 0 and zhi > zlo and nth >= 3 and nz >= 1):
        sys.exit("make_stl.py: need RADIUS > 0, ZHI > ZLO, NTHETA >= 3, NZ >= 1")
    rv = radius / math.cos(math.pi / nth)

    def p(i, k):
        a = 2 * math.pi * i / nth
        return (rv * math.cos(a), rv * math.sin(a), zlo + (zhi - zlo) * k / nz)

    with open(out, "w") as f:
        f.write("solid cylinder\n")
        for i in range(nth):
            am = 2 * math.pi * (i + 0.5) / nth
            n = (-math.cos(am), -math.sin(am), 0.0)
            for k in range(nz):
                a, b = p(i, k), p(i + 1, k)
                c, d = p(i + 1, k + 1), p(i, k + 1)
                # inward normal: going a -> d -> c is counter-clockwise seen from the axis
                for tri in ((a, d, c), (a, c, b)):
                    f.write("facet normal %.9g %.9g %.9g\n outer loop\n" % n)
                    for v in tri:
                        f.write("  vertex %.12g %.12g %.12g\n" % v)
                    f.write(" endloop\nendfacet\n")
        f.write("endsolid cylinder\n")


if __name__ == "__main__":
    main()
