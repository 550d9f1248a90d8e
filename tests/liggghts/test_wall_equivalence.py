#!/usr/bin/python3
"""fix wall/rigid with law hertz or hooke reproduces LIGGGHTS's own primitive walls.

Pins: our CYLINDER plane (one LINE, n = +z) is the Hertz wall of `fix wall/gran model
hertz tangential history primitive zplane 0`, and the inside of our REVOLUTION drum is
`primitive zcylinder`; spheres sliding then rolling around the inside of the drum on
held contacts give the same trajectories as on the drum whose mantle is two collinear
LINEs (the per-sphere path of a revolved LINE against the block query); law hooke without props, from the same material properties and
characteristicVelocity, is `fix wall/gran model hooke tangential history` on the plane. The answer is LIGGGHTS's wall in the same deck, same executable;
positions, velocities and spins agree to 1e-9 relative at every output step, with the
default tracking thickness and with `tracking 0`.
"""
import math

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
TOL = 1e-9
# Initial gaps are not a whole number of steps of travel, so no run starts a contact
# on an exact tie (overlap 0 to round-off), which would test rounding, not the law.
GAP = 2.13e-4
# Scales below which a difference is judged absolutely: a quantity that crosses zero is
# compared against its natural size (radius for positions, 1 m/s, 1 m/s / R for spin).
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}


# LIGGGHTS's hooke model takes its stiffness from this velocity (m/s); hertz ignores it.
CHARVEL = "fix m5 all property/global characteristicVelocity scalar 0.8\n"


def compare(s, name, ours, ref, atoms, steps, gravity, integrator, box, bounced):
    L.compare_walls(s, name, ours, ref, atoms, steps, gravity, integrator, box, bounced,
                    DT, SCALES, TOL, extra_props=CHARVEL, ref_tag="gran")


