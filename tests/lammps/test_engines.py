#!/usr/bin/python3
"""fix wall/rigid in LAMMPS is fix wall/rigid in LIGGGHTS: the same deck gives the same
numbers in lmp-rigidsurf and in liggghts-rigidsurf.

The wall is one library object (include/rigidsurf/wall.h) under two adapters; LIGGGHTS's
is checked against LIGGGHTS's own walls (tests/liggghts/). Each deck here runs in both
engines with spheres that touch only the walls (LIGGGHTS: neigh_modify exclude type 1 1;
LAMMPS: pair_style none) and the same integration (fix nve/sphere, fix gravity), the
materials given as LIGGGHTS's fix property/global and as LAMMPS's keywords of the fix
line. Every dumped value (positions, velocities, spins, forces, torques, the fix's
per-atom array and stored force) every 100 steps, and each wall's global vector (18
values) every 10 steps, agree to 1e-9 relative (measured: bit for bit), and so do the
VTK files the walls write. The decks cover every surface kind and the fix's keywords:
- a REVOLUTION drum from a surface file, with fillets, turning (rotate), law hertz with
  the materials, peratom, store_force, vtk;
- a CYLINDER trough (inline, with a fillet), moving (move) and carrying a belt
  (surface_vel), law hooke with props;
- a SEGMENTS profile (inline), law linear_softening;
- a MESH box from an STL file (inline mesh), spun (spin), law hertz, wear finnie with
  k_finnie, vtk with the facets' stress and wear;
- a plane with a FRIC routine compiled from its Fortran source (law fric ... normal
  hertz), and with a UINTER (law uinter ... normal hertz) and a VUINTER (a linear
  penalty, the plane moving along itself) likewise;
- a plate driven by the servo to a target force on spheres resting on a floor, law hooke
  from the materials and characteristicVelocity.
"""
import math
import os

import lmplib as M

DT = 1.0e-5
HERE = os.path.dirname(os.path.abspath(__file__))
ROUTINES = os.path.join(HERE, "..", "liggghts", "routines")
FRIC = os.path.join(ROUTINES, "fric_coulomb.f")
UINTER = os.path.join(ROUTINES, "uinter_coulomb.f")
VUINTER = os.path.join(ROUTINES, "vuinter_facets.f")
YOUNG, POISSON, E, MU = (5e7, 2e8), (0.3, 0.25), 0.7, 0.5
LMP_MAT = ("youngsModulus %r %r poissonsRatio %r %r coefficientRestitution %r %r "
           "coefficientFriction %r %r" % (YOUNG + POISSON + (E, E, MU, MU)))
HERTZ_PROPS = "props 5e7 0.3 2e8 0.25 0.7 0.5 0"
PLANE_DOWN = ("*SURFACE, TYPE=CYLINDER, NAME=plate\n0, 0, %r, 1, 0, %r\n0, 1, %r\n"
              "START, -1, 0\nLINE, 1, 0\n")


def header(engine, box, extra_lig=""):
    if engine == "liggghts":
        return M.L.header(box, DT, young=YOUNG, poisson=POISSON, e=E, mu=MU,
                          extra_props=extra_lig) + "neigh_modify exclude type 1 1\n"
    return M.header(box, DT)


def sphere(engine, k, x, r, v=(0, 0, 0), w=(0, 0, 0)):
    if engine == "liggghts":
        return M.L.sphere(k, x, r, 2500.0, v, w)
    return M.sphere(k, x, r, 2500.0, v, w)


def dump(engine, tag, cols):
    if engine == "liggghts":
        return M.L.dump_lines("d", 100, tag + ".dump", cols=cols)
    return M.dump_lines("d", 100, tag + ".dump", cols=cols)


def drum_atoms(engine):
    d = ""
    for k, (deg, z) in enumerate(((-100, -0.006), (-90, 0.0), (-80, 0.006), (-95, -0.007),
                                   (-70, 0.003))):
        r = 0.05 - 0.002 - 1e-4
        d += sphere(engine, k + 1, (r * math.cos(math.radians(deg)),
                                    r * math.sin(math.radians(deg)), z), 0.002,
                    (0.1 * k, 0, 0), (0, 0, 20.0 - 10 * k))
    return d


