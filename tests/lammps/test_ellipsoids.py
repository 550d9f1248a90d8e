#!/usr/bin/python3
"""fix wall/rigid in LAMMPS on ellipsoids (atom_style ellipsoid, fix nve/asphere): rest
heights against the laws' closed forms, and the energy of an elastic bounce.

The wall is the plate z = 0 (a CYLINDER surface whose LINE is the plate, normal +z), the
ellipsoid of half-axes (a, b, c) = (4, 6, 10) mm, density 2500, under gravity -z.
- Rest: the ellipsoid is set down touching the plate in three orientations (long axis c
  vertical; turned 90 deg about x, so that b is vertical; 90 deg about y, a vertical) and
  left to settle under a damped frictionless law. At rest the law's force carries the
  weight m g at the lowest point, straight below the centre, so the centre's height is the
  half-axis h along the normal less the static overlap:
  - law hooke (kn, zeta_n 0.5): delta = m g / kn;
  - law hertz (LAMMPS's materials, type 1 against the wall's type 2, restitution 0.5):
    4/3 Y* sqrt(R delta) delta = m g, delta = (3 m g / (4 Y* sqrt(R)))^(2/3), with
    Y* = 1 / ((1 - nu1^2)/Y1 + (1 - nu2^2)/Y2) and R the ellipsoid's characteristic length,
    the radius of the sphere of equal volume (a b c)^(1/3) (docs/lammps.md).
  The damped oscillation about the rest height decays as exp(-zeta w t) (w = sqrt(k/m),
  zeta >= 0.2 for both laws, t = 50 ms: below 1e-8 of delta), and the height is rounded
  at 1e-18 m: |z - (h - delta)| <= 1e-6 delta, with the speed below 1e-6 m/s and the
  orientation kept (the law is frictionless and the contact below the centre). The same
  plate made as the other kinds of wall gives the same rest height with law hooke: the
  end disc of a REVOLUTION (off its axis), and a MESH of two triangles (off their
  diagonal).
- Spheres and ellipsoids together (atom_style hybrid sphere ellipsoid: fix nve/sphere on
  the sphere, nve/asphere on the ellipsoid, one wall on both): a sphere of radius 5 mm
  rests at R - m_s g / kn and the ellipsoid at c - m g / kn, each to 1e-6 of its overlap.
- Bounce: an ellipsoid tilted 30 deg about (1, 1, 0), falling at 0.5 m/s with no spin,
  lands on one end and bounces twice on the elastic frictionless hooke law (zeta 0, mu 0):
  the first impact throws it into a spin (rotational energy > 50 % of the impact's). The
  energy, kinetic (compute ke) + rotational (compute erotate/asphere, from LAMMPS's
  angmom and the ellipsoid's moments) + m g z + the wall's elastic energy (f_w[8],
  kn delta^2 / 2), is kept up to the integrator's error, which is second order in the time
  step: within (w dt)^2 / 2 = 2e-4 of the start (w = sqrt(kn/m) = 2000 rad/s, dt = 1e-5 s)
  in and out of contact. The wall adds none: in free flight after each bounce the energy
  is at most the start's (1e-9), and what a bounce loses falls at dt/2 to a third or less
  (second order).
- Dissipation: the same drop on a damped rough hooke law (zeta 0.3, mu 0.3) loses most of
  its energy; what the law reports dissipated (f_w[9] to f_w[12]: friction, plastic,
  viscous and creep) balances it: in free flight after each bounce E + dissipated is E0
  to 5e-3 E0 while over half of E0 is gone. The law takes the slip and the normal speed
  at the contact point, v + w x r, with w from LAMMPS's angmom: an angular velocity off
  by one of its body-axis terms breaks the balance by 3 % to 30 %.
"""
import math

import lmplib as M

HALF = (0.004, 0.006, 0.010)
RHO, G, DT = 2500.0, 9.81, 1.0e-5
MASS = RHO * 4.0 / 3.0 * math.pi * HALF[0] * HALF[1] * HALF[2]
KN = 1.0e4
YOUNG, NU = 5.0e7, 0.3
HOOKE = "law hooke props %r %r 0.5 0.5 0" % (KN, KN)
HERTZ = ("law hertz type 2 youngsModulus %r %r poissonsRatio %r %r "
         "coefficientRestitution 0.5 0.5 coefficientFriction 0 0" % (YOUNG, YOUNG, NU, NU))
