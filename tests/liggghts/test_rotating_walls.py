#!/usr/bin/python3
"""Rotating walls: the wall velocity seen by a sphere is Omega x (x - origin).

1. Drum mantle (wall normal perpendicular to the axis). A sphere that cannot spin (fix
   nve) rests at the bottom of a drum turning slowly (0.5 rad/s) about z, gravity -y.
   The mantle carries it up until friction can no longer hold it and then slides
   beneath it. While the mantle slides, friction is mu times the normal force whatever
   the sphere does, so the sphere swings like a pendulum (undamped, amplitude ~ wall
   speed / pendulum frequency ~ 2 degrees) about the angle where gravity's tangential
   part equals mu times its normal part: atan(mu) from the bottom. The centre of the
   swing (mid-point of its extremes over the last 0.5 s, more than one period) is
   checked against atan(mu) within 0.3 degree for mu = 0.3 and 0.6, with the sense of
   rotation.
2. End disc (wall normal parallel to the axis): the plane z = 0 facing +z turns at
   5 rad/s about the axis through o = (0.01, 0.005, 0). Spheres (fix nve) dropped at
   rest on it:
   - start moving along Omega x (x - o): the first velocity picked up is within 0.5
     degree of that direction;
   - an inner sphere (Omega^2 r = 0.1 m/s2 < mu g) sticks and turns with the disc:
     v = Omega x (x - o) within 1e-3 of Omega r, and its distance from the axis holds
     to 0.2 mm;
   - an outer sphere (Omega^2 r = 3.75 m/s2 > mu g = 2.94 m/s2) cannot be held and slides
     outward.
"""
import math

import liglib as L

R, RHO = 0.004, 2500.0


def drum_case(s, mu):
    RC, W, DT, STEPS = 0.05, 0.5, 2.0e-5, 80000
    tag = "drum_mu%02d" % round(10 * mu)
    d = L.header((-0.06, 0.06, -0.06, 0.06, -0.05, 0.05), DT, mu=mu)
    d += L.sphere(1, (0, -(RC - R + 1e-5), 0), R, RHO)
    d += "fix grav all gravity 9.81 vector 0 -1 0\n"
    d += ("fix w all wall/rigid surface drum.inp law hertz type 2 "
          "rotate origin 0 0 0 axis 0 0 1 omega %r\n" % W)
    d += "fix integr all nve\n"
    d += L.dump_lines("d", 200, tag + ".dump")
    d += "run %d\n" % STEPS
    s.run(tag, d)
    fr = L.read_dump(s.path(tag + ".dump"))
    # angle from the bottom, positive toward +x: the mantle at the bottom moves along
    # Omega z x (-y) = +x for Omega > 0.
    angs = [math.degrees(math.atan2(a[1]["x"], -a[1]["y"])) for _, a in fr]
    tail = angs[-(int(0.5 / DT) // 200):]
    mid = 0.5 * (max(tail) + min(tail))
    want = math.degrees(math.atan(mu))
    s.ck.check(tag + ": carried up on the +x side (sense of Omega x r)", min(tail) > 0,
               "min %.3f deg" % min(tail))
    s.ck.check(tag + ": swings about atan(mu) = %.3f deg within 0.3 deg" % want,
               abs(mid - want) <= 0.3, "centre %.4f deg, swing %.4f deg"
               % (mid, max(tail) - min(tail)))


def disc_case(s):
    W, MU, DT, STEPS = 5.0, 0.3, 1.0e-5, 40000
    o = (0.01, 0.005, 0.0)
    r_in, r_out = 0.004, 0.15
    s.write("disc.inp", L.disc_z(1.0))
    d = L.header((-1, 1, -1, 1, -0.05, 0.05), DT, mu=MU)
    # sphere 1 inner, sphere 2 outer; both start touching (zero overlap) at rest
    d += L.sphere(1, (o[0] + r_in, o[1], R), R, RHO)
    d += L.sphere(2, (o[0] - r_out * 0.6, o[1] - r_out * 0.8, R), R, RHO)
    d += "fix grav all gravity 9.81 vector 0 0 -1\n"
    d += ("fix w all wall/rigid surface disc.inp law hertz type 2 "
          "rotate origin %r %r %r axis 0 0 1 omega %r\n" % (o + (W,)))
    d += "fix integr all nve\n"
    d += L.dump_lines("early", 1, "disc_early.dump") + "run 20\nundump early\n"
    d += L.dump_lines("d", 1000, "disc.dump") + "run %d\n" % STEPS
    s.run("disc", d)

    def wall_vel(a):
        rx, ry = a["x"] - o[0], a["y"] - o[1]
        return (-W * ry, W * rx)
    early = L.read_dump(s.path("disc_early.dump"))
    for i in (1, 2):
        a = early[-1][1][i]
        vw = wall_vel(a)
        ang = math.degrees(math.atan2(a["vx"] * vw[1] - a["vy"] * vw[0],
                                      a["vx"] * vw[0] + a["vy"] * vw[1]))
        s.ck.check("disc: sphere %d first moves along Omega x (x - o)" % i,
                   math.hypot(a["vx"], a["vy"]) > 0 and abs(ang) < 0.5,
                   "angle %.4f deg, |v| %.3g" % (ang, math.hypot(a["vx"], a["vy"])))
    fr = L.read_dump(s.path("disc.dump"))
    a = fr[-1][1][1]
    vw = wall_vel(a)
    err = math.hypot(a["vx"] - vw[0], a["vy"] - vw[1]) / (W * r_in)
    s.ck.check("disc: inner sphere turns with the disc, v = Omega x (x - o) within 1e-3",
               err < 1e-3, "rel err %.3g" % err)
    rr = [math.hypot(f[1]["x"] - o[0], f[1]["y"] - o[1]) for _, f in fr]
    s.ck.check("disc: inner sphere keeps its radius about the axis within 0.2 mm",
               max(abs(r - r_in) for r in rr) < 2e-4, "max drift %.3g" % max(abs(r - r_in) for r in rr))
    turned = 0.0
    for (_, f0), (_, f1) in zip(fr, fr[1:]):
        a0 = math.atan2(f0[1]["y"] - o[1], f0[1]["x"] - o[0])
        a1 = math.atan2(f1[1]["y"] - o[1], f1[1]["x"] - o[0])
        turned += math.remainder(a1 - a0, 2 * math.pi)
    t_total = (fr[-1][0] - fr[0][0]) * DT
    s.ck.check("disc: inner sphere turned Omega t (after a short spin-up) within 2%",
               abs(turned - W * t_total) <= 0.02 * W * t_total,
               "%.4f rad vs %.4f" % (turned, W * t_total))
    b = fr[-1][1][2]
    r2 = math.hypot(b["x"] - o[0], b["y"] - o[1])
    s.ck.check("disc: outer sphere slides outward", r2 > r_out + 0.01, "r %.4f from %.4f" % (r2, r_out))


def body(s):
    s.write("drum.inp", L.drum(0.05, -0.05, 0.05))
    drum_case(s, 0.3)
    drum_case(s, 0.6)
    disc_case(s)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
