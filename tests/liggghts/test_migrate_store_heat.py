#!/usr/bin/python3
"""`fix wall/gran ... store_force yes` and a wall's `temperature` under `fix heat/gran`,
run by LIGGGHTS's own walls and as rigidsurf-migrate rewrites them (wall/rigid's
`store_force` and `conduction liggghts`), in the same executable.

store_force: LIGGGHTS keeps the wall's force on each particle in the per-atom vector
force_ID (FixWallGran::post_create), which a deck dumps as f_force_ID[1..3]. Each deck
drops spheres obliquely, spinning, onto the wall: a primitive zplane (wall/rigid with the
same ID), and one wall/gran over two STL plates (two wall/rigid fixes adding into the
wall/gran's force_ID). The dumped stored forces, with the trajectories, must equal
LIGGGHTS's to TOL relative (forces against the sphere's weight at least).

Heat: a sphere (R = 5 mm, c = 10 J/(kg K), conductivity 1000 against the wall's 5000)
resting on a wall at 400 K, starting at 300 K; fix heat/gran integrates its temperature
from the wall's conduction (fix_wall_gran.cpp, addHeatFlux: A = pi (R^2 - (R - delta)^2),
h = 4 k_p k_w / (k_p + k_w) sqrt(A)). Resting under gravity the overlap is about 2 um,
so h is about 0.9 W/K and m c / h about 15 ms: over the 30 ms of the run the sphere gains
tens of kelvin. Its temperature must equal LIGGGHTS's to TOL relative at every dumped step,
on a primitive plane, on an STL plate, with heat/gran/conduction's area correction
(youngsModulusOriginal: the overlap scaled by (Y*/Y*_orig)^(2/3)), and beside a model
only law liggghts has (rolling friction cdt). On the plane, the heat out of the wall
(its global output 14) equals the heat the sphere gained, m c (T - T0): the flux leaves
the wall as it enters the sphere.

TOL = 1e-9: the contact's overlap agrees with LIGGGHTS's to rounding on a plane (the
trajectories of test_wall_equivalence and test_mesh_wall, 1e-15), and the flux is the
same formula of it; the measured differences are reported.
"""
import os
import subprocess

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
TOL = 1e-9
BOX = (-0.1, 0.1, -0.1, 0.1, -0.05, 0.1)
MASS = RHO * 4.0 / 3.0 * 3.141592653589793 * R ** 3
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
HEAT_PROPS = ("fix ftco all property/global thermalConductivity peratomtype 1000 5000\n"
              "fix ftca all property/global thermalCapacity peratomtype 10 10\n")


def plate(x0, x1):
    h = 0.05
    a, b, c, d = (x0, -h, 0.0), (x1, -h, 0.0), (x1, h, 0.0), (x0, h, 0.0)
    return L.stl_text([(a, b, c), (a, c, d)], "plate")


def migrate(s, tag, text):
    path = s.write(tag + ".stock", text)
    p = subprocess.run([MIGRATE, path], capture_output=True, text=True, timeout=60)
    s.ck.check(tag + ": the tool translates the deck (exit 0)", p.returncode == 0,
               p.stderr.strip())
    return p.stdout


def pair(s, tag, text, scales, more=""):
    """Runs the stock deck and the migrated one (with the lines more after it); checks
    the dumped columns against each other, returns the reference's frames and the
    migrated run's output."""
    rigid = migrate(s, tag, text).replace(tag + "_ref.dump", tag + "_rigid.dump")
    s.run(tag + "_ref", text)
    out = s.run(tag + "_rigid", rigid + more)[1]
    fb = L.read_dump(s.path(tag + "_ref.dump"))
    fa = L.read_dump(s.path(tag + "_rigid.dump"))
    L.check_trajectories(s, tag, fa, fb, scales, TOL)
    return fb, out


def store_deck(tag, walls, spheres, fid, after=""):
    d = L.header(BOX, DT)
    for i, (x, v) in enumerate(spheres, 1):
        d += L.sphere(i, (x, 0.0, R + 2e-4), R, RHO, v=v, omega=(0, 30.0, -20.0))
    d += "fix grav all gravity 9.81 vector 0 0 -1\n" + walls
    d += "fix integr all nve/sphere\n"
    d += L.dump_lines("d", 5, tag + "_ref.dump", L.DUMP_COLS + " f_force_%s[1] "
                      "f_force_%s[2] f_force_%s[3]" % (fid, fid, fid))
    d += "run 2000\n" + after
    return d


def heat_deck(tag, wall, heat="heat/gran initial_temperature 300", extra=""):
    d = L.header(BOX, DT, extra_props=HEAT_PROPS + extra)
    d += L.sphere(1, (0.0, 0.0, R), R, RHO)
    d += "fix grav all gravity 9.81 vector 0 0 -1\n"
    d += "fix heat all %s\n" % heat
    d += wall + "\n"
    d += "fix integr all nve/sphere\n"
    d += L.dump_lines("d", 100, tag + "_ref.dump", L.DUMP_COLS + " f_Temp[0] f_heatFlux[0]")
    d += "run 3000\n"
    return d


