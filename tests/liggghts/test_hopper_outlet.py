#!/usr/bin/python3
"""A sphere larger than the outlet of a REVOLUTION hopper settles in it at rest.

The hopper: an outlet pipe of radius 4 mm under a 45-degree cone. A sphere of radius
5 mm cannot pass: it rests on the outlet's rim, a ring around the axis, which
fix wall/rigid gives as one contact per ring sector (docs/conventions.md, "Rings around
the axis"). Checked against statics, at the end of 0.3 s:
- dropped on the axis: at rest (speed < 1e-6 m/s), on the axis, the wall's lateral
  force zero to rounding (< 1e-12 m g), its vertical force m g;
- dropped 0.5 mm off the axis: centred (|x| < 1e-6 m) and at rest, with the same wall
  force; and never thrown sideways on the way (|v_x| below the drop speed).
"""
import liglib as L

R, RHO, DT, G = 0.005, 2500.0, 1e-5, 9.81
MASS = RHO * 4.0 / 3.0 * 3.141592653589793 * R ** 3
HOPPER = ("*SURFACE, TYPE=REVOLUTION, NAME=hopper\n0, 0, 0, 0, 0, 1\n"
          "START, 0.004, -0.05\nLINE, 0.004, 0\nLINE, 0.05, 0.046\nLINE, 0.05, 0.1\n")


def deck(x0):
    d = L.header((-0.06, 0.06, -0.06, 0.06, -0.06, 0.11), DT)
    d += L.sphere(1, (x0, 0.0, 0.006), R, RHO)
    d += "fix g all gravity %r vector 0 0 -1\n" % G
    d += "fix w all wall/rigid surface hopper.inp law hertz type 2\n"
    d += "fix integr all nve/sphere\n"
    d += L.dump_lines("d", 100, "traj.dump", "id x y z vx vy vz")
    d += ('variable fx equal f_w[1]\nvariable fy equal f_w[2]\nvariable fz equal f_w[3]\n'
          'fix pr all print 30000 "${fx} ${fy} ${fz}" file wall.txt screen no\n')
    d += "run 30000\n"
    return d


def body(s):
    s.write("hopper.inp", HOPPER)
    w = MASS * G
    for tag, x0 in (("on_axis", 0.0), ("off_axis", 0.0005)):
        s.run(tag, deck(x0))
        frames = L.read_dump(s.path("traj.dump"))
        last = frames[-1][1][1]
        speed = (last["vx"] ** 2 + last["vy"] ** 2 + last["vz"] ** 2) ** 0.5
        vmax = max(abs(f[1][1]["vx"]) for f in frames)
        vdrop = max(abs(f[1][1]["vz"]) for f in frames)
        fx, fy, fz = L.read_table(s.path("wall.txt"))[-1]
        s.ck.check(tag + ": at rest", speed < 1e-6, "%.3g m/s" % speed)
        s.ck.check(tag + ": on the axis", abs(last["x"]) < 1e-6 and abs(last["y"]) < 1e-6,
                   "x %.3g, y %.3g" % (last["x"], last["y"]))
        s.ck.check(tag + ": in the outlet's rim, not through it", last["z"] > 0.0,
                   "z %.6g" % last["z"])
        s.ck.check(tag + ": the wall's lateral force zero to rounding",
                   abs(fx) < 1e-12 * w and abs(fy) < 1e-12 * w, "%.3g, %.3g N" % (fx, fy))
        s.ck.check(tag + ": the wall carries m g", abs(-fz - w) < 1e-6 * w,
                   "%.9g vs %.9g N" % (-fz, w))
        s.ck.check(tag + ": never thrown sideways", vmax < vdrop, "%.3g vs %.3g m/s"
                   % (vmax, vdrop))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
