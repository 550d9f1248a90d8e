#!/usr/bin/python3
"""The oscillating `fix move/mesh` styles (wiggle, viblin, riggle, vibrot), superposed
translations, a rotation superposed on a translation and `wall/gran ... shear`, run by
stock LIGGGHTS as written and by liggghts-rigidsurf as rigidsurf-migrate rewrites them.

Each deck: an STL plate (the square |x|, |y| <= 0.1 at z = 0, two triangles, wall type
2), two spheres of radius 5 mm set on it, gravity -z, law hertz. The spheres settle for
SETTLE steps on the plate at rest; then the move/mesh fix is made and the deck runs
MOVE steps more. The motion starts where the plate has been at rest, so the time since
the move fix was made (LIGGGHTS's dTAbs) is not the simulation time: a translation that
took the simulation time instead would be out of phase by SETTLE dt (a quarter of the
wiggle's period), and the control run (WRONG_T0) shows that such a deck fails the check
by orders of magnitude. Each motion shakes the plate with an acceleration below g
normal to it, so the spheres ride on it (and slip on it where its sideways
acceleration passes mu g): their positions are the plate's, and their trajectories
follow from its motion alone, without chaos.

The tolerance. LIGGGHTS moves the mesh each step by v(dTAbs) dt with dTAbs the sum of
the steps' dt; the migrated wall moves by its rate variable evaluated at the same step,
v(time - t0) dt, the same formula, time - t0 = k dt equal to that sum to rounding
(k eps t), so the two walls' displacements agree to the rounding of their sums: each
of the MOVE = 10^4 steps rounds the plate's coordinates (0.1 m) by eps, 2e-17 m, so
2e-13 m at the end, 4e-11 of R. The plate is a plane in both (two flat triangles; no
facetting of a curved surface), and a static mesh wall of wall/rigid equals LIGGGHTS's to 1e-9 relative
(test_mesh_wall). A sphere riding on the plate follows a wall-position error delta
with its contact spring, so its own error is of the order of delta plus the contact
model's 1e-9 relative: TOL = 1e-8 relative (positions against R, velocities against
1 m/s, spins against 1/R) leaves a factor 10 over the mesh contact's agreement, and is
1e5 times smaller than the control's disagreement.

On a turning plate (riggle, vibrot, a rotation made while a translation runs,
`linear_rotate`, whose origin the translation carries, a translation made while a
rotation runs, `rotate_linear`, whose origin stays in space, and two rotations at once,
`rotate_spin`, the second about an origin the first carries) that holds for the motion,
checked without friction
(`_mu0`: the normal contact alone, no tangential history). With friction the contact
models differ on a turning wall, apart from the motion: wall/rigid carries a contact's
shear history with the wall's frame where LIGGGHTS projects it onto the new tangent
plane (docs/conventions.md, *LIGGGHTS Hertz wall model*), and takes the wall's velocity
at the contact point within the overlap where LIGGGHTS interpolates it at the mesh's
surface, a tangential velocity difference of omega delta/2 (omega at most 2.2 rad/s here,
delta about 1 micrometre: 1e-6 m/s) that the sticking spheres' shear history integrates.
Measured 1e-5 relative (riggle) and 1e-6 (vibrot) over the run: TOL_TURNING = 1e-3
bounds that difference, and a time origin off by SETTLE dt (the control) is out by 0.1.

Shear: `zplane ... shear x V` is wall/rigid's surface_vel V 0 0 on the same plane (a
primitive wall: an exact plane in both), checked to the same TOL.
"""
import os
import re
import subprocess

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
SETTLE, MOVE, EVERY = 2000, 10000, 100
TOL = 1e-8
# The turning plates (riggle, vibrot) run twice: without friction to TOL, with friction
# (mu 0.5) to TOL_TURNING, the contact model's difference on a turning wall.
TURNING = ("riggle", "vibrot", "linear_rotate", "rotate_linear", "rotate_spin")
TOL_TURNING = 1e-3
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
BOX = (-0.15, 0.15, -0.15, 0.15, -0.05, 0.1)
SPHERES = ((0.04, 0.0), (-0.03, 0.03))
# style: the move/mesh lines (after the settling run), and the plate's largest
# displacement normal to it at the spheres (m), for the checks that they ride on it.
CASES = {
    "wiggle": (["fix mv all move/mesh mesh plate wiggle amplitude 5e-4 0 3e-4 period 0.05"],
               3e-4),
    "viblin": (["fix mv all move/mesh mesh plate viblin axis 1 0 1 order 2 amplitude 2e-4 "
                "1e-4 phase 0.3 1.1 period 0.05 0.025"], 1e-4),
    "riggle": (["fix mv all move/mesh mesh plate riggle origin 0.01 0 0 axis 0 1 0 period "
                "0.1 amplitude 2"], 0.04 * 0.0349),
    "vibrot": (["fix mv all move/mesh mesh plate vibrot origin 0.01 0.005 0 axis 1 1 0 "
                "order 1 amplitude 0.02 phase 0.2 period 0.1"], 2 * 0.02 * 0.046),
    "superposed": (["fix mv1 all move/mesh mesh plate linear 0.02 0 0",
                    "fix mv2 all move/mesh mesh plate wiggle amplitude 0 0 3e-4 period 0.05"],
                   3e-4),
    # a rotation made while a translation runs turns about an origin the translation
    # carries: the plate tilts about the line through (0.01 + 0.02 t, *, 0) along y
    "linear_rotate": (["fix mv1 all move/mesh mesh plate linear 0.02 0 0",
                       "fix mv2 all move/mesh mesh plate rotate origin 0.01 0 0 axis 0 1 0 "
                       "period 20"], 1e-3),
    # a translation made while a rotation runs, the rotation first among the movers: the
    # plate tilts about the line through (0.01, *, 0) fixed in space, and the translation
    # made so far turns with it (wall/rigid's rotate ... centre fixed)
    "rotate_linear": (["fix mv1 all move/mesh mesh plate rotate origin 0.01 0 0 axis 0 1 0 "
                       "period 20",
                       "fix mv2 all move/mesh mesh plate linear 0.02 0 0"], 1e-3),
    # two rotations at once: the plate tilts about y through (0.01, *, 0), and about x
    # through (*, 0.02, 0), a point the first rotation carries, the axis keeping its
    # direction in space (wall/rigid's rotate and spin)
    "rotate_spin": (["fix mv1 all move/mesh mesh plate rotate origin 0.01 0 0 axis 0 1 0 "
                     "period 20",
                     "fix mv2 all move/mesh mesh plate rotate origin 0 0.02 0 axis 1 0 0 "
                     "period 30"], 1e-3),
}