def body(s):
    s.write("p1.stl", plate(-0.05, 0.0))
    s.write("p2.stl", plate(0.0, 0.05))
    s.write("plate.stl", plate(-0.05, 0.05))
    fsc = dict(SCALES)
    for fid in ("floor", "w"):
        for c in (1, 2, 3):
            fsc["f_force_%s[%d]" % (fid, c)] = MASS * 9.81
    # store_force on a primitive plane
    sc = {k: v for k, v in fsc.items() if "_w[" not in k}
    text = store_deck("store_plane", "fix floor all wall/gran model hertz tangential history "
                      "primitive type 2 zplane 0 store_force yes\n",
                      [(0.0, (0.3, 0.1, -0.5))], "floor")
    fb = pair(s, "store_plane", text, sc)[0]
    peak = max(abs(f[1]["f_force_floor[3]"]) for _, f in fb)
    s.ck.check("store_plane: LIGGGHTS stored the wall's force (peak above the weight)",
               peak > 2 * MASS * 9.81, "peak Fz %.3g N" % peak)
    # store_force of one wall/gran over two meshes: both walls add into force_w
    sc = {k: v for k, v in fsc.items() if "_floor[" not in k}
    walls = ("fix p1 all mesh/surface file p1.stl type 2\n"
             "fix p2 all mesh/surface file p2.stl type 2\n"
             "fix w all wall/gran model hertz tangential history mesh n_meshes 2 meshes "
             "p1 p2 store_force yes\n")
    # then the wall goes (its meshes' walls, the last first, and force_w with them) and
    # the deck runs on
    text = store_deck("store_meshes", walls, [(-0.025, (0.2, 0.0, -0.4)),
                                              (0.025, (-0.1, 0.2, -0.6))], "w",
                      "undump d\nunfix w\nrun 10\n")
    fb = pair(s, "store_meshes", text, sc)[0]
    touched = [max(abs(f[i]["f_force_w[3]"]) for _, f in fb) for i in (1, 2)]
    s.ck.check("store_meshes: LIGGGHTS stored each mesh's force on its sphere",
               min(touched) > 2 * MASS * 9.81, "peaks %.3g %.3g N" % tuple(touched))

    # conduction from a hot wall
    hsc = dict(SCALES)
    hsc["f_Temp[0]"] = 300.0
    hsc["f_heatFlux[0]"] = 1.0
    cases = {
        "heat_plane": heat_deck("heat_plane", "fix floor all wall/gran model hertz "
                                "tangential history primitive type 2 zplane 0 "
                                "temperature 400"),
        "heat_mesh": heat_deck("heat_mesh", "fix plate all mesh/surface file plate.stl "
                               "type 2 temperature 400\nfix w all wall/gran model hertz "
                               "tangential history mesh n_meshes 1 meshes plate"),
        "heat_area_correction": heat_deck(
            "heat_area_correction", "fix floor all wall/gran model hertz tangential "
            "history primitive type 2 zplane 0 temperature 400",
            "heat/gran/conduction initial_temperature 300 area_correction yes",
            "fix ymo all property/global youngsModulusOriginal peratomtype 5e9 2e10\n"),
        # contact_area: the conduction's area pi R^2, or a constant, in place of the
        # overlap's
        "heat_projection": heat_deck("heat_projection", "fix floor all wall/gran model hertz "
                                     "tangential history primitive type 2 zplane 0 "
                                     "temperature 400 contact_area projection"),
        "heat_constant": heat_deck("heat_constant", "fix plate all mesh/surface file "
                                   "plate.stl type 2 temperature 400\nfix w all wall/gran "
                                   "model hertz tangential history mesh n_meshes 1 meshes "
                                   "plate contact_area constant 2e-6"),
        # a model only law liggghts has (rolling friction): the conduction beside it
        "heat_liggghts": heat_deck(
            "heat_liggghts", "fix floor all wall/gran model hertz tangential history "
            "rolling_friction cdt primitive type 2 zplane 0 temperature 400",
            extra="fix rf all property/global coefficientRollingFriction peratomtypepair "
            "2 0.1 0.1 0.1 0.1\n"),
    }
    for tag, text in cases.items():
        fb, out = pair(s, tag, text, hsc, 'variable q equal f_floor[14]\nprint "HEATQ ${q}"\n'
                       if tag == "heat_plane" else "")
        t_end = fb[-1][1][1]["f_Temp[0]"]
        s.ck.check(tag + ": LIGGGHTS's wall heated the sphere by more than 10 K",
                   t_end > 310.0, "%.6f K at the end" % t_end)
        if tag == "heat_plane":
            # the heat that left the wall (held at 400 K) is the heat the sphere gained
            q = [float(l.split()[1]) for l in out.splitlines() if l.startswith("HEATQ")]
            want = -MASS * 10.0 * (t_end - 300.0)
            s.ck.check("heat_plane: the heat into the wall (f_ID[14]) is -m c (T - T0)",
                       q and L.rel_diff(q[-1], want, 0) <= TOL,
                       "%r vs %r J" % (q[-1] if q else None, want))
    # the area correction and contact_area change the answer: each run differs from
    # the plane's with the overlap's area
    a = L.read_dump(s.path("heat_plane_ref.dump"))[-1][1][1]["f_Temp[0]"]
    for tag in ("heat_area_correction", "heat_projection", "heat_constant"):
        b = L.read_dump(s.path(tag + "_ref.dump"))[-1][1][1]["f_Temp[0]"]
        s.ck.check("%s changes LIGGGHTS's heating (so it is tested)" % tag,
                   abs(a - b) > 1.0, "%.6f vs %.6f K" % (a, b))
    # the migrated decks carry the area
    for tag, want in (("heat_projection", "contact_area projection"),
                      ("heat_constant", "contact_area constant 2e-6")):
        with open(s.path(tag + "_rigid.in")) as f:
            text = f.read()
        walls = [ln for ln in text.replace(" &\n    ", " ").splitlines()
                 if "wall/rigid" in ln]
        s.ck.check(tag + ": the migrated wall/rigid has '%s'" % want,
                   walls and all(want in ln for ln in walls), "\n".join(walls))


SES = L.Session(__doc__)
MIGRATE = os.environ.get("RS_MIGRATE") or os.path.join(os.path.dirname(SES.exe), "..",
                                                       "rigidsurf-migrate")
if __name__ == "__main__":
    L.main_guard(SES, body)
