"""Physical checks of FRIC and UINTER routines written as for Abaqus (tests/liggghts/
routines/: upper-case include, tab-indented statements, lines past column 72, the
utility routines), given to fix wall/rigid as Fortran sources with `normal hertz`.

One sphere on a plane z = 0 (n = +z), starting at its Hertz equilibrium overlap under
m g cos(theta), h = (3 m g cos(theta) / (4 Y* sqrt(R)))^(2/3); a slope of theta is a
tilted gravity (sin(theta), 0, -cos(theta)). The answers are closed forms:
- fric_coulomb.f (elastic stick capped at mu PRESS, returns at once when LM = 2), sphere
  without rotation (fix nve) launched at 0.1 m/s along x: it slows at mu g.
- fric_rough.f (LM = 1 always) on a 20 degree slope with nve/sphere: rolling without
  slip, acceleration (5/7) g sin(theta); the wall's force along the slope (f_w[1]) is
  the friction (2/7) m g sin(theta) at every output step after the first millisecond;
  the contact point x - (R - h/2) n moves at under 1e-3 of the sphere's speed.
- fric_smooth.f (LM = 2 always) on the same slope: acceleration g sin(theta), no spin.
- uinter_coulomb.f (Coulomb shear on the pressure STRESS(1) of the normal law) on the
  sliding case of the first deck: the velocity history of the built-in `law hertz`
  with the same material and friction coefficient, and both slow at mu g.
Each routine's information line (XPLB_ABQERR, LOP = 1) is in the log: the job name
(GETJOBNAME), the process count (GETNUMCPUS) and the pressure on the first call, m g.
"""
import math
import os
import re

import liglib as L

HERE = os.path.dirname(os.path.abspath(__file__))
ROUTINES = os.path.join(HERE, "routines")

R, RHO, G = 0.005, 2500.0, 9.81
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
# Particle (type 1) and wall (type 2) materials of the deck head.
YP, NUP, YW, NUW, REST, MU = 5.0e7, 0.3, 2.0e8, 0.25, 0.7, 0.5
YSTAR = 1.0 / ((1.0 - NUP ** 2) / YP + (1.0 - NUW ** 2) / YW)
HERTZ_PROPS = (YP, NUP, YW, NUW, REST, MU, 0.0)
K_STICK = 5.0e3  # elastic stick of the Coulomb routines, N/m (area node: stress = force)
V0 = 0.1
THETA = math.radians(20.0)
BOX = (-0.05, 0.05, -0.05, 0.05, -0.01, 0.05)
EVERY = 10  # output interval, steps
TOL = 0.01


def overlap(theta):
    """Hertz equilibrium overlap: 4/3 Y* sqrt(R) h^(3/2) = m g cos(theta)."""
    return (3.0 * MASS * G * math.cos(theta) / (4.0 * YSTAR * math.sqrt(R))) ** (2.0 / 3.0)


def fit_slope(ts, vs):
    """Least-squares slope of v(t)."""
    n = len(ts)
    tm, vm = sum(ts) / n, sum(vs) / n
    return (sum((t - tm) * (v - vm) for t, v in zip(ts, vs))
            / sum((t - tm) ** 2 for t in ts))


def rel(a, b):
    return abs(a - b) / abs(b)


def deck(s, name, law, theta, v0, integrator, steps, dt):
    """One sphere at its equilibrium overlap, gravity tilted by theta about y, the wall
    with law LAW; a dump and the wall force (f_w[1..3]) every EVERY steps."""
    floor = s.write("floor.inp", L.plane_z(0.0, half=1.0))
    text = L.header(BOX, dt, young=(YP, YW), poisson=(NUP, NUW), e=REST, mu=MU)
    text += L.sphere(1, (0.0, 0.0, R - overlap(theta)), R, RHO, v=(v0, 0.0, 0.0))
    text += ("fix grav all gravity %r vector %r 0 %r\n"
             % (G, math.sin(theta), -math.cos(theta)))
    text += "fix w all wall/rigid surface %s %s type 2\n" % (floor, law)
    text += "fix integr all %s\n" % integrator
    text += ("variable stp equal step\nvariable fx equal f_w[1]\n"
             "variable fy equal f_w[2]\nvariable fz equal f_w[3]\n"
             "fix out all print %d \"${stp} ${fx} ${fy} ${fz}\" file %s.force screen no\n"
             % (EVERY, name))
    text += L.dump_lines("d", EVERY, name + ".dump")
    text += "run %d\n" % steps
    s.run(name, text)
    frames = [(st, a[1]) for st, a in L.read_dump(s.path(name + ".dump"))]
    forces = L.read_table(s.path(name + ".force"))
    with open(s.path(name + ".log")) as f:
        log = f.read()
    return frames, forces, log


