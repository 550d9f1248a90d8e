#!/usr/bin/python3
"""fix wall/rigid in LAMMPS on rounded polyhedra (atom_style body rounded/polyhedron, fix
nve/body): closed forms, LAMMPS's own fix wall/body/polyhedron on the same deck, and bad
bodies.

The wall is the plate z = 0 (a CYLINDER surface whose LINE is the plate, normal +z) unless
said otherwise; the bodies come from a data file (vertices, edges, faces, rounding
diameter, the moments of inertia given with them), mass 0.02 kg, gravity 9.81.
- Rest: a cube of half-side s = 10 mm rounded by r = 2 mm, set down flat and left to settle
  under law hooke (kn 1e4, zeta_n 0.5, frictionless), rests on its four bottom corners, each
  a contact of stiffness kn carrying a quarter of the weight: the centre's height is
  s + r - m g / (4 kn), to 1e-6 of the overlap (the oscillation decays as exp(-zeta w t),
  w = sqrt(4 kn / m), below 1e-15 at 50 ms), with four contacts and the speed below
  1e-6 m/s. The same on the end disc of a REVOLUTION and on a MESH of two triangles (the
  cube across their diagonal).
- Slide: a box of half-extents (10, 10, 5) mm rounded by 1 mm rests on the plate with
  gravity tilted by 30 degrees (the plate an incline); under law hooke (kn = kt = 1e4,
  zeta 0.5, mu 0.3) it slides down at g (sin 30 - mu cos 30) = 2.3555 m/s^2: every corner
  slips with its friction at mu times its normal force, which sum to m g cos 30 (the box
  does not tip: mu h_z < h_x). The acceleration from v_x between 40 and 100 ms, to 1e-6.
- Rolling: a prism of 24 sides whose corners lie on a circle of radius c (0.5 mm, then
  0.2 mm), 10 mm long, rounded by 10 mm - c, its moment about its axis given as m rho^2/2
  (rho its perimeter over 2 pi), rolls down a 20 degree incline (hooke, mu 0.5, zeta 0.3)
  at (2/3) g sin 20 = 2.2368 m/s^2, a solid cylinder's. Its core's corners make it roll
  over facets (the centre rises and falls by c (1 - cos 7.5 deg) and each facet's landing
  takes some energy), which slows it by an amount that vanishes with c: to 1e-3 at
  c = 0.2 mm, and at most half the deviation of c = 0.5 mm (measured 4.3e-4 and 1.1e-3).
  Its hull is slender (48 corners on a 1 mm wide core): every corner is a vertex.
- LAMMPS's own wall: fix wall/body/polyhedron (kn c_n c_t zplane) is a spring kn on the
  overlap of each vertex's rounding sphere with the plane, plus dashpots c_n on the
  vertex's normal and c_t on its tangential velocity, no friction limit, its force at the
  vertex's centre. law hooke with the same kn is that spring on the same overlap, at the
  contact point below the vertex: for a normal force the lever arm differs along n only,
  which gives the same torque. So without damping and friction (c_n = c_t = 0; zeta 0,
  mu 0) the two walls give the same trajectory: a cube tilted 25 degrees about (1, 1, 0)
  dropped at 0.5 m/s lands on one corner, spins and bounces; every dumped value (x, v,
  angular momentum, force, torque, quaternion) at every 100 steps to 1e-9 of its column's
  largest. Damped: hooke's dashpot is 2 zeta sqrt(kn m_e) on each contact's effective mass
  m_e (docs/conventions.md), a quarter of the cube's mass on each of four corners that
  push together; LAMMPS's c_n is a constant. The cube dropped flat at 0.5 m/s with zeta_n
  0.3 and c_n = 2 zeta_n sqrt(kn m / 4) (c_t = 0) bounces on the same trajectory, to 1e-9.
  With friction the walls differ by design (hooke has a tangential spring and a Coulomb
  limit, LAMMPS's wall a tangential dashpot and no limit): not compared.
- Bad bodies: a cube with a corner pushed inside the hull of the others (non-convex) and
  law lammps on a body each stop the run with one error naming the fix, the particle and
  what was wrong.
"""
import math

import lmplib as M

G, DT, KN, MASS = 9.81, 1.0e-5, 1.0e4, 0.02
S, R = 0.01, 0.002
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.1)
ELASTIC = "law hooke props %r %r 0 0 0" % (KN, KN)


def cube(x, axis=(0, 0, 1), angle=0.0, v=(0, 0, 0), half=(S, S, S), r=R):
    V, E, F = M.box_body(half)
    V = [M.rotate(p, axis, angle) for p in V]
    hx, hy, hz = half
    # a solid box's moments; isotropic for a cube, so any orientation keeps them
    ixx, iyy, izz = (MASS / 3 * (hy ** 2 + hz ** 2), MASS / 3 * (hx ** 2 + hz ** 2),
                     MASS / 3 * (hx ** 2 + hy ** 2))
    assert angle == 0.0 or ixx == iyy == izz
    return {"V": V, "E": E, "F": F, "r": r, "m": MASS, "I": (ixx, iyy, izz, 0, 0, 0),
            "x": x, "v": v}


