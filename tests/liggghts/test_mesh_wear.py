#!/usr/bin/python3
"""Per-facet stress and Finnie wear of a MESH wall (`wear finnie`, the VTK's cell data)
against LIGGGHTS's `fix mesh/surface/stress ... wear finnie` on the same STL.

Three spheres on a plate of 32 triangles: one strikes at 45 deg (Finnie's cos^2/3
branch), one at 11 deg (the sin 2g - 3 sin^2 g branch), one slides and stays in contact.
LIGGGHTS's mesh wall and ours give the same trajectories (test_mesh_wall), so at steps
200, 400 and 600:
- sigma_n and sigma_t of every facet equal LIGGGHTS's normal and shear stress to 1e-9
  relative (LIGGGHTS writes 11 digits);
- the wear of every facet equals LIGGGHTS's to 2e-5 relative: LIGGGHTS writes Finnie's
  1/3 as 0.33333 (1e-5 less), rigidsurf as 1/3.
Both branches are met (two struck facets), and the sliding sphere's facet wears too.
The wear is written to restart files and read back bit for bit, and over two ranks it
is the one-rank run's to 1e-12. `wear` on an analytic surface,
a wrong word, and a deck without k_finnie are rejected.
"""
import math
import os

import liglib as L
from test_mesh_wall import plate, stl

R, RHO, DT = 0.005, 2500.0, 1.0e-5
KF = "fix m5 all property/global k_finnie peratomtypepair 2 1.0 1.0 1.0 1.0\n"
BOX = (-0.2, 0.2, -0.2, 0.2, -0.05, 0.3)
NF = 32


def atoms():
    a = L.sphere(1, (0.03, 0.07, R + 2e-4), R, RHO, v=(1.0, 0.0, -1.0))
    a += L.sphere(2, (-0.1, -0.05, R + 2e-4), R, RHO, v=(1.0, 0.3, -0.2))
    a += L.sphere(3, (0.13, 0.13, R), R, RHO, v=(0.3, 0.1, 0.0))
    return a


def deck(wall, steps, pre="", np=1):
    d = L.header(BOX, DT, extra_props=KF,
                 pre=("processors %d 1 1\n" % np) if np > 1 else "") + atoms()
    d += "fix grav all gravity 9.81 vector 0 0 -1\n" + pre + wall
    d += "fix integr all nve/sphere\nrun %d\n" % steps
    return d


def cells(path):
    """{name: [value per cell]} of a polydata VTK: LIGGGHTS's FIELD arrays or our
    SCALARS."""
    text = open(path).read().split("CELL_DATA", 1)[1]
    toks = text.split()
    out = {}
    for i, t in enumerate(toks):
        if t in ("normal_stress_average", "shear_stress_average", "wear") and \
                toks[i + 1] == "1" and toks[i + 3] == "double":
            out[t] = [float(v) for v in toks[i + 4:i + 4 + NF]]
        if t == "SCALARS":
            out[toks[i + 1]] = [float(v) for v in toks[i + 6:i + 6 + NF]]
    return out


def rel(a, b, scale):
    return abs(a - b) / scale if scale > 0 else abs(a - b)