def props(*routine):
    return "props " + " ".join("%r" % p for p in HERTZ_PROPS + routine)


def routine(name):
    return os.path.join(ROUTINES, name)


def info_line(ck, name, log, pattern, want_press=None):
    """The routine's XPLB_ABQERR information line is in the log; with want_press its
    pressure field is m g cos(theta)."""
    m = re.search(r"rigidsurf INFO \[rank 0\] (FRIC|UINTER) \(XPLB_ABQERR\): " + pattern, log)
    if want_press is None or not m:
        return ck.check(name + ": information line in the log", m is not None,
                        m.group(0) if m else "", why="no line matching " + pattern)
    press = float(m.group("press"))
    return ck.check(name + ": information line in the log, pressure m g on the first call",
                    rel(press, want_press) <= TOL,
                    "%s (m g = %.6g)" % (m.group(0), want_press))


def sliding(ck, name, frames, dt):
    """vx(t) of a sphere sliding at V0 against 0.1 - mu g t: the fitted deceleration
    after the first millisecond and the speed at the end. Returns the times and vx."""
    ts = [st * dt for st, a in frames]
    vx = [a["vx"] for st, a in frames]
    sel = [i for i, t in enumerate(ts) if t >= 1e-3]
    slope = fit_slope([ts[i] for i in sel], [vx[i] for i in sel])
    ck.check(name + ": deceleration mu g to 1%", rel(-slope, MU * G) <= TOL,
             "fit %.6g, mu g = %.6g, rel %.2e" % (-slope, MU * G, rel(-slope, MU * G)))
    want = V0 - MU * G * ts[-1]
    ck.check(name + ": speed V0 - mu g t at t = %g s to 1%%" % ts[-1],
             rel(vx[-1], want) <= TOL, "%.6g vs %.6g" % (vx[-1], want))
    ck.check(name + ": still sliding at the end (the deck tests Coulomb sliding)",
             vx[-1] > 0.2 * V0, "vx %.4g" % vx[-1])
    return ts, vx


