#!/usr/bin/python3
"""Decks whose walls other commands name, run by stock LIGGGHTS as written and by
liggghts-rigidsurf as rigidsurf-migrate rewrites them: what the deck reads and writes is
the same (docs/migration.md, "What names a wall").

Each deck prints its values every PRINT steps (`V step values...`, through variables and
thermo) and dumps its spheres; the migrated deck must print the same values at the same
steps and dump the same trajectories, to TOL relative (the walls are flat STL plates and
planes, where wall/rigid's contacts are LIGGGHTS's to rounding: test_mesh_wall).

- servo: a mesh/surface/stress/servo plate (com off the plate's origin) presses a sphere
  onto a floor; the deck reads the plate's force f_plate[1-3], its torque about com
  f_plate[4-6], its centre f_plate[7-9] and the servo's f_plate[10-12] (wall/rigid's
  force, moment moved to com, and com plus the translation).
- unfix: a sphere rests on a stress mesh; `unfix w` then `unfix m` (each wall/rigid
  unfixed once), and the sphere falls through in both runs at the same step.
- dumps: four plates of one wall/gran, one moved by move/mesh, written by
  `dump mesh/stl`: the plates stay LIGGGHTS meshes for the dump, their walls wall/rigid
  (the STL files equal, byte for byte); each plate's open rim is one INFO line of the
  rigidsurf run, and no WARNING.
- stress: a piston (mesh/surface/stress moved by move/mesh) whose `dump mesh/vtk` writes
  its stress: the wall's vtk, at the dump's steps; the piston's force f_piston[3] read.
- local: `compute wall/gran/local` on the mesh wall: that wall stays LIGGGHTS's (exit
  3), a plane migrates, and the deck runs.
- frictionless: `model hertz` without `tangential` (no friction in LIGGGHTS): a
  sphere slides on as in stock.
- include: the walls in an included file, placed by `$(-2^2*0.001)` (+0.004 by
  LIGGGHTS's rules), run in a loop of `label`, `next`, `jump`; `fix_modify energy yes`
  of the mesh wall/gran: pe the same.
"""
import os
import re
import subprocess

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1e-5
TOL = 1e-9
PRINT = 50
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.1)
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
MODEL = "model hertz tangential history"


def plate(z, half=0.04, x0=0.0):
    return L.stl_text([((x0 - half, -half, z), (x0 + half, -half, z), (x0 + half, half, z)),
                       ((x0 - half, -half, z), (x0 + half, half, z), (x0 - half, half, z))])


def head(extra=""):
    return L.header(BOX, DT) + extra


def printer(values, fid="pr"):
    """Prints V step and values every PRINT steps (fix print substitutes at each)."""
    out = "".join("variable %s%d equal %s\n" % (fid, k, v) for k, v in enumerate(values))
    return out + "fix %s all print %d \"V $(step) %s\"\n" % (
        fid, PRINT, " ".join("${%s%d}" % (fid, k) for k in range(len(values))))


