#!/usr/bin/python3
"""law liggghts on a moving wall: the model gets the wall's velocity at the contact.

LIGGGHTS gives its model the mesh's velocity at the contact point (the nodes'
velocities interpolated there, exact for a rigid motion); wall/rigid gives it its
motion's velocity at the master point. Reference: the same STL plate as `fix
mesh/surface` with `fix wall/gran ... mesh` and `fix move/mesh`, in the same executable.
A sphere (rolling friction epsd2, cohesion sjkr) lands on the plate while it turns about
z (it is carried round, sliding, then sticking) or while it translates in its plane
(dragged along), and stays on one triangle of the two (in the plate's frame).
Trajectories equal LIGGGHTS's to 1e-9 relative on the translating plate and to 1e-8 on
the turning one (measured 1.9e-9 there, in vz during the bounces): the turning wall's
pose and velocity are computed two ways (LIGGGHTS turns its nodes and interpolates
their velocities; rigidsurf evaluates its pose and its velocity at the contact), and a
rounding difference of 1e-16 m in a height is 1e-10 of an overlap of 1e-6 m, which the
bounces and the stick-slip grow. A control run of the turning case
with the wall kept still differs from the reference by more than 1e-3: the motion
reaches the model.
"""
import math

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
MODEL = "model hertz tangential history cohesion sjkr rolling_friction epsd2"
PROPS = ("fix m5 all property/global coefficientRollingFriction peratomtypepair 2 "
         "0.05 0.05 0.05 0.05\n"
         "fix m6 all property/global cohesionEnergyDensity peratomtypepair 2 "
         "2e4 2e4 2e4 2e4\n")
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.1)
PERIOD = 0.5
MOTIONS = {  # LIGGGHTS's move/mesh, wall/rigid's motion, tolerance, angular speed
    "turning": ("rotate origin 0 0 0 axis 0 0 1 period %r" % PERIOD,
                "rotate origin 0 0 0 axis 0 0 1 period %r" % PERIOD, 1e-8,
                2 * math.pi / PERIOD),
    "translating": ("linear 0.05 0.02 0", "move linear 0.05 0.02 0", 1e-9, 0.0),
}


def plate(s, half=0.05):
    tris = [((-half, -half, 0.0), (half, -half, 0.0), (half, half, 0.0)),
            ((-half, -half, 0.0), (half, half, 0.0), (-half, half, 0.0))]
    s.write("plate.stl", L.stl_text(tris, "plate"))


def deck(ours, lig, steps, tag, still=False):
    if ours:
        wall = ("fix w all wall/rigid surface inline mesh plate.stl law liggghts %s type 2"
                % MODEL) + ("" if still else " " + lig[1])
    else:
        wall = ("fix plate all mesh/surface file plate.stl type 2\n"
                "fix w all wall/gran %s mesh n_meshes 1 meshes plate\n"
                "fix mv all move/mesh mesh plate %s" % (MODEL, lig[0]))
    atoms = L.sphere(1, (0.02, -0.008, R + 2e-4), R, RHO, v=(0.0, 0.0, -0.2))
    return L.sphere_wall_deck(wall, atoms, steps, True, "nve/sphere", BOX, tag, DT, PROPS,
                              {"ntypes": 2})


def body(s):
    plate(s)
    for name, lig in MOTIONS.items():
        steps = 20000
        for ours, tag in ((False, name + "_gran"), (True, name + "_rigid")):
            s.run(tag, deck(ours, lig, steps, tag))
        fa = L.read_dump(s.path(name + "_rigid.dump"))
        fb = L.read_dump(s.path(name + "_gran.dump"))
        last = fb[-1][1][1]
        s.ck.check(name + ": the sphere rests on the plate at the end, carried along",
                   abs(last["z"] - R) < 0.01 * R and
                   (last["vx"] ** 2 + last["vy"] ** 2) ** 0.5 > 0.01,
                   "z %.6g, v (%.3g, %.3g)" % (last["z"], last["vx"], last["vy"]))
        # the centre in the plate's frame: turned back by the plate's angle, less its
        # translation; on the triangle y < x, away from the diagonal
        def plate_xy(step, a):
            th = lig[3] * step * DT
            x, y = a["x"], a["y"]
            if not lig[3]:
                x, y = x - 0.05 * step * DT, y - 0.02 * step * DT
            return (x * math.cos(th) + y * math.sin(th), -x * math.sin(th) + y * math.cos(th))
        gap = min(px - py for px, py in (plate_xy(st, f[1]) for st, f in fb))
        s.ck.check(name + ": it stays on one triangle (y < x in the plate's frame)",
                   gap > 0.5 * R, "closest approach to the diagonal %.3g" % gap)
        L.check_trajectories(s, name, fa, fb, SCALES, lig[2])
        if name == "turning":
            s.run("still_rigid", deck(True, lig, steps, "still_rigid", still=True))
            fc = L.read_dump(s.path("still_rigid.dump"))
            worst = L.compare_frames(fc, fb, SCALES)
            d = max(v[0] for v in worst.values()) if worst else float("inf")
            s.ck.check("control: with the wall kept still the run differs by > 1e-3",
                       d > 1e-3, "%.3g" % d)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