def plate_stl():
    h = 0.1
    a, b, c, d = (-h, -h, 0.0), (h, -h, 0.0), (h, h, 0.0), (-h, h, 0.0)
    return L.stl_text([(a, b, c), (a, c, d)], "plate")


def deck(moves, tag, wall=None, mu=0.5):
    d = L.header(BOX, DT, mu=mu)
    for i, (x, y) in enumerate(SPHERES, 1):
        d += L.sphere(i, (x, y, R), R, RHO)
    d += "fix grav all gravity 9.81 vector 0 0 -1\n"
    if wall is None:
        d += ("fix plate all mesh/surface file plate.stl type 2\n"
              "fix walls all wall/gran model hertz tangential history mesh n_meshes 1 "
              "meshes plate\n")
    else:
        d += wall + "\n"
    d += "fix integr all nve/sphere\n"
    d += "run %d\n" % SETTLE
    d += "".join(m + "\n" for m in moves)
    d += L.dump_lines("d", EVERY, tag + ".dump")
    d += "run %d\n" % MOVE
    return d


def migrate(s, tag, text):
    """The deck as rigidsurf-migrate rewrites it, and its exit status."""
    path = s.write(tag + ".stock", text)
    p = subprocess.run([MIGRATE, path], capture_output=True, text=True, timeout=60)
    return p.stdout, p.returncode, p.stderr


def stock(s, tag, text):
    s.write(tag + "_stock.in", text)
    env = dict(os.environ)
    env.update(L.MPI_ENV)
    p = subprocess.run([L.STOCK_LIGGGHTS, "-in", tag + "_stock.in", "-log", tag + ".log",
                        "-echo", "none"], cwd=s.dir, capture_output=True, text=True,
                       errors="replace", timeout=300, env=env)
    ok = s.ck.check(tag + ": stock LIGGGHTS runs the deck", p.returncode == 0,
                    why="\n".join((p.stdout + p.stderr).splitlines()[-8:]))
    if not ok:
        raise L.RunError(tag)