def body(s):
    ck = s.ck
    s.write("plate.stl", stl(plate(0.2, 4)))
    os.makedirs(s.path("post"), exist_ok=True)
    ours = ("fix w all wall/rigid surface inline mesh plate.stl law hertz type 2 wear finnie "
            "vtk post/o_*.vtk 200\n")
    ref = ("fix cad all mesh/surface/stress file plate.stl type 2 wear finnie\n"
           "fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
           "dump dm all mesh/gran/VTK 200 post/m_*.vtk stress wear cad\n")
    s.run("wear_ours", deck(ours, 600))
    s.run("wear_ref", deck(ref, 600))
    for step in (200, 400, 600):
        a = cells(s.path("post/m_%d.vtk" % step))
        b = cells(s.path("post/o_%d.vtk" % step))
        for mine, theirs, tol in (("sigma_n", "normal_stress_average", 1e-9),
                                  ("sigma_t", "shear_stress_average", 1e-9),
                                  ("wear", "wear", 2e-5)):
            x, y = b.get(mine, []), a.get(theirs, [])
            if not ck.check("step %d: %s for every facet" % (step, mine),
                            len(x) == NF and len(y) == NF, "%d, %d values" % (len(x), len(y))):
                continue
            worst = max(rel(p, q, max(abs(q), 1e-300)) if q else abs(p) for p, q in zip(x, y))
            ck.check("step %d: %s equals LIGGGHTS's to %g" % (step, mine, tol), worst <= tol,
                     "worst relative difference %.3g" % worst)
    last = cells(s.path("post/o_600.vtk"))
    worn = [k for k, w in enumerate(last.get("wear", [])) if w > 0]
    ck.check("three facets wear (two struck, one slid on)", len(worn) == 3, str(worn))
    sn = [k for k, v in enumerate(last.get("sigma_n", [])) if v > 0]
    ck.check("the resting sphere loads one facet at step 600", len(sn) == 1, str(sn))

    # restart: the wear written with the restart file is the wear the restarted run
    # starts from (its setup writes the VTK of step 300). The trajectories themselves
    # part after the restart for the sliding sphere, in LIGGGHTS's mesh wall as in ours:
    # a run's setup forces use the full-step velocity.
    first = deck(ours.replace("o_*", "first_*").replace(" 200\n", " 300\n"), 300)
    s.run("wear_first", first + "write_restart wear.restart\n")
    d = "atom_modify map array\ncommunicate single vel yes\nread_restart wear.restart\n"
    head = L.header(BOX, DT, extra_props=KF)
    d += "\n".join(l for l in head.splitlines()
                   if l.startswith(("newton", "fix m", "pair_", "timestep", "neighbor",
                                    "neigh_modify"))) + "\n"
    d += "fix grav all gravity 9.81 vector 0 0 -1\n"
    d += ours.replace("o_*", "rst_*").replace(" 200\n", " 300\n")
    d += "fix integr all nve/sphere\nrun 300\n"
    s.run("wear_restarted", d)
    before = cells(s.path("post/first_300.vtk")).get("wear", [])
    after = cells(s.path("post/rst_300.vtk")).get("wear", [])
    ck.check("restart: the wear carries over bit for bit", len(before) == NF and
             before == after and any(before),
             "largest difference %.3g" % max((abs(p - q) for p, q in zip(before, after)),
                                             default=float("nan")))
    grown = cells(s.path("post/rst_600.vtk")).get("wear", [])
    ck.check("restart: the restarted run goes on wearing", len(grown) == NF and
             sum(grown) > sum(after), "%.6g after, %.6g at the restart" % (sum(grown),
                                                                          sum(after)))

    # two ranks
    s.run("wear_np2", deck(ours.replace("o_*", "np2_*"), 600, np=2), np=2)
    two = cells(s.path("post/np2_600.vtk")).get("wear", [])
    one = last.get("wear", [])
    worst = max((rel(p, q, max(q, 1e-300)) if q else abs(p) for p, q in zip(two, one)),
                default=float("inf"))
    ck.check("two ranks: the wear of the one-rank run to 1e-12", len(two) == NF and
             worst <= 1e-12, "worst %.3g" % worst)

    # bad input
    floor = s.write("floor.inp", L.plane_z(0.0, half=1.0))
    for name, fix, want, props in (
            ("wear_on_analytic", "fix w all wall/rigid surface %s law hertz type 2 wear finnie"
             % floor, ["wear", "mesh surface"], KF),
            ("wear_wrong_word", "fix w all wall/rigid surface inline mesh plate.stl law hertz "
             "type 2 wear archard", ["wear", "archard"], KF),
            ("wear_without_k_finnie", "fix w all wall/rigid surface inline mesh plate.stl law "
             "hertz type 2 wear finnie", ["k_finnie"], "")):
        d = L.header(BOX, DT, extra_props=props) + L.sphere(1, (0, 0, 0.02), R, RHO)
        d += fix + "\nfix integr all nve/sphere\nrun 10\n"
        rc, out = s.run(name, d, expect_ok=False)
        L.check_rejected(ck, name, fix, want, rc, out)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