def rain(engine, xs, y, z=0.0, r=0.002, gravity_y=True):
    """Spheres at x = xs, each at height y (or y(x)) above the floor of the case."""
    d = ""
    for k, x in enumerate(xs):
        h = y(x) if callable(y) else y
        p = (x, h, z) if gravity_y else (x, z, h)
        d += sphere(engine, k + 1, p, r, (0.05 * math.sin(k), 0, 0.02 * math.cos(k)),
                    (3.0 * k, -2.0, 1.0))
    return d


CASES = [
    {"name": "drum", "box": (-0.055, 0.055, -0.055, 0.055, -0.013, 0.013), "g": "0 -1 0",
     "files": {"drum.inp": open(os.path.join(HERE, "..", "..", "examples", "lammps_drum",
                                             "drum.inp")).read()},
     "atoms": drum_atoms, "steps": 4000,
     "walls": {"w": "surface drum.inp law hertz type 2 {MAT} peratom yes store_force yes "
                    "rotate origin 0 0 0 axis 0 0 1 omega 3 vtk {TAG}_drum_*.vtk 1000"},
     "cols": "f_w[1] f_w[2] f_w[3] f_w[4] f_w[5] f_w[6] f_force_w[1] f_force_w[2] "
             "f_force_w[3]", "vtk": ["drum_1000", "drum_4000"]},
    {"name": "trough", "box": (-0.05, 0.05, -0.01, 0.05, -0.02, 0.02), "g": "0 -1 0",
     "atoms": lambda e: rain(e, (-0.015, -0.005, 0.005, 0.015), 0.003), "steps": 3000,
     "walls": {"w": "surface inline cylinder a 0 0 0 b 1 0 0 c 0 0 1 fillet 0.005 profile "
                    "START -0.04 0.03 LINE -0.015 0 LINE 0.015 0 LINE 0.04 0.03 end "
                    "law hooke props 1e4 5e3 0.2 0.2 0.5 move linear 0.01 0 0 "
                    "surface_vel 0 0 0.05"}, "cols": ""},
    {"name": "segments", "box": (-0.05, 0.05, -0.01, 0.05, -0.01, 0.01), "g": "0 -1 0",
     "atoms": lambda e: rain(e, (-0.02, 0.0, 0.02), lambda x: 0.75 * abs(x) + 0.0035),
     "steps": 3000,
     "walls": {"w": "surface inline segments profile START -0.04 0.03 LINE 0 0 LINE 0.04 "
                    "0.03 end law linear_softening props 1e4"}, "cols": ""},
    {"name": "mesh", "box": (-0.04, 0.04, -0.04, 0.04, -0.04, 0.04), "g": "0 -1 0",
     "files": {"box.stl": M.L.stl_text(M.L.cube_triangles(0.03))},
     "lig_props": "fix m5 all property/global k_finnie peratomtypepair 2 1 1 1 1\n",
     "lmp_props": " k_finnie 1 1",
     "atoms": lambda e: rain(e, (-0.015, 0.0, 0.012), -0.0265, z=0.005), "steps": 3000,
     "walls": {"w": "surface inline mesh box.stl law hertz type 2 {MAT} wear finnie "
                    "spin origin 0 0 0 axis 0 0 1 omega 2 vtk {TAG}_box_*.vtk 1000"},
     "cols": "", "vtk": ["box_1000", "box_3000"]},
    {"name": "fric", "box": (-0.05, 0.05, -0.05, 0.05, -0.01, 0.05), "g": "0 0 -1",
     "files": {"floor.inp": M.L.plane_z(0.0)},
     "atoms": lambda e: rain(e, (-0.02, 0.0, 0.02), 0.00201, gravity_y=False), "steps": 2000,
     "walls": {"w": "surface floor.inp law fric %s normal hertz statev 1 %s 0.4 1e5"
                    % (FRIC, HERTZ_PROPS)}, "cols": ""},
    {"name": "uinter", "box": (-0.05, 0.05, -0.05, 0.05, -0.01, 0.05), "g": "0 0 -1",
     "files": {"floor.inp": M.L.plane_z(0.0)},
     "atoms": lambda e: rain(e, (-0.02, 0.0, 0.02), 0.00201, gravity_y=False), "steps": 2000,
     "walls": {"w": "surface floor.inp law uinter %s normal hertz statev 2 %s 0.4 5e3"
                    % (UINTER, HERTZ_PROPS)}, "cols": ""},
    {"name": "vuinter", "box": (-0.05, 0.05, -0.05, 0.05, -0.01, 0.05), "g": "0 0 -1",
     "files": {"floor.inp": M.L.plane_z(0.0)},
     "atoms": lambda e: rain(e, (-0.02, 0.0, 0.02), 0.00201, gravity_y=False), "steps": 2000,
     "walls": {"w": "surface floor.inp law vuinter %s props 1e3 0 move linear 0.01 0 0"
                    % VUINTER}, "cols": ""},
    {"name": "servo", "box": (-0.05, 0.05, -0.05, 0.05, -0.01, 0.05), "g": "0 0 -1",
     "files": {"floor.inp": M.L.plane_z(0.0), "plate.inp": PLANE_DOWN % (0.0045, 0.0045,
                                                                          0.0045)},
     "lig_props": "fix m5 all property/global characteristicVelocity scalar 0.5\n",
     "lmp_props": " characteristicVelocity 0.5",
     "atoms": lambda e: rain(e, (-0.02, 0.0, 0.02), 0.002, gravity_y=False), "steps": 3000,
     "walls": {"w": "surface floor.inp law hertz type 2 {MAT}",
               "p": "surface plate.inp law hooke type 2 {MAT} servo com 0 0 0.0045 ctrlPV "
                    "force axis 0 0 1 target_val -0.05 vel_max 0.05 kp 0.5"}, "cols": ""},
]