def compare(s, tag, text_stock, text_rigid, normal_amp):
    stock(s, tag + "_ref", text_stock)
    s.run(tag + "_rigid", text_rigid)
    fb = L.read_dump(s.path(tag + "_ref.dump"))
    fa = L.read_dump(s.path(tag + "_rigid.dump"))
    zr = max(max(f[i]["z"] for _, f in fb) - min(f[i]["z"] for _, f in fb) for i in fb[0][1])
    moved = max(abs(f[i]["x"] - fb[0][1][i]["x"]) + abs(f[i]["y"] - fb[0][1][i]["y"])
                for _, f in fb for i in f)
    s.ck.check(tag + ": LIGGGHTS's plate carries the spheres",
               (zr > 0.5 * normal_amp) if normal_amp else moved > R / 10,
               "largest z range %.3g m, largest sideways travel %.3g m" % (zr, moved))
    s.ck.check(tag + ": the spheres stay on the plate (z within R/10 of R)",
               all(abs(f[i]["z"] - R) < R / 10 + normal_amp for _, f in fb for i in f))
    worst = L.compare_frames(fa, fb, SCALES)
    if not s.ck.check(tag + ": same frames and atoms", worst is not None,
                      "%d vs %d frames" % (len(fa), len(fb))):
        return None
    fld, (d, step, i) = max(worst.items(), key=lambda kv: kv[1][0])
    return d, "worst %s rel %.3g at step %d atom %d" % (fld, d, step, i)


def body(s):
    s.write("plate.stl", plate_stl())
    runs = [(style, moves, amp, 0.5, TOL) for style, (moves, amp) in CASES.items()]
    runs += [(style + "_mu0", CASES[style][0], CASES[style][1], 0.0, TOL)
             for style in TURNING]
    for tag, moves, amp, mu, tol in runs:
        if tag in TURNING:
            tol = TOL_TURNING
        text = deck(moves, tag + "_ref", mu=mu)
        rigid, rc, err = migrate(s, tag, text)
        s.ck.check(tag + ": the tool translates the deck (exit 0)", rc == 0, err.strip())
        rigid = rigid.replace(tag + "_ref.dump", tag + "_rigid.dump")
        got = compare(s, tag, text, rigid, amp)
        if got:
            s.ck.check(tag + ": trajectories equal stock LIGGGHTS's to %g" % tol,
                       got[0] <= tol, got[1])
        if tag == "wiggle":
            # the control: the same migrated deck with its time origin at 0
            wrong = re.sub(r"\$\(time\)", "0", rigid).replace("wiggle_rigid", "wrong_rigid")
            s.run("wrong_rigid", wrong)
            fa = L.read_dump(s.path("wrong_rigid.dump"))
            fb = L.read_dump(s.path("wiggle_ref.dump"))
            worst = L.compare_frames(fa, fb, SCALES)
            d = max(v[0] for v in worst.values()) if worst else 0.0
            s.ck.check("control: the wiggle with its time origin at 0 (WRONG_T0) is out by "
                       "more than 1e5 TOL", d > 1e5 * TOL, "worst rel %.3g" % d)
        if tag == "rotate_linear_mu0":
            # the control: the same migrated deck with the rotation's centre carried by
            # the translation, as when the rotation comes after it
            ok = s.ck.check("rotate_linear: the tool keeps the rotation's centre fixed",
                            "centre fixed" in rigid,
                            " ".join(ln.strip() for ln in rigid.splitlines()
                                     if "omega v_rs_" in ln))
            if ok:
                moving = rigid.replace(" centre fixed", "").replace("rotate_linear_mu0_rigid",
                                                                     "moving_rigid")
                s.run("moving_rigid", moving)
                worst = L.compare_frames(L.read_dump(s.path("moving_rigid.dump")),
                                         L.read_dump(s.path(tag + "_ref.dump")), SCALES)
                d = max(v[0] for v in worst.values()) if worst else 0.0
                s.ck.check("control: rotate_linear with the centre moving with the translation "
                           "is out by more than 1e5 TOL", d > 1e5 * TOL, "worst rel %.3g" % d)
    # shear of a primitive plane: LIGGGHTS's wall velocity, wall/rigid's surface_vel
    shear_wall = ("fix floor all wall/gran model hertz tangential history primitive type 2 "
                  "zplane 0 shear x 0.05")
    text = deck([], "shear_ref", shear_wall)
    rigid, rc, err = migrate(s, "shear", text)
    s.ck.check("shear: the tool translates the deck (exit 0) into surface_vel",
               rc == 0 and "surface_vel 0.05 0 0" in rigid, err.strip())
    rigid = rigid.replace("shear_ref.dump", "shear_rigid.dump")
    got = compare(s, "shear", text, rigid, 0.0)
    if got:
        s.ck.check("shear: trajectories equal stock LIGGGHTS's to %g" % TOL, got[0] <= TOL,
                   got[1])


SES = L.Session(__doc__)
MIGRATE = os.environ.get("RS_MIGRATE") or os.path.join(os.path.dirname(SES.exe), "..",
                                                       "rigidsurf-migrate")
if __name__ == "__main__":
    L.main_guard(SES, body)