def deck(s, tag, bodies, wall, steps, every=100, gravity="0 0 -1", extra=""):
    s.write(tag + ".data", M.body_data(bodies, BOX))
    d = M.body_header(tag + ".data", DT)
    d += "fix grav all gravity %r vector %s\n" % (G, gravity)
    d += wall + "\nfix integr all nve/body\n" + extra
    d += M.dump_lines("d", every, tag + ".dump", M.BCOLS)
    d += "run %d\n" % steps
    return d


def rest(s):
    delta = MASS * G / (4 * KN)
    h = S + R
    hooke = "law hooke props %r %r 0.5 0.5 0" % (KN, KN)
    s.write("plate.inp", M.L.plane_z(0.0))
    s.write("disc.inp", M.L.disc_z(0.05))
    w = 0.05
    s.write("plate.stl", M.L.stl_text([((-w, -w, 0), (w, -w, 0), (w, w, 0)),
                                       ((-w, -w, 0), (w, w, 0), (-w, w, 0))]))
    for name, surf, xy in (("plate (CYLINDER)", "plate.inp", (0.0, 0.0)),
                           ("REVOLUTION disc", "disc.inp", (0.01, 0.004)),
                           ("MESH of two triangles", "inline mesh plate.stl", (0.0, 0.0))):
        tag = "rest_" + surf.split(".")[-1]
        wall = "fix w all wall/rigid surface %s %s" % (surf, hooke)
        s.run(tag, deck(s, tag, [cube((xy[0], xy[1], h + 1e-4))], wall, 5000, 5000,
                        extra="variable nc equal f_w[7]\n"
                              'fix pr all print 5000 "${nc}" screen no file %s.nc\n' % tag))
        last = M.read_dump(s.path(tag + ".dump"))[-1][1][1]
        nc = M.read_table(s.path(tag + ".nc"))[-1][0]
        err = abs(last["z"] - (h - delta))
        speed = math.sqrt(sum(last[c] ** 2 for c in ("vx", "vy", "vz")))
        s.ck.check("cube at rest on a %s: s + r - m g/(4 kn) to 1e-6 delta, 4 contacts" % name,
                   err <= 1e-6 * delta and speed < 1e-6 and nc == 4,
                   "z %.12g, closed form %.12g, |dz|/delta %.2g, speed %.2g, %d contacts"
                   % (last["z"], h - delta, err / delta, speed, nc))


def slide(s):
    th, mu = math.radians(30.0), 0.3
    half, r = (0.01, 0.01, 0.005), 0.001
    delta = MASS * G * math.cos(th) / (4 * KN)
    b = cube((0.0, 0.0, half[2] + r - delta), half=half, r=r)
    wall = "fix w all wall/rigid surface plate.inp law hooke props %r %r 0.5 0.5 %r" % (
        KN, KN, mu)
    s.run("slide", deck(s, "slide", [b], wall, 10000, 500,
                        gravity="%r 0 %r" % (math.sin(th), -math.cos(th))))
    fr = dict(M.read_dump(s.path("slide.dump")))
    a = (fr[10000][1]["vx"] - fr[4000][1]["vx"]) / (6000 * DT)
    want = G * (math.sin(th) - mu * math.cos(th))
    tilt = max(abs(fr[10000][1]["c_quat[%d]" % j] - fr[0][1]["c_quat[%d]" % j])
               for j in (1, 2, 3, 4))
    s.ck.check("box sliding down a 30 degree incline: a = g (sin - mu cos) to 1e-6",
               abs(a - want) <= 1e-6 * want and tilt < 1e-3,
               "a %.10g, closed form %.10g, rel %.2g; quaternion turned by %.2g"
               % (a, want, abs(a - want) / want, tilt))


def roll(s, tag, core):
    """The acceleration of a 24-sided prism of corner radius core, rounded to 10 mm, rolling
    down a 20 degree incline from rest, from v_x between 50 and 200 ms."""
    th, n, hl, rho_c = math.radians(20.0), 24, 0.005, 0.01
    V, E, F = M.prism_body(n, core, hl)
    rr = rho_c - core
    rho = core * n * math.sin(math.pi / n) / math.pi + rr  # its perimeter over 2 pi
    iy = MASS * rho * rho / 2
    ix = MASS * (3 * rho * rho + (2 * hl) ** 2) / 12
    z = rho_c - MASS * G * math.cos(th) / (2 * KN)
    b = {"V": V, "E": E, "F": F, "r": rr, "m": MASS, "I": (ix, iy, ix, 0, 0, 0),
         "x": (-0.05, 0.0, z)}
    s.write(tag + ".data", M.body_data([b], (-0.1, 0.3, -0.05, 0.05, -0.05, 0.1)))
    d = M.body_header(tag + ".data", DT, M.body_nmax([b]), pair=False)
    d += "fix grav all gravity %r vector %r 0 %r\n" % (G, math.sin(th), -math.cos(th))
    d += ("fix w all wall/rigid surface plate.inp law hooke props %r %r 0.3 0.3 0.5\n"
          "fix integr all nve/body\n" % (KN, KN))
    d += M.dump_lines("d", 5000, tag + ".dump", M.BCOLS) + "run 20000\n"
    s.run(tag, d)
    fr = dict(M.read_dump(s.path(tag + ".dump")))
    return (fr[20000][1]["vx"] - fr[5000][1]["vx"]) / (15000 * DT)