def deck(engine, case):
    tag = case["name"] + "_" + engine
    d = header(engine, case["box"], case.get("lig_props", ""))
    d += case["atoms"](engine)
    d += "fix grav all gravity 9.81 vector %s\n" % case["g"]
    mat = (LMP_MAT + case.get("lmp_props", "")) if engine == "lammps" else ""
    prints = []
    for wid, words in case["walls"].items():
        d += "fix %s all wall/rigid %s\n" % (wid, words.replace("{MAT}", mat)
                                              .replace("{TAG}", tag))
        prints += ["${%s%d}" % (wid, k) for k in range(1, 19)]
        d += "".join("variable %s%d equal f_%s[%d]\n" % (wid, k, wid, k) for k in range(1, 19))
    d += "fix integr all nve/sphere\n"
    d += dump(engine, tag, M.COLS + (" " + case["cols"] if case["cols"] else ""))
    d += 'fix pr all print 10 "%s" screen no file %s.tot\n' % (" ".join(prints), tag)
    d += "run %d\n" % case["steps"]
    return d


def body(s):
    os.environ["RIGIDSURF_CACHE"] = s.path("cache")
    for case in CASES:
        for f, text in case.get("files", {}).items():
            s.write(f, text)
        name = case["name"]
        s.run(name + "_liggghts", deck("liggghts", case), exe=s.args.liggghts)
        s.run(name + "_lammps", deck("lammps", case))
        fl = M.read_dump(s.path(name + "_liggghts.dump"))
        fm = M.read_dump(s.path(name + "_lammps.dump"))
        # LAMMPS's fix print also prints at the setup of the run (step 0), LIGGGHTS's not
        tl = M.read_table(s.path(name + "_liggghts.tot"))
        tm = M.read_table(s.path(name + "_lammps.tot"))[1:]
        touched = sum(1 for r in tl if any(r[18 * k + 6] > 0 for k in range(len(r) // 18)))
        s.ck.check("%s: the walls touched the spheres (at %d of %d outputs)"
                   % (name, touched, len(tl)), touched >= 5)
        M.L.check_trajectories(s, name, fm, fl, M.scales(0.002, force=1e-3, torque=1e-6),
                               1e-9, ref="LIGGGHTS's")
        worst = max((M.rel_diff(a, b, 1e-12) for ra, rb in zip(tm, tl) for a, b in zip(ra, rb)),
                    default=1.0)
        s.ck.check("%s: the global vectors equal LIGGGHTS's to 1e-9" % name,
                   len(tm) == len(tl) > 0 and worst <= 1e-9, "worst rel %.3g" % worst)
        for v in case.get("vtk", []):
            a, b = s.path(name + "_lammps_" + v + ".vtk"), s.path(name + "_liggghts_" + v + ".vtk")
            same = os.path.exists(a) and os.path.exists(b) and open(a).read() == open(b).read()
            s.ck.check("%s: %s.vtk equals LIGGGHTS's" % (name, v), same)


if __name__ == "__main__":
    M.L.main_guard(M.L.Session(__doc__, extra=[M.STOCK, ("--liggghts",
                                                         "liggghts-rigidsurf")]), body)