ELASTIC = "law hooke props %r %r 0 0 0" % (KN, KN)
# orientation: (name, axis, angle in degrees, the half-axis along z)
ORIENT = (("long axis vertical", (0, 0, 1), 0.0, HALF[2]),
          ("b vertical (long axis horizontal)", (1, 0, 0), 90.0, HALF[1]),
          ("a vertical (long axis horizontal)", (0, 1, 0), 90.0, HALF[0]))
BOX = (-0.05, 0.05, -0.05, 0.05, -0.02, 0.06)


def deck(law, x, axis, angle, steps, tag, dt=DT, v=(0, 0, 0), energy=False, lost=False,
         surface="plate.inp"):
    d = M.ellipsoid_header(BOX, dt)
    d += M.ellipsoid(1, x, HALF, RHO, axis, angle, v)
    d += "fix grav all gravity %r vector 0 0 -1\n" % G
    d += "fix w all wall/rigid surface %s %s\n" % (surface, law)
    d += "fix integr all nve/asphere\n"
    if energy:
        d += ("compute rot all erotate/asphere\ncompute ke all ke\n"
              "variable pe equal mass[1]*%r*z[1]\nvariable se equal f_w[8]\n"
              "variable nc equal f_w[7]\n" % G)
        if lost:  # what the law dissipated counts in the energy's last term
            d = d.replace("equal f_w[8]", "equal f_w[8]+f_w[9]+f_w[10]+f_w[11]+f_w[12]")
        d += ('fix pr all print 20 "$(step) $(c_ke:%%.17g) $(c_rot:%%.17g) $(v_pe:%%.17g) '
              '$(v_se:%%.17g) $(v_nc)" screen no file %s.tot\n' % tag)
    d += M.dump_lines("d", steps, tag + ".dump", M.ECOLS)
    d += "run %d\n" % steps
    return d


def rest(s, name, law, delta, tag, orient=ORIENT, surface="plate.inp", xy=(0.0, 0.0)):
    for k, (oname, axis, angle, h) in enumerate(orient):
        t = "%s%d" % (tag, k)
        s.run(t, deck(law, (xy[0], xy[1], h), axis, angle, 5000, t, surface=surface))
        last = M.read_dump(s.path(t + ".dump"))[-1][1][1]
        first = M.read_dump(s.path(t + ".dump"))[0][1][1]
        err = abs(last["z"] - (h - delta))
        speed = math.sqrt(sum(last[c] ** 2 for c in ("vx", "vy", "vz")))
        turn = max(abs(last["c_quat[%d]" % j] - first["c_quat[%d]" % j]) for j in (1, 2, 3, 4))
        s.ck.check("%s, %s: rest height h - delta to 1e-6 delta" % (name, oname),
                   err <= 1e-6 * delta and speed < 1e-6 and turn < 1e-12,
                   "z %.12g, closed form %.12g, |dz|/delta %.2g, speed %.2g, dq %.2g"
                   % (last["z"], h - delta, err / delta, speed, turn))


def mixed(s):
    r, rho_s = 0.005, 2500.0
    ms = rho_s * 4.0 / 3.0 * math.pi * r ** 3
    d = M.ellipsoid_header(BOX, DT).replace("atom_style ellipsoid",
                                            "atom_style hybrid sphere ellipsoid")
    d += M.ellipsoid(1, (-0.02, 0.0, HALF[2]), HALF, RHO, hybrid=True)
    d += "create_atoms 1 single 0.02 0 %r units box\n" % r
    d += "set atom 2 diameter %r density %r\n" % (2 * r, rho_s)
    d += "group ell id 1\ngroup sph id 2\n"
    d += "fix grav all gravity %r vector 0 0 -1\n" % G
    d += "fix w all wall/rigid surface plate.inp %s\n" % HOOKE
    d += "fix i1 ell nve/asphere\nfix i2 sph nve/sphere\n"
    d += M.dump_lines("d", 5000, "mixed.dump", "id x y z vx vy vz")
    d += "run 5000\n"
    s.run("mixed", d)
    last = M.read_dump(s.path("mixed.dump"))[-1][1]
    for i, what, h, m in ((1, "the ellipsoid", HALF[2], MASS), (2, "the sphere", r, ms)):
        delta = m * G / KN
        err = abs(last[i]["z"] - (h - delta))
        s.ck.check("hybrid sphere ellipsoid: %s rests at h - m g/kn to 1e-6 delta" % what,
                   err <= 1e-6 * delta, "z %.12g, closed form %.12g, |dz|/delta %.2g"
                   % (last[i]["z"], h - delta, err / delta))


