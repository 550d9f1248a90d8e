#!/usr/bin/python3
"""surface_vel: a wall whose material moves in its tangent plane while its shape stays
(a conveyor belt), as LIGGGHTS's `fix mesh/surface ... surface_vel`.

- On an STL plate, our MESH wall with `surface_vel` is LIGGGHTS's mesh wall with the same
  surface_vel (hertz, tangential history): a sphere dropped on the belt is dragged along,
  positions, velocities and spins to 1e-9 relative at every output step.
- On an analytic plane, a sphere at rest on a belt moving at U slides with acceleration
  mu g until its contact point moves with the belt, at t = U / (3.5 mu g), then rolls at
  v = 2 U / 7 with omega_y = -5 U / (7 R) (closed forms of a solid sphere).
- The velocity's normal part is dropped and its tangential part scaled to |U| (LIGGGHTS's
  rule): U = (0.3, 0, 0.4) moves the plane's belt as U = (0.5, 0, 0).
- Bad values are rejected with an error naming the keyword.
"""
import math

import liglib as L
from test_mesh_wall import plate, stl

R, RHO, DT = 0.005, 2500.0, 1.0e-5
MU, G, U = 0.5, 9.81, 0.5
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}


def hertz_overlap():
    """Equilibrium overlap of the sphere under m g on the plane (liglib's materials)."""
    y = (5.0e7, 2.0e8)
    nu = (0.3, 0.25)
    ystar = 1.0 / ((1 - nu[0] ** 2) / y[0] + (1 - nu[1] ** 2) / y[1])
    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    return (3.0 * m * G / (4.0 * ystar * math.sqrt(R))) ** (2.0 / 3.0)


def body(s):
    ck = s.ck
    box = (-0.2, 0.2, -0.2, 0.2, -0.05, 0.3)
    # 1. the belt of an STL plate against LIGGGHTS's
    s.write("plate.stl", stl(plate(0.2, 4)))
    ours = ("fix w all wall/rigid surface inline mesh plate.stl law hertz type 2 "
            "surface_vel %r 0.1 0" % U)
    ref = ("fix plate all mesh/surface file plate.stl type 2 surface_vel %r 0.1 0\n"
           "fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes plate"
           % U)
    L.compare_walls(s, "belt_mesh", ours, ref,
                    L.sphere(1, (0.03, 0.07, R + 2e-4), R, RHO), 3000, True, "nve/sphere",
                    box, lambda f: f[-1][1][1]["vx"] > 0.05, DT, SCALES, 1e-9)

    # 2. an analytic plane: slip at mu g, then rolling at 2 U / 7
    floor = s.write("floor.inp", L.plane_z(0.0, half=1.0))
    h = hertz_overlap()
    atoms = L.sphere(1, (0.0, 0.0, R - h), R, RHO)
    t_stick = U / (3.5 * MU * G)

    def run_plane(tag, vel):
        wall = "fix w all wall/rigid surface %s law hertz type 2 surface_vel %s" % (
            floor, " ".join("%r" % v for v in vel))
        s.run(tag, L.sphere_wall_deck(wall, atoms, 6000, True, "nve/sphere", box, tag, DT))
        return L.read_dump(s.path(tag + ".dump"))

    fr = run_plane("belt_plane", (U, 0.0, 0.0))
    by_t = {step * DT: a[1] for step, a in fr}

    def at(t):
        return min(by_t, key=lambda x: abs(x - t))

    # the slope between 0.2 and 0.8 of the slip phase (hertz's tangential damping, like
    # LIGGGHTS's, gives the first step an extra kick that shifts vx by a constant)
    ta, tb = at(0.2 * t_stick), at(0.8 * t_stick)
    acc = (by_t[tb]["vx"] - by_t[ta]["vx"]) / (tb - ta)
    ck.check("slip phase: acceleration mu g", abs(acc - MU * G) <= 0.01 * MU * G,
             "%.6g between t = %.4g and %.4g s, closed form %.6g" % (acc, ta, tb, MU * G))
    last = fr[-1][1][1]
    ck.check("rolling on the belt: vx = 2 U / 7", abs(last["vx"] - 2 * U / 7) <= 0.01 * 2 * U / 7,
             "vx %.6g, closed form %.6g" % (last["vx"], 2 * U / 7))
    w_want = -5 * U / (7 * R)
    ck.check("rolling on the belt: omega_y = -5 U / (7 R)",
             abs(last["omegay"] - w_want) <= 0.01 * abs(w_want),
             "omega_y %.6g, closed form %.6g" % (last["omegay"], w_want))

    # 3. the normal part is dropped and the rest scaled to |U|
    fr2 = run_plane("belt_plane_tilted", (0.3, 0.0, 0.4))
    worst = L.compare_frames(fr, fr2, SCALES)
    ok = worst is not None and max(v[0] for v in worst.values()) <= 1e-12
    ck.check("U = (0.3, 0, 0.4) moves the plane's belt as (0.5, 0, 0)", ok,
             "" if worst is None else "worst %.3g" % max(v[0] for v in worst.values()))

    # 4. bad values
    for name, line, want in (
            ("surface_vel_missing", "surface_vel 1 2", ["surface_vel", "VX VY VZ"]),
            ("surface_vel_nan", "surface_vel nan 0 0", ["surface_vel", "nan"]),
            ("surface_vel_word", "surface_vel 1 fast 0", ["surface_vel", "fast"])):
        fix = "fix w all wall/rigid surface %s law hertz type 2 %s" % (floor, line)
        rc, out = s.run(name, L.one_sphere_deck(fix), expect_ok=False)
        L.check_rejected(ck, name, fix, want, rc, out)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
