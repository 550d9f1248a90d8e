#!/usr/bin/python3
"""rigidsurf-migrate keeps working what names a wall or its mesh
(rigidsurf_migrate_refs.py, docs/migration.md): each wall/rigid is unfixed once; dumps
of meshes become the walls' vtk or keep their meshes for the dump alone; a compute
wall/gran/local keeps its wall; fix_modify of a mesh wall/gran; a mesh that another
command uses stays for it; the NOTE on a mesh's folds within contact reach counts them
as an independent count of the STL's edges does. The values of f_M[i] themselves are
run against stock LIGGGHTS in tests/liggghts/test_migrate_decks.py.

Usage: test_migrate_refs.py PATH/TO/rigidsurf-migrate
"""
import math
import sys

import clilib

T = clilib.Tool(sys.argv[1], "rs_refs_")
TMP = T.tmp
check, migrate = T.check, T.migrate


def stl(name, tris):
    T.write(name, "solid s\n" + "".join(
        " facet normal 0 0 0\n  outer loop\n" +
        "".join("   vertex %.17g %.17g %.17g\n" % tuple(p) for p in t) +
        "  endloop\n endfacet\n" for t in tris) + "endsolid s\n")


PLATE = [((0, 0, 0), (1, 0, 0), (1, 1, 0)), ((0, 0, 0), (1, 1, 0), (0, 1, 0))]
for k in range(4):
    stl("p%d.stl" % k, [tuple((x, y, z + 0.1 * k) for x, y, z in t) for t in PLATE])
BOX = "region reg block -2 2 -2 2 -2 2 units box\ncreate_box 1 reg\n"
MODEL = "model hertz tangential history"


def meshes(n, style="mesh/surface"):
    return "".join("fix m%d all %s file p%d.stl type 1\n" % (k, style, k) for k in range(n))


def wall(ids, wid="w"):
    return "fix %s all wall/gran %s mesh n_meshes %d meshes %s\n" % (
        wid, MODEL, len(ids), " ".join(ids))


def lines_of(out, word):
    return [l for l in out.splitlines() if l.startswith(word)]


# ---- unfix, once -------------------------------------------------------------------------
for order in (("w", "m0"), ("m0", "w")):
    rc, out, err = migrate(BOX + meshes(1) + wall(["m0"]) + "run 10\n" +
                           "".join("unfix %s\n" % x for x in order) + "run 10\n")
    check("unfix %s then unfix %s: wall/rigid m0 unfixed once, at the first" % order,
          rc == 0 and out.endswith("run 10\nunfix m0\nrun 10\n"), out + err)
rc, out, err = migrate(BOX + meshes(2) + wall(["m0", "m1"]) + "run 1\nunfix w\nunfix m1\n"
                       "unfix m0\n")
check("unfix of a wall/gran of two meshes: the last made first, its meshes' unfix gone",
      rc == 0 and lines_of(out, "unfix") == ["unfix m1", "unfix m0"], out + err)

# ---- dumps ---------------------------------------------------------------------------------
FOUR = BOX + meshes(4) + wall(["m0", "m1"], "wa") + wall(["m2", "m3"], "wb") + \
    "dump d all mesh/stl 100 post/walls*.stl\nrun 10\n"
rc, out, err = migrate(FOUR)
check("a dump mesh/stl of four meshes: every wall migrated, the meshes kept as LIGGGHTS's "
      "for the dump, the walls under IDs of their own",
      rc == 0 and all("fix m%d all mesh/surface file p%d.stl type 1\n" % (k, k) in out and
                      "fix rs_m%d all wall/rigid" % k in out for k in range(4)) and
      "dump d all mesh/stl 100 post/walls*.stl\n" in out and "wall/gran" not in out and
      "NOTE: dump d writes meshes m0 m1 m2 m3, kept as LIGGGHTS meshes for it alone "
      "(without a wall); the walls are wall/rigid rs_m0 rs_m1 rs_m2 rs_m3" in err,
      out + err)
rc, out, err = migrate(BOX + meshes(1, "mesh/surface/stress") + wall(["m0"]) +
                       "dump dm all mesh/vtk 100 post/m*.vtk id stress stresscomponents vel\n"
                       "dump_modify dm pad 5\nrun 10\nundump dm\n")
check("a dump mesh/vtk of the wall's stress (hydrogel_default): the wall's vtk, the dump, "
      "its dump_modify and undump gone, NOTEs of the fields not written and of the undump",
      rc == 0 and "vtk post/m*.vtk 100" in out.replace(" &\n    ", " ") and
      "dump" not in out and "not written: id stresscomponents vel" in err and
      "undump dm: the walls that write its meshes' vtk go on writing it" in err, out + err)
rc, out, err = migrate(BOX + meshes(2, "mesh/surface/stress") + wall(["m0"]) +
                       "dump dm all mesh/gran/VTK 100 post/m*.vtk stress wear m0 m1\n")