def body(s):
    ck = s.ck
    os.environ["RIGIDSURF_CACHE"] = s.path("cache")
    mg = MASS * G
    gs = G * math.sin(THETA)

    # 1. Coulomb FRIC, sliding without rotation.
    dt = 1e-5
    frames, _, log = deck(s, "coulomb", "law fric %s normal hertz statev 1 %s"
                          % (routine("fric_coulomb.f"), props(MU, K_STICK)),
                          0.0, V0, "nve", 1500, dt)
    sliding(ck, "fric coulomb", frames, dt)
    info_line(ck, "fric coulomb", log,
              r"COULOMB friction at node 1: pressure (?P<press>\S+), mu %s,"
              % re.escape("%g" % MU), mg)

    # 2. Perfectly rough FRIC on the slope: rolling without slip.
    h = overlap(THETA)
    frames, forces, log = deck(s, "rough", "law fric %s normal hertz %s"
                               % (routine("fric_rough.f"), props()),
                               THETA, 0.0, "nve/sphere", 3000, dt)
    ts = [st * dt for st, a in frames]
    sel = [i for i, t in enumerate(ts) if t >= 1e-3]
    acc = fit_slope([ts[i] for i in sel], [frames[i][1]["vx"] for i in sel])
    want = 5.0 / 7.0 * gs
    ck.check("fric rough: acceleration (5/7) g sin(theta) to 1%", rel(acc, want) <= TOL,
             "fit %.6g, want %.6g, rel %.2e" % (acc, want, rel(acc, want)))
    # The sphere accelerates along +x; the friction on it points up the slope (-x), so
    # the wall receives +x.
    fwant = 2.0 / 7.0 * MASS * gs
    late = [(row[0], row[1]) for row in forces if row[0] * dt >= 1e-3]
    worst = max(late, key=lambda r: rel(r[1], fwant)) if late else (None, float("nan"))
    ck.check("fric rough: friction (2/7) m g sin(theta) to 1% at every output step "
             "after 1 ms", bool(late) and rel(worst[1], fwant) <= TOL,
             "%d steps, worst %.6g at step %d, want %.6g, rel %.2e"
             % (len(late), worst[1], int(worst[0] or 0), fwant, rel(worst[1], fwant)))
    a = frames[-1][1]
    rc = R - 0.5 * h  # lever arm of the contact point x_cp = x - (R - h/2) n, n = +z
    # v + omega x (-rc z) = (vx - rc wy, vy + rc wx, vz)
    vcp = math.sqrt((a["vx"] - rc * a["omegay"]) ** 2 + (a["vy"] + rc * a["omegax"]) ** 2
                    + a["vz"] ** 2)
    speed = math.sqrt(a["vx"] ** 2 + a["vy"] ** 2 + a["vz"] ** 2)
    ck.check("fric rough: contact point at rest, |v_cp| < 1e-3 |v| at the end",
             speed > 0.0 and vcp < 1e-3 * speed,
             "|v_cp| %.3g, |v| %.4g, ratio %.2e" % (vcp, speed, vcp / speed if speed else 0))
    info_line(ck, "fric rough", log,
              r"perfectly rough friction at node 1, first increment, 1 processes")

    # 3. Perfectly smooth FRIC on the slope: sliding, no spin.
    frames, _, log = deck(s, "smooth", "law fric %s normal hertz %s"
                          % (routine("fric_smooth.f"), props()),
                          THETA, 0.0, "nve/sphere", 3000, dt)
    ts = [st * dt for st, a in frames]
    sel = [i for i, t in enumerate(ts) if t >= 1e-3]
    acc = fit_slope([ts[i] for i in sel], [frames[i][1]["vx"] for i in sel])
    ck.check("fric smooth: acceleration g sin(theta) to 1%", rel(acc, gs) <= TOL,
             "fit %.6g, want %.6g, rel %.2e" % (acc, gs, rel(acc, gs)))
    wmax = max(math.sqrt(a["omegax"] ** 2 + a["omegay"] ** 2 + a["omegaz"] ** 2)
               for _, a in frames)
    vend = abs(frames[-1][1]["vx"])
    ck.check("fric smooth: no spin (|omega| R < 1e-12 of the speed)",
             vend > 0.0 and wmax * R <= 1e-12 * vend,
             "max |omega| %.3g rad/s, speed %.4g m/s" % (wmax, vend))
    info_line(ck, "fric smooth", log,
              r"perfectly smooth friction in job smooth at node 1, first increment")

    # 4. UINTER Coulomb shear on normal hertz against the built-in law hertz.
    #    The built-in law, as LIGGGHTS's Hertz model, applies its tangential damping
    #    gamma_t vt uncapped at the setup of the run, where the shear history is still
    #    zero (0.065 N, 5 mu m g, for half a step): it starts 2.2e-4 m/s slower than
    #    Coulomb sliding, 0.85% of the speed left at 15 ms.
    frames_u, _, log = deck(s, "uinter", "law uinter %s normal hertz statev 2 %s"
                            % (routine("uinter_coulomb.f"), props(MU, K_STICK)),
                            0.0, V0, "nve", 1500, dt)
    frames_h, _, _ = deck(s, "hertz", "law hertz", 0.0, V0, "nve", 1500, dt)
    sliding(ck, "uinter coulomb", frames_u, dt)
    sliding(ck, "law hertz", frames_h, dt)
    steps_u = [st for st, _ in frames_u]
    steps_h = [st for st, _ in frames_h]
    if ck.check("uinter vs hertz: same output steps", steps_u == steps_h,
                "%d vs %d frames" % (len(steps_u), len(steps_h))):
        worst = max(((rel(au["vx"], ah["vx"]), st)
                     for (st, au), (_, ah) in zip(frames_u, frames_h)), default=(0.0, 0))
        ck.check("uinter vs hertz: vx equal to 1% at every output step", worst[0] <= TOL,
                 "worst rel %.2e at step %d" % worst)
    info_line(ck, "uinter coulomb", log,
              r"COULOMB shear at node 1 from increment \d+: pressure (?P<press>\S+), mu %s,"
              % re.escape("%g" % MU),
              mg)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
