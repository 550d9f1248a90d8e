#!/usr/bin/python3
"""wall/rigid's `behind none` on a cylinder's mantle, through the line path and the staged
calls: a particle whose centre lies behind the one-sided surface is left alone, as
LAMMPS's region wall leaves alone a particle outside its region.

A REVOLUTION mantle (r = 50 mm about z, normal inward, one-sided) and spheres (R = 2 mm)
in the plane z = 0 that touch only the wall, law hertz (the materials on the fix line,
restitution 1, friction 0: elastic and frictionless, so every speed below has a closed
form), `behind none`:

- going out: spheres just inside the mantle at 40 m/s outward, fast enough to push their
  centre through it (the elastic energy at an overlap of R, E(R) = 8/15 Y* sqrt(R) R^(5/2),
  is less than m v^2 / 2). The contact ends where the centre crosses the surface, with the
  energy E(R) stored in it: each flies on outward at sqrt(v^2 - 2 E(R) / m). A sphere
  the line path still took as touching once its centre is behind would be pushed back in.
- coming in: spheres outside at 40 m/s inward, left alone until their centre crosses into
  the front, where the contact starts at an overlap of R and gives back E(R): each goes on
  at sqrt(v^2 + 2 E(R) / m). Some start closer to the surface than the skin, farther than
  their radius, so the wall must find them without a neighbour-list build in between.
- bouncing: spheres inside at 5 m/s outward, too slow to get through: each comes back at
  5 m/s.

Speeds to 0.2 % (the time step's error in where a contact starts or ends); every sphere
ends on the side the closed form says. The deck runs with the fused kernel (`fused yes`,
the line path on the mantle) and with `fused no` (the staged calls): the dumps agree bit
for bit.
"""
import math

import lmplib as M

RC, R, RHO, DT, STEPS = 0.05, 0.002, 2500.0, 1.0e-7, 6000
YOUNG, NU = 1.0e7, 0.3
V_FAST, V_SLOW = 40.0, 5.0
SKIN = 0.006  # larger than the spheres' diameter
BOX = (-0.1, 0.1, -0.1, 0.1, -0.01, 0.01)


def stored_energy():
    """Hertz's elastic energy at an overlap of R (law hertz: Reff = R, Y* of two equal
    materials)."""
    ystar = 1.0 / (2.0 * (1.0 - NU * NU) / YOUNG)
    return 8.0 / 15.0 * ystar * math.sqrt(R) * R ** 2.5


def spheres():
    """(kind, start radius, radial speed) of each sphere; sphere i (id i + 1) starts at
    the angle 2 pi i / n."""
    out = []
    # going out: their centre R + 10 um inside the mantle
    out += [("out", RC - R - 1e-5, V_FAST)] * 4
    # coming in: centres 1.5 R and 2.5 mm behind the surface (the latter within the skin,
    # beyond R)
    for k in range(4):
        out.append(("in", RC + (1.5 * R if k % 2 else 0.0025), -V_FAST))
    out += [("bounce", RC - R - 1e-5, V_SLOW)] * 2
    return out


def deck(tag, fused):
    d = M.header(BOX, DT).replace("neighbor 0.002 bin", "neighbor %r bin" % SKIN)
    sph = spheres()
    for i, (_, r0, vr) in enumerate(sph):
        a = 2.0 * math.pi * i / len(sph)
        c, s = math.cos(a), math.sin(a)
        d += M.sphere(i + 1, (r0 * c, r0 * s, 0.0), R, RHO, (vr * c, vr * s, 0.0))
    d += ("fix w all wall/rigid surface mantle.inp law hertz type 2 youngsModulus %r %r "
          "poissonsRatio %r %r coefficientRestitution 1 1 coefficientFriction 0 0 "
          "behind none%s\n" % (YOUNG, YOUNG, NU, NU, "" if fused else " fused no"))
    d += "fix integr all nve/sphere\n"
    d += M.dump_lines("d", 500, tag + ".dump")
    d += "run %d\n" % STEPS
    return d


def body(s):
    s.write("mantle.inp", M.L.drum(RC, -1.0, 1.0, name="mantle"))
    frames = {}
    for fused in (True, False):
        tag = "fused_" + ("yes" if fused else "no")
        s.run(tag, deck(tag, fused))
        frames[tag] = M.read_dump(s.path(tag + ".dump"))
    diff = M.exact_frames(frames["fused_yes"], frames["fused_no"])
    s.ck.check("fused yes (the line path) and fused no (the staged calls) bit for bit",
               diff is None, "first difference: %s" % (diff,))

    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    e = stored_energy()
    last = frames["fused_yes"][-1][1]
    for i, (kind, r0, vr) in enumerate(spheres()):
        a = last[i + 1]
        r = math.hypot(a["x"], a["y"])
        v_rad = (a["vx"] * a["x"] + a["vy"] * a["y"]) / r
        if kind == "out":
            want, side = math.sqrt(vr * vr - 2.0 * e / m), r > RC
        elif kind == "in":
            want, side = -math.sqrt(vr * vr + 2.0 * e / m), r < RC - R
        else:
            want, side = -vr, r < RC - R
        s.ck.check("sphere %d (%s): radial speed %.4f m/s (closed form), on its side"
                   % (i + 1, kind, want), side and abs(v_rad - want) <= 2e-3 * abs(want),
                   "%.6f m/s at r = %.5f m" % (v_rad, r))


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