check("a dump of the stress of a migrated mesh and of a mesh without wall: the wall's "
      "vtk named after its mesh, the dump kept for the other",
      rc == 0 and "vtk post/mm0_*.vtk 100" in out.replace(" &\n    ", " ") and
      "dump dm all mesh/gran/VTK 100 post/m*.vtk stress wear m1\n" in out, out + err)

# ---- compute wall/gran/local, fix_modify, other users --------------------------------------
rc, out, err = migrate(BOX + meshes(2) + wall(["m0"], "wa") + wall(["m1"], "wb") +
                       "compute c all wall/gran/local id force\n" +
                       "fix p all wall/gran %s primitive type 1 zplane 0\n" % MODEL)
check("compute wall/gran/local keeps the mesh wall it reads (the last made before it), "
      "exit 3, and the others migrate",
      rc == 3 and "LINE 6: fix wb: compute c (LINE 7) reads its contacts" in err and
      "fix wb all wall/gran" in out and "fix m0 all wall/rigid" in out and
      "fix p all wall/rigid" in out and "2 of 3 wall/gran fixes translated" in err, out + err)
rc, out, err = migrate(BOX + meshes(2) + wall(["m0", "m1"]) + "fix_modify w energy yes\n" +
                       "fix p all wall/gran %s primitive type 1 zplane 0\n" % MODEL +
                       "fix_modify p energy yes\n")
check("fix_modify energy of a mesh wall/gran: of each of its walls; of a primitive: as "
      "written", rc == 0 and "fix_modify m0 energy yes\nfix_modify m1 energy yes\n" in out
      and "fix_modify p energy yes\n" in out, out + err)
rc, out, err = migrate(BOX + meshes(1) + wall(["m0"]) + "fix_modify w virial yes\n")
check("another fix_modify of a wall/gran: exit 1 (LIGGGHTS refuses it)",
      rc == 1 and "LINE 5: ERROR: fix_modify w" in err, err)
rc, out, err = migrate(BOX + meshes(1) + wall(["m0"]) + "variable f equal f_w[1]\n")
check("f_ID of a wall/gran (which has no value): exit 1", rc == 1 and
      "f_w[1]: fix wall/gran computes no value" in err, err)
rc, out, err = migrate(BOX + meshes(1) + wall(["m0"]) + "fix ins all insert/stream seed "
                       "123457 distributiontemplate pdd nparticles 10 massrate 0.1 "
                       "insertion_face m0 extrude_length 0.1\n")
check("a mesh another command uses (an insertion face) stays a LIGGGHTS mesh for it; its "
      "wall migrates under an ID of its own", rc == 0 and
      "fix m0 all mesh/surface file p0.stl" in out and "fix rs_m0 all wall/rigid" in out and
      "insertion_face m0" in out and "mesh m0 stays a LIGGGHTS mesh, without a wall, for LINE 5 (fix ins all "
      "insert/stream)" in err, out + err)

# ---- the servo's and a turning mesh's values -----------------------------------------------
TURN = BOX + "fix m all mesh/surface/stress file p0.stl type 1 reference_point 1 0 0\n" + \
    wall(["m"]) + "fix r all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1 period 1\n"
rc, out, err = migrate(TURN + "variable t equal f_m[4]\n")
check("the torque about a point a turning wall carries away from its origin: the wall kept",
      rc == 3 and "reads f_m[4]: the torque about a point the wall turns away from its "
      "surface origin" in err, err)
rc, out, err = migrate(TURN + "variable t equal f_m[3]\n")
check("a turning wall's force: kept as it is", rc == 0 and "variable t equal f_m[3]" in out,
      err)

# ---- folds within contact reach ------------------------------------------------------------
# half a cylinder of radius 1 in N facets (folds of 180/N degrees), a box (folds of 90)
def half_cylinder(n):
    tris = []
    for k in range(n):
        a0, a1 = math.pi * k / n, math.pi * (k + 1) / n
        p = [(math.cos(a0), math.sin(a0), 0), (math.cos(a1), math.sin(a1), 0),
             (math.cos(a1), math.sin(a1), 1), (math.cos(a0), math.sin(a0), 1)]
        tris += [(p[0], p[1], p[2]), (p[0], p[2], p[3])]
    return tris


def box_tris():
    out = []
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for s in (0.0, 1.0):
            q = []
            for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = s, a, b
                q.append(tuple(p))
            out += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    return out


stl("chute.stl", half_cylinder(30))
stl("coarse.stl", half_cylinder(6))
stl("box.stl", box_tris())
for name, want in (("chute.stl", "29 of its 59 inner edges are folds of 6 to 6 degrees"),
                   ("coarse.stl", None), ("box.stl", None), ("p0.stl", None)):
    rc, out, err = migrate(BOX + "fix m all mesh/surface file %s type 1\n" % name +
                           wall(["m"]))
    notes = [l for l in err.splitlines() if "folds" in l]
    check("the fold NOTE of %s: %s" % (name, want or "none (folds of 30 or 90 degrees, or "
                                        "none)"),
          rc == 0 and (want is None and not notes or want is not None and len(notes) == 1
                       and "LINE 3: NOTE: mesh m (%s): %s" % (name, want) in notes[0]),
          err)

T.finish()