def rolling(s):
    want = 2.0 / 3.0 * G * math.sin(math.radians(20.0))
    dev = [roll(s, "roll%d" % k, core) / want - 1.0 for k, core in enumerate((5e-4, 2e-4))]
    s.ck.check("rounded 24-sided prism (I = m rho^2/2) rolling down 20 degrees: (2/3) g sin "
               "to 1e-3, closer as its core shrinks",
               abs(dev[1]) <= 1e-3 and abs(dev[1]) <= 0.5 * abs(dev[0]),
               "a/a0 - 1: %.3g with a core of 0.5 mm, %.3g with 0.2 mm" % tuple(dev))


def compare(s, tag, bodies, ours, theirs, what, tol):
    s.run(tag + "_rigid", deck(s, tag + "_rigid", bodies, ours, 6000))
    s.run(tag + "_stock", deck(s, tag + "_stock", bodies, theirs, 6000), exe=s.args.lmp)
    fa = M.read_dump(s.path(tag + "_rigid.dump"))
    fb = M.read_dump(s.path(tag + "_stock.dump"))
    cols = M.BCOLS.split()[1:]
    big = {c: max(abs(f[1][c]) for _, f in fa + fb) for c in cols}
    # each column against its largest value, or a thousandth of its family's (a column that
    # stays at zero, such as x of a body dropped straight down, compares with its family)
    fam = {c: max(big[d] for d in cols if d.rstrip("xyz1234]") == c.rstrip("xyz1234]"))
           for c in cols}
    scale = {c: max(big[c], 1e-3 * fam[c]) or 1.0 for c in cols}
    worst = M.L.compare_frames(fa, fb, scale)
    top = max(worst.items(), key=lambda kv: kv[1][0]) if worst else None
    bounced = any(f[1]["vz"] > 0 for _, f in fa)
    s.ck.check("%s: wall/rigid = wall/body/polyhedron, every dumped value to %g" % (what, tol),
               top is not None and top[1][0] <= tol and bounced,
               "worst %s: %.3g of its scale (step %d); bounced %s"
               % (top[0], top[1][0], top[1][1], bounced) if top else "frames differ")
    return fa


def stock(s):
    tilted = cube((0.0, 0.0, 0.02), (1, 1, 0), 25.0, (0, 0, -0.5))
    fa = compare(s, "tilted", [tilted], "fix w all wall/rigid surface plate.inp " + ELASTIC,
                 "fix w all wall/body/polyhedron %r 0 0 zplane 0.0 NULL" % KN,
                 "elastic tilted cube landing on a corner", 1e-9)
    spin = max(abs(f[1]["angmomx"]) + abs(f[1]["angmomy"]) for _, f in fa)
    s.ck.check("the tilted landing turns the cube (angular momentum > 0)", spin > 1e-6,
               "largest |Lx| + |Ly| %.3g" % spin)
    zeta = 0.3
    cn = 2 * zeta * math.sqrt(KN * MASS / 4)
    flat = cube((0.0, 0.0, 0.0125), v=(0, 0, -0.5))
    compare(s, "damped", [flat],
            "fix w all wall/rigid surface plate.inp law hooke props %r %r %r 0 0" % (
                KN, KN, zeta),
            "fix w all wall/body/polyhedron %r %r 0 zplane 0.0 NULL" % (KN, cn),
            "damped flat cube, c_n = 2 zeta sqrt(kn m/4)", 1e-6)


def bad(s):
    dent = cube((0.0, 0.0, 0.02))
    dent["V"][7] = (0.3 * S, 0.3 * S, 0.3 * S)
    line = "fix w all wall/rigid surface plate.inp " + ELASTIC
    rc, out = s.run("nonconvex", deck(s, "nonconvex", [dent], line, 10), expect_ok=False)
    # found on the rank that holds the body (error->one, which ends with MPI_Abort)
    errs = M.L.error_lines(out)
    s.ck.check("a non-convex body: one error naming the fix, the particle and the vertex",
               rc == 1 and len(set(errs)) == 1 and "Segmentation" not in out
               and all(w in errs[0] for w in ("Fix wall/rigid w", "particle 1",
                                              "vertex 7 lies inside the convex hull",
                                              "not convex")),
               errs[0] if errs else "exit %s, no error" % rc)
    line = "fix w all wall/rigid surface plate.inp law lammps hooke 1e4 NULL 0 NULL 0 0"
    rc, out = s.run("lawlammps", deck(s, "lawlammps", [cube((0.0, 0.0, 0.02))], line, 10),
                    expect_ok=False)
    M.L.check_rejected(s.ck, "law lammps on a body", line,
                       ["Fix wall/rigid w", "law lammps", "atom_style sphere"], rc, out)


def body(s):
    rest(s)
    slide(s)
    rolling(s)
    stock(s)
    bad(s)


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK]), body)