def migrate(s, tag, text):
    path = s.write(tag + ".stock.in", text)
    p = subprocess.run([MIGRATE, path], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def stock(s, tag, text):
    s.write(tag + "_stock.in", text)
    env = dict(os.environ)
    env.update(L.MPI_ENV)
    p = subprocess.run([L.STOCK_LIGGGHTS, "-in", tag + "_stock.in", "-log", tag + "_stock.log",
                        "-echo", "none"], cwd=s.dir, capture_output=True, text=True,
                       errors="replace", timeout=300, env=env)
    if not s.ck.check(tag + ": stock LIGGGHTS runs the deck", p.returncode == 0,
                      why="\n".join((p.stdout + p.stderr).splitlines()[-8:])):
        raise L.RunError(tag)
    return p.stdout


def values(out):
    return {int(float(l.split()[1])): [float(x) for x in l.split()[2:]]
            for l in out.splitlines() if l.startswith("V ")}


def run_pair(s, tag, text, want_rc=0, tol=TOL, upto=None):
    """Stock and migrated runs of text; their V lines and dumps compared to tol relative
    (up to step upto, when given). Returns the migrated deck, and the stock and
    rigidsurf outputs."""
    rc, rigid, err = migrate(s, tag, text)
    s.ck.check(tag + ": the tool migrates the deck (exit %d)" % want_rc, rc == want_rc,
               err.strip().splitlines()[-1] if err.strip() else "", err)
    a = stock(s, tag, text.replace("DUMP", tag + "_stock.dump"))
    _, b = s.run(tag + "_rigid", rigid.replace("DUMP", tag + "_rigid.dump"))
    va, vb = values(a), values(b)
    if upto is not None:
        va = {k: v for k, v in va.items() if k <= upto}
        vb = {k: v for k, v in vb.items() if k <= upto}
    worst = 0.0
    for st in va:
        for x, y in zip(va[st], vb.get(st, [])):
            worst = max(worst, abs(x - y) / max(abs(x), abs(y), 1e-6))
    s.ck.check(tag + ": the values the deck reads are stock's at every printed step (%g)"
               % tol, va and sorted(va) == sorted(vb) and worst <= tol,
               "%d steps, worst rel %.3g" % (len(va), worst),
               "steps %s vs %s" % (sorted(va)[:5], sorted(vb)[:5]))
    fa = L.read_dump(s.path(tag + "_rigid.dump"))
    fb = L.read_dump(s.path(tag + "_stock.dump"))
    if upto is not None:
        fa, fb = ([f for f in x if f[0] <= upto] for x in (fa, fb))
    L.check_trajectories(s, tag, fa, fb, SCALES, tol)
    return rigid, a, b


def servo(s):
    s.write("plate.stl", plate(0.0106137))
    text = head() + L.sphere(1, (0.003, 0.0, R + 0.0001), R, RHO)
    text += "fix floor all wall/gran %s primitive type 2 zplane 0\n" % MODEL
    text += ("fix plate all mesh/surface/stress/servo file plate.stl type 2 com 0.01 0 0.0106137 "
             "ctrlPV force axis 0 0 1 target_val -0.5 vel_max 0.05 kp 0.5\n"
             "fix wp all wall/gran %s mesh n_meshes 1 meshes plate\n" % MODEL)
    text += "fix integr all nve/sphere\n" + printer(
        ["f_plate[3]", "f_plate[4]", "f_plate[5]", "f_plate[9]", "f_plate[12]",
         "f_plate[7]+f_plate[8]"])
    text += L.dump_lines("d", PRINT, "DUMP") + "run 4000\n"
    rigid, a, _ = run_pair(s, "servo", text)
    v = values(a)
    last = v[max(v)]
    s.ck.check("servo: the plate pressed the sphere and turned nothing (torque about com "
               "nonzero)", last[0] > 0.1 and abs(last[2]) > 1e-4,
               "force %.3g N, torque y %.3g N m" % (last[0], last[2]))


def unfix(s):
    s.write("floor.stl", plate(0.0))
    text = head() + L.sphere(1, (0.0, 0.0, R + 0.0002), R, RHO)
    text += ("fix fm all mesh/surface/stress file floor.stl type 2\n"
             "fix w all wall/gran %s mesh n_meshes 1 meshes fm\n" % MODEL)
    text += "fix grav all gravity 9.81 vector 0 0 -1\nfix integr all nve/sphere\n"
    text += printer(["z[1]", "f_fm[3]"]) + L.dump_lines("d", PRINT, "DUMP")
    text += "run 1500\nunfix pr\nunfix w\nunfix fm\n" + printer(["z[1]"], "pz")
    text += "run 1500\n"
    rigid, a, _ = run_pair(s, "unfix", text)
    s.ck.check("unfix: wall/rigid fm is unfixed once", rigid.count("unfix fm") == 1 and
               "unfix w\n" not in rigid, rigid)
    v = values(a)
    s.ck.check("unfix: the sphere falls through the floor once it is gone",
               v[1450][0] > 0.99 * R and v[max(v)][0] < 0.9 * R, "z %.3g then %.3g" % (
                   v[1450][0], v[max(v)][0]))


def dumps(s):
    for k in range(4):
        s.write("pl%d.stl" % k, plate(0.0, 0.02, -0.06 + 0.04 * k))
    text = head() + "".join(L.sphere(k + 1, (-0.06 + 0.04 * k, 0.0, R + 0.0002 * (k + 1)),
                                     R, RHO, v=(0.05, 0, -0.1)) for k in range(4))
    text += "".join("fix pl%d all mesh/surface file pl%d.stl type 2\n" % (k, k)
                    for k in range(4))
    text += "fix wa all wall/gran %s mesh n_meshes 4 meshes pl0 pl1 pl2 pl3\n" % MODEL
    text += "fix mv all move/mesh mesh pl3 linear 0 0 0.02\n"
    text += "fix grav all gravity 9.81 vector 0 0 -1\nfix integr all nve/sphere\n"
    text += "dump stl all mesh/stl 500 DUMP_*.stl\n"
    text += printer(["z[1]", "z[4]"]) + L.dump_lines("d", PRINT, "DUMP") + "run 2000\n"
    rigid, a, b = run_pair(s, "dumps", text)
    s.ck.check("dumps: four walls under IDs of their own, the plates kept for the dump",
               all("fix rs_pl%d all wall/rigid" % k in rigid and
                   "fix pl%d all mesh/surface" % k in rigid for k in range(4)), rigid)
    same, n = True, 0
    for st in range(0, 2001, 500):
        fa, fb = (s.path("dumps_%s.dump_%d.stl" % (t, st)) for t in ("stock", "rigid"))
        if os.path.exists(fa):
            n += 1
            same &= os.path.exists(fb) and open(fa).read() == open(fb).read()
    s.ck.check("dumps: the STL files of the four plates are stock's, byte for byte", n == 5
               and same, "%d files" % n)
    log = open(s.path("dumps_rigid.log")).read()
    s.ck.check("dumps: each plate's open rim is one INFO line, no WARNING about it",
               log.count("INFO: fix wall/rigid rs_pl") == 4 and "open boundary" not in
               "".join(l for l in log.splitlines(True) if "WARNING" in l), "")


def stress(s):
    s.write("piston.stl", plate(0.0102237, 0.05))
    text = head() + L.sphere(1, (0.0, 0.0, R + 0.0001), R, RHO)
    text += "fix floor all wall/gran %s primitive type 2 zplane 0\n" % MODEL
    text += ("fix piston all mesh/surface/stress file piston.stl type 2\n"
             "fix pw all wall/gran %s mesh n_meshes 1 meshes piston\n"
             "fix pm all move/mesh mesh piston linear 0 0 -0.01\n" % MODEL)
    text += "fix integr all nve/sphere\n" + printer(["f_piston[3]", "f_piston[9]"])
    text += "dump dm all mesh/vtk 500 DUMP_*.vtk id stress vel\n"
    text += L.dump_lines("d", PRINT, "DUMP") + "run 2500\nunfix pm\nrun 500\n"
    # 1e-8: stock's piston sums its steps (z - z0 = -1.238000000000002e-4 at step 1238),
    # wall/rigid's pose is exact, which moves the first contact's force by 2e-9
    rigid, a, b = run_pair(s, "stress", text, tol=1e-8, upto=2500)
    va, vb = values(a), values(b)
    after = max(abs(va[k][0] - vb[k][0]) / abs(va[k][0]) for k in va if k > 2500)
    s.ck.check("stress: after the piston stops (unfix of its move/mesh between runs), its "
               "force stays within 1e-3 of stock's (the setup's half step: docs/migration.md)",
               after < 1e-3, "largest relative difference %.2g" % after)
    steps = lambda t: sorted(int(re.search(r"_(\d+)\.vtk", f).group(1)) for f in os.listdir(
        s.dir) if f.startswith("stress_%s.dump_" % t) and f.endswith(".vtk"))  # noqa: E731
    s.ck.check("stress: the wall's vtk is written at the dump's steps",
               steps("rigid") and steps("rigid") == steps("stock"),
               "%s vs %s" % (steps("rigid"), steps("stock")))
    s.ck.check("stress: the piston pressed the sphere", max(v[0] for v in va.values()) > 0.1,
               "largest force %.3g N" % max(v[0] for v in va.values()))


def local(s):
    s.write("l0.stl", plate(0.0, 0.03, -0.05))
    s.write("l1.stl", plate(0.0, 0.03, 0.05))
    text = head() + L.sphere(1, (-0.05, 0, R + 0.0002), R, RHO) + \
        L.sphere(2, (0.05, 0, R + 0.0002), R, RHO)
    text += ("fix l0 all mesh/surface file l0.stl type 2\n"
             "fix l1 all mesh/surface file l1.stl type 2\n"
             "fix w0 all wall/gran %s mesh n_meshes 2 meshes l0 l1\n"
             "compute cl all wall/gran/local id force\n"
             "fix roof all wall/gran %s primitive type 2 zplane 0.08\n" % (MODEL, MODEL))
    text += "fix grav all gravity 9.81 vector 0 0 -1\nfix integr all nve/sphere\n"
    text += printer(["z[1]", "z[2]"]) + L.dump_lines("d", PRINT, "DUMP") + "run 1500\n"
    rigid, _, _ = run_pair(s, "local", text, want_rc=3)
    s.ck.check("local: the wall the compute reads stays LIGGGHTS's, the other migrates",
               "fix w0 all wall/gran" in rigid and "fix l0 all mesh/surface" in rigid and
               "fix roof all wall/rigid" in rigid, rigid)


def include(s):
    s.write("floor.stl", plate(0.0))
    s.write("in.walls", "fix fl all mesh/surface file floor.stl type 2 move 0 0 "
            "$(-2^2*0.001)\nfix w all wall/gran %s mesh n_meshes 1 meshes fl\n"
            "fix_modify w energy yes\n" % MODEL)
    text = head() + L.sphere(1, (0.0, 0.0, 0.004 + R + 0.0005), R, RHO, v=(0.02, 0, 0))
    text += "include in.walls\n"
    text += "fix grav all gravity 9.81 vector 0 0 -1\nfix integr all nve/sphere\n"
    text += printer(["z[1]", "ke"]) + L.dump_lines("d", PRINT, "DUMP")
    text += "variable i loop 3\nlabel again\nrun 500\nnext i\njump SELF again\n"
    rigid, a, _ = run_pair(s, "include", text)
    v = values(a)
    s.ck.check("include: the sphere rests on the floor LIGGGHTS placed at +0.004 "
               "(-2^2 is 4)", abs(v[max(v)][0] - (0.004 + R)) < 0.0006 and max(v) == 1500,
               "z %.6g at step %d" % (v[max(v)][0], max(v)))
    s.ck.check("include: the included walls stand in the deck, migrated",
               "include in.walls" not in rigid.replace("rigidsurf-migrate: include", "")
               and "fix fl all wall/rigid" in rigid and "fix_modify fl energy yes" in rigid,
               rigid)


def frictionless(s):
    """`model hertz` without `tangential`: LIGGGHTS's selector takes no tangential model,
    so a sphere slides on without friction (friction 0.5 is set)."""
    text = head() + L.sphere(1, (0.0, 0.0, R + 0.0001), R, RHO, v=(0.2, 0.0, 0.0))
    text += "fix floor all wall/gran model hertz primitive type 2 zplane 0\n"
    text += "fix grav all gravity 9.81 vector 0 0 -1\nfix integr all nve/sphere\n"
    text += printer(["vx[1]"]) + L.dump_lines("d", PRINT, "DUMP") + "run 2000\n"
    rigid, a, _ = run_pair(s, "frictionless", text)
    v = values(a)
    s.ck.check("frictionless: law liggghts with the words as written, and the sphere slides "
               "on at 0.2 m/s", "law liggghts model hertz type 2" in rigid.replace(
                   " &\n    ", " ") and abs(v[max(v)][0] - 0.2) < 1e-9, "vx %.12g" % v[max(v)][0])


def body(s):
    for case in (servo, unfix, dumps, stress, local, include, frictionless):
        try:
            case(s)
        except L.RunError:
            pass


if __name__ == "__main__":
    SES = L.Session(__doc__)
    MIGRATE = os.environ.get("RS_MIGRATE") or os.path.join(os.path.dirname(SES.exe), "..",
                                                           "rigidsurf-migrate")
    L.main_guard(SES, body)