def body(s):
    s.write("plane.inp", L.plane_z(0.0, 1.0))
    ours = "fix w all wall/rigid surface plane.inp law hertz type 2"
    ref = "fix w all wall/gran model hertz tangential history primitive type 2 zplane 0"
    box = (-0.2, 0.2, -0.2, 0.2, -0.05, 0.3)

    def vz_flips(frames):
        return any(a[1]["vz"] > 0 for _, a in frames) and frames[0][1][1]["vz"] < 0

    # 1. normal impact at 1 m/s, no gravity.
    compare(s, "normal_impact", ours, ref,
            L.sphere(1, (0, 0, R + GAP), R, RHO, v=(0, 0, -1.0)),
            400, False, "nve/sphere", box, vz_flips)
    # 2. oblique impact with spin, under gravity: the tangential history and the
    #    contact-point lever arm (R - delta/2) both matter.
    oblique = L.sphere(1, (0, 0, R + GAP), R, RHO, v=(0.6, -0.3, -1.0),
                       omega=(40.0, -90.0, 25.0))
    compare(s, "oblique_spin", ours, ref, oblique,
            600, True, "nve/sphere", box, vz_flips)
    # 2b. the same with tracking 0: the contact is made when the sphere touches, not
    #     when it enters the skin; hertz's force is the same (docs: "Cost of the
    #     tracking thickness").
    compare(s, "oblique_spin_tracking0", ours + " tracking 0", ref, oblique,
            600, True, "nve/sphere", box, vz_flips)

    # 3. slide to rest: starts touching with 0.5 m/s, spin frozen (fix nve), so friction
    #    stops it; then the tangential spring rings down. Also a closed form: the sliding
    #    distance is v0^2 / (2 mu g) with mu = 0.5 (up to the overlap settling).
    def stopped(frames):
        return abs(frames[-1][1][1]["vx"]) < 1e-3
    compare(s, "slide_to_rest", ours, ref,
            L.sphere(1, (0, 0, R), R, RHO, v=(0.5, 0, 0)),
            20000, True, "nve", box, stopped)
    fr = L.read_dump(s.path("slide_to_rest_rigid.dump"))
    dist = fr[-1][1][1]["x"]
    want = 0.5 ** 2 / (2 * 0.5 * 9.81)
    s.ck.check("slide_to_rest: distance v0^2/(2 mu g) within 1%",
               abs(dist - want) <= 0.01 * want, "%.6g vs %.6g" % (dist, want))
    # 4. slide then roll (spin free): the rolling speed is 5/7 v0 once slip stops.
    compare(s, "slide_to_roll", ours, ref,
            L.sphere(1, (0, 0, R), R, RHO, v=(0.5, 0, 0)),
            6000, True, "nve/sphere", box, lambda f: f[-1][1][1]["omegay"] > 0)
    fr = L.read_dump(s.path("slide_to_roll_rigid.dump"))
    vx = fr[-1][1][1]["vx"]
    s.ck.check("slide_to_roll: rolling speed 5/7 v0 within 1%",
               abs(vx - 5.0 / 7.0 * 0.5) <= 0.01 * 0.5 * 5 / 7, "%.6g" % vx)

    # 5. normal impacts on the inside of a drum of radius 0.05 about z, three directions
    #    at three heights (the spheres never meet), 1 m/s radially outward.
    RC = 0.05
    s.write("drum.inp", L.drum(RC, -0.2, 0.2))
    ours = "fix w all wall/rigid surface drum.inp law hertz type 2"
    ref = "fix w all wall/gran model hertz tangential history primitive type 2 zcylinder %r 0 0" % RC
    atoms = ""
    for k, (ang, z) in enumerate(((0.0, -0.03), (30.0, 0.0), (135.0, 0.03))):
        c, sn = math.cos(math.radians(ang)), math.sin(math.radians(ang))
        r0 = RC - R - GAP
        atoms += L.sphere(k + 1, (r0 * c, r0 * sn, z), R, RHO, v=(c, sn, 0.0))

    def all_back(frames):
        last = frames[-1][1]
        return all(a["vx"] * a["x"] + a["vy"] * a["y"] < 0 for a in last.values())
    compare(s, "drum_normal_impacts", ours, ref, atoms, 500, False, "nve/sphere",
            (-0.06, 0.06, -0.06, 0.06, -0.06, 0.06), all_back)

    # 5b. held contacts for thousands of steps: without gravity, spheres sent along the
    #     inside of the drum at 1.2 m/s (and a little outward) stay pressed against it,
    #     slide, then roll around it, so that the per-sphere path for a held face contact
    #     on a revolved LINE (the wall's line path) carries the contact almost the whole run. The
    #     answer is the same drum whose mantle is two collinear LINEs: a profile of more
    #     than one segment takes the block query and the staged stages, and the sphere at
    #     z = 0 crosses the joint (its history handed over between the faces).
    atoms = ""
    for k, (ang, z, vz) in enumerate(((10.0, -0.03, 0.0), (100.0, 0.0, 0.2),
                                      (250.0, 0.03, -0.1))):
        c, sn = math.cos(math.radians(ang)), math.sin(math.radians(ang))
        r0 = RC - R - GAP
        atoms += L.sphere(k + 1, (r0 * c, r0 * sn, z), R, RHO,
                          v=(0.05 * c - 1.2 * sn, 0.05 * sn + 1.2 * c, vz))

    def on_mantle(frames):
        last = frames[-1][1]
        return all(math.hypot(a["x"], a["y"]) > RC - R - 1e-4 for a in last.values())
    s.write("drum_split.inp",
            "*SURFACE, TYPE=REVOLUTION, NAME=mantle\n0, 0, 0, 0, 0, 1\n"
            "START, %r, -0.2\nLINE, %r, 0.0\nLINE, %r, 0.2\n" % (RC, RC, RC))
    L.compare_walls(s, "drum_rolling", ours,
                    "fix w all wall/rigid surface drum_split.inp law hertz type 2", atoms,
                    6000, False, "nve/sphere", (-0.06, 0.06, -0.06, 0.06, -0.06, 0.06),
                    on_mantle, DT, SCALES, TOL, ref_tag="split")
    fr = L.read_dump(s.path("drum_rolling_rigid.dump"))
    s.ck.check("drum_rolling: the spheres roll on the mantle at the end (|omega_z| > 0)",
               all(abs(a["omegaz"]) > 1.0 for a in fr[-1][1].values()),
               str([a["omegaz"] for a in fr[-1][1].values()]))

    # 6. law hooke without props: LIGGGHTS's hooke from the material properties and
    #    characteristicVelocity, normal and oblique impacts and a slide to roll. The slide
    #    starts 0.1 um above the plane, not on it: at exactly zero overlap LIGGGHTS's
    #    primitive wall counts a contact and applies hooke's tangential damping
    #    (0.8 N here), where rigidsurf's laws act on overlaps > 0 only; hertz's damping
    #    vanishes there, so the hertz slides above start on the plane.
    ours = "fix w all wall/rigid surface plane.inp law hooke type 2"
    ref = "fix w all wall/gran model hooke tangential history primitive type 2 zplane 0"
    compare(s, "hooke_normal_impact", ours, ref,
            L.sphere(1, (0, 0, R + GAP), R, RHO, v=(0, 0, -1.0)),
            400, False, "nve/sphere", box, vz_flips)
    compare(s, "hooke_oblique_spin", ours, ref, oblique, 600, True, "nve/sphere", box,
            vz_flips)
    compare(s, "hooke_slide_to_roll", ours, ref,
            L.sphere(1, (0, 0, R + 1e-7), R, RHO, v=(0.5, 0, 0)),
            6000, True, "nve/sphere", box, lambda f: f[-1][1][1]["omegay"] > 0)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
