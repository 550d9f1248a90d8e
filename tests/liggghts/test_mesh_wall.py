#!/usr/bin/python3
"""fix wall/rigid on a MESH surface reproduces LIGGGHTS's own walls.

Pins: on a face interior, our MESH wall (an STL plate of 32 triangles, law hertz) is
`fix mesh/surface` + `fix wall/gran model hertz tangential history mesh` on the same STL,
for a normal and an oblique, spinning impact; a sphere dropped exactly on the vertex
that six coplanar triangles share rebounds as on LIGGGHTS's primitive plane (one
contact, not six); and a sphere sliding across the plate's flat edges hands its history
over, so its trajectory is the primitive plane's; and a fast impact between neighbour
builds that LIGGGHTS delays finds the plate in time. Positions, velocities and spins
agree to 1e-9 relative at every output step.
"""
import math

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
TOL = 1e-9
GAP = 2.13e-4
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}


def stl(tris, name="part"):
    out = ["solid %s" % name]
    for a, b, c in tris:
        out.append(" facet normal 0 0 0\n  outer loop")
        for p in (a, b, c):
            out.append("   vertex %.17g %.17g %.17g" % p)
        out.append("  endloop\n endfacet")
    out.append("endsolid %s" % name)
    return "\n".join(out) + "\n"


def plate(half, n):
    """The square [-half, half]^2 at z = 0 as n x n cells of two triangles, normal +z."""
    h = 2.0 * half / n
    tris = []
    for i in range(n):
        for j in range(n):
            x0, y0 = -half + i * h, -half + j * h
            a, b, c, d = (x0, y0, 0.0), (x0 + h, y0, 0.0), (x0 + h, y0 + h, 0.0), (x0, y0 + h, 0.0)
            tris += [(a, b, c), (a, c, d)]
    return tris


def fan(radius):
    """Six triangles around the origin, normal +z."""
    o = (0.0, 0.0, 0.0)
    p = [(radius * math.cos(k * math.pi / 3), radius * math.sin(k * math.pi / 3), 0.0)
         for k in range(6)]
    return [(o, p[k], p[(k + 1) % 6]) for k in range(6)]


def compare(s, name, ours, ref, atoms, steps, gravity, integrator, box, touched,
            extra_props=""):
    L.compare_walls(s, name, ours, ref, atoms, steps, gravity, integrator, box, touched,
                    DT, SCALES, TOL, extra_props)


def body(s):
    s.write("plate.stl", stl(plate(0.2, 4)))
    s.write("fan.stl", stl(fan(0.1)))
    box = (-0.2, 0.2, -0.2, 0.2, -0.05, 0.3)
    ours = "fix w all wall/rigid surface inline mesh plate.stl law hertz type 2"
    ref = ("fix plate all mesh/surface file plate.stl type 2\n"
           "fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes plate")

    def vz_flips(frames):
        return any(a[1]["vz"] > 0 for _, a in frames) and frames[0][1][1]["vz"] < 0

    # 1. normal impact on a face interior, 1 m/s, no gravity
    compare(s, "mesh_normal_impact", ours, ref,
            L.sphere(1, (0.03, 0.07, R + GAP), R, RHO, v=(0, 0, -1.0)),
            400, False, "nve/sphere", box, vz_flips)
    # 2. oblique impact with spin under gravity, on a face interior
    compare(s, "mesh_oblique_spin", ours, ref,
            L.sphere(1, (0.03, 0.07, R + GAP), R, RHO, v=(0.6, -0.3, -1.0),
                     omega=(40.0, -90.0, 25.0)),
            600, True, "nve/sphere", box, vz_flips)
    # 3. dropped exactly on the vertex of six coplanar triangles: the primitive plane
    prim = "fix w all wall/gran model hertz tangential history primitive type 2 zplane 0"
    compare(s, "fan_vertex_drop",
            "fix w all wall/rigid surface inline mesh fan.stl law hertz type 2", prim,
            L.sphere(1, (0.0, 0.0, R + GAP), R, RHO, v=(0, 0, -1.0)),
            400, False, "nve/sphere", box, vz_flips)
    # 4. slide then roll across the plate's flat edges (the grid line x = 0 after 2 mm,
    #    then the diagonal y = x of the next cell after about 8 mm): history passes at
    #    every edge
    compare(s, "mesh_slide_across_edges", ours, prim,
            L.sphere(1, (-0.002, 0.005, R), R, RHO, v=(0.5, 0.2, 0)),
            6000, True, "nve/sphere", box, lambda f: f[-1][1][1]["omegay"] > 0)
    # 5. a fast impact under LIGGGHTS's default delay between neighbour builds (skin
    #    0.5 mm, builds at most every 10 steps, 0.375 mm apart): the last build before
    #    the impact finds the sphere 0.3 mm above the plate, more than half the skin, and
    #    the next comes after it touched. Its candidate lists must reach a whole skin.
    compare(s, "mesh_impact_delayed_builds", ours, prim,
            L.sphere(1, (0.03, 0.07, R + 0.0003 + 3 * 0.000375), R, RHO, v=(0, 0, -3.75)),
            400, False, "nve/sphere", box, vz_flips,
            extra_props="neighbor 0.0005 bin\nneigh_modify delay 10\n")
    fr = L.read_dump(s.path("mesh_slide_across_edges_rigid.dump"))
    x, y = fr[-1][1][1]["x"], fr[-1][1][1]["y"]
    s.ck.check("mesh_slide_across_edges: the sphere crossed x = 0 and y = x", x > 0 and y < x,
               "ends at (%.4g, %.4g)" % (x, y))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