def bounce(s, dt, tag, law=ELASTIC):
    steps = int(round(0.04 / dt))
    s.run(tag, deck(law, (0.0, 0.0, 0.012), (1, 1, 0), 30.0, steps, tag, dt=dt,
                    v=(0, 0, -0.5), energy=True, lost=law != ELASTIC))
    rows = M.read_table(s.path(tag + ".tot"))
    e = [r[1] + r[2] + r[3] + r[4] for r in rows]
    return rows, e


def body(s):
    s.write("plate.inp", M.L.plane_z(0.0))
    rest(s, "law hooke", HOOKE, MASS * G / KN, "hooke")
    s.write("disc.inp", M.L.disc_z(0.05))
    rest(s, "REVOLUTION disc, law hooke", HOOKE, MASS * G / KN, "disc", ORIENT[1:2],
         "disc.inp", (0.01, 0.004))
    h = 0.05
    s.write("plate.stl", M.L.stl_text([((-h, -h, 0), (h, -h, 0), (h, h, 0)),
                                       ((-h, -h, 0), (h, h, 0), (-h, h, 0))]))
    rest(s, "MESH plate, law hooke", HOOKE, MASS * G / KN, "mesh", ORIENT[1:2],
         "inline mesh plate.stl", (0.01, 0.004))
    ystar = 1.0 / (2.0 * (1.0 - NU * NU) / YOUNG)
    R = (HALF[0] * HALF[1] * HALF[2]) ** (1.0 / 3.0)
    rest(s, "law hertz", HERTZ, (3.0 * MASS * G / (4.0 * ystar * math.sqrt(R))) ** (2.0 / 3.0),
         "hertz")

    mixed(s)

    rows, e = bounce(s, DT, "bounce")
    e0 = e[0]
    touched = [k for k, r in enumerate(rows) if r[5] > 0]
    s.ck.check("the ellipsoid bounced twice", len(touched) > 0 and rows[-1][5] == 0
               and any(touched[j + 1] - touched[j] > 1 for j in range(len(touched) - 1)),
               "%d rows in contact" % len(touched))
    first_off = next(k for k in range(touched[0], len(rows)) if rows[k][5] == 0)
    impact_ke = max(r[1] for r in rows[:touched[0] + 1])
    s.ck.check("the tilted impact throws it into a spin", rows[first_off][2] > 0.5 * impact_ke,
               "rotational %.4g J of %.4g J" % (rows[first_off][2], impact_ke))
    w = math.sqrt(KN / MASS)
    bound = 0.5 * (w * DT) ** 2
    drift = max(abs(x - e0) for x in e) / e0
    s.ck.check("energy kept within (w dt)^2/2 over the bounces, in and out of contact",
               drift <= bound, "worst |dE|/E %.3g, bound %.3g" % (drift, bound))
    free = flights(rows, e)
    s.ck.check("the wall adds no energy: after each bounce E <= E0",
               len(free) == 2 and all(x <= e0 * (1 + 1e-9) for x in free),
               "after the bounces (E - E0)/E0 = %s" % ", ".join("%.3g" % ((x - e0) / e0)
                                                               for x in free))
    rows2, e2 = bounce(s, DT / 2, "bounce_half")
    free2 = flights(rows2, e2)
    loss, loss2 = abs(free[-1] - e0) / e0, abs(free2[-1] - e2[0]) / e2[0]
    s.ck.check("the energy lost is the integrator's: at dt/2 a third of it or less",
               len(free2) == 2 and loss2 <= loss / 3.0,
               "%.3g at dt/2 against %.3g" % (loss2, loss))

    rows, e = bounce(s, DT, "damped", "law hooke props %r %r 0.3 0.3 0.3" % (KN, KN))
    e0 = e[0]
    free = flights(rows, e)
    gone = (e0 - (rows[-1][1] + rows[-1][2] + rows[-1][3])) / e0
    worst = max(abs(x - e0) for x in free) / e0 if free else 1.0
    s.ck.check("damped rough bounce: the law's dissipation balances the energy lost",
               len(free) >= 1 and gone > 0.5 and worst <= 5e-3,
               "%.1f %% of E0 dissipated, |E + dissipated - E0|/E0 %.2g in flight"
               % (100 * gone, worst))


def flights(rows, e):
    """The energy in free flight after each contact (the first row out of contact)."""
    return [e[k] for k in range(1, len(rows)) if rows[k][5] == 0 and rows[k - 1][5] > 0]

if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
