#!/usr/bin/python3
"""Checks rigidsurf-frames against closed-form frames and for its error messages.

Usage: test_frames_cli.py PATH/TO/rigidsurf-frames
"""
import math
import os
import random
import sys

import clilib
from clilib import close

T = clilib.Tool(sys.argv[1], "rs_cli_")
TMP = T.tmp
check, write, run = T.check, T.write, T.run


def rows(out):
    return [[float(v) for v in line.split()] for line in out.splitlines() if line.strip()]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


# A drum mantle: REVOLUTION about z with a LINE at r = R travelling +z, so n points inward.
R = 0.75
drum = write("drum.inp", f"""** drum mantle
*SURFACE, TYPE=REVOLUTION, NAME=mantle
0, 0, 0, 0, 0, 1
START, {R}, -1
LINE, {R}, 1
""")
rng = random.Random(7)
pts = []
for _ in range(200):
    r = rng.uniform(0.05, 0.7)
    th = rng.uniform(-math.pi, math.pi)
    pts.append((r * math.cos(th), r * math.sin(th), rng.uniform(-0.9, 0.9)))
code, out, err = run([drum], "\n".join("%.17g %.17g %.17g" % p for p in pts) + "\n")
check("revolution_cli_runs", code == 0 and len(rows(out)) == len(pts), err)
ok = True
for p, row in zip(pts, rows(out)):
    r = math.hypot(p[0], p[1])
    er = [p[0] / r, p[1] / r, 0.0]
    n = [-er[0], -er[1], 0.0]                  # inward: left of travel +z in (r, z)
    t2 = cross([0, 0, 1], er)                  # hoop
    t1 = cross(t2, n)
    expect = [r - R, R * er[0], R * er[1], p[2]] + n + t1 + t2
    if len(row) != 13 or not close(row, expect):
        ok = False
        print("   point", p, "\n   got", row, "\n   expected", expect)
        break
check("revolution_closed_form_frame_t2_is_hoop", ok)

# 2D SEGMENTS: a LINE along +x has n = +y (left of travel) and t1 = travel.
seg = write("seg.inp", "*Surface, type=SEGMENTS, name=floor\nSTART, 0, 0\nLINE, 2, 0\n")
code, out, err = run([seg], "0.5 0.25\n1.5 -0.125  # behind\n")
r2 = rows(out)
check("segments_cli_two_columns_sets", code == 0 and len(r2) == 2 and all(len(x) == 7 for x in r2), err)
check("segments_penetration_sign",
      code == 0 and close(r2[0], [-0.25, 0.5, 0, 0, 1, 1, 0]) and close(r2[1], [0.125, 1.5, 0, 0, 1, 1, 0]),
      str(r2))

# Points beyond --tracking print 1e30 in every column.
code, out, err = run([drum, "--tracking", "0.1"], "0 0 0\n0.7 0 0\n")
r3 = rows(out)
check("tracking_beyond_prints_maxval",
      code == 0 and len(r3) == 2 and all(v == 1e30 for v in r3[0]) and close(r3[1][:1], [0.7 - R]), str(r3))

# Without --tracking there is no limit: a point 5 in front of the floor gets its frame.
code, out, err = run([seg], "1 5\n")
check("tracking_default_no_limit", code == 0 and close(rows(out)[0], [-5, 1, 0, 0, 1, 1, 0]),
      out + err)

# Several surfaces in one file, chosen by name; points from a file.
multi = write("multi.inp", "*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 1, 0\n"
              "*SURFACE, TYPE=SEGMENTS, NAME=b\nSTART, 0, 1\nLINE, 0, 0\n")
ptsf = write("p.txt", "# x y\n-0.5 0.5\n")
code, out, err = run([multi, ptsf, "--name", "b"])
r4 = rows(out)
# Travel (0,-1): n = (1, 0); the point is behind by 0.5.
check("surface_chosen_by_name", code == 0 and close(r4[0], [0.5, 0, 0.5, 1, 0, 0, -1]), str(r4) + err)

# VTK output.
vtk = os.path.join(TMP, "f.vtk")
code, out, err = run([drum, "--vtk", vtk], "0.5 0 0\n")
text = open(vtk).read() if os.path.exists(vtk) else ""
check("vtk_written", code == 0 and "DATASET POLYDATA" in text and "VECTORS t2 double" in text, err)

# The VTK holds the surface's nodes (the drum's two profile nodes in rings of 64) and a
# vertex at the closest point of each point that got a frame (not the one beyond
# --tracking), with n there.
vtk = os.path.join(TMP, "f2.vtk")
code, out, err = run([drum, "--tracking", "0.1", "--vtk", vtk], "0 0 0\n0.7 0 0.5\n")
text = open(vtk).read() if os.path.exists(vtk) else ""
tail = text.split("VECTORS n double\n")[-1].split("\n")
check("vtk_surface_nodes_and_a_vertex_per_frame",
      code == 0 and "POINTS 129 double" in text and "VERTICES 1 2\n1 128\n" in text
      and len(tail) > 128 and close([float(v) for v in tail[128].split()], [-1, 0, 0]),
      err + text[:200])

# MESH: a unit cube of quads in an OFF file next to the surface file. Above a face, the
# face's normal and the FACETED frame (n = +z: t1 = x, t2 = y); beyond an edge, the
# normal toward the point; the VTK holds the cube's 12 triangles; the open boundary of a
# sheet is a line of information on stderr, a hole in a closed surface a warning.
write("cube.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
      "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n")
cube = write("cube.inp", "*SURFACE, TYPE=MESH, NAME=cube, FILE=cube.off\n")
code, out, err = run([cube, "--tracking", "1"], "0.3 0.6 1.25\n1.3 0.5 1.4\n")
r = rows(out)
check("mesh_face_frame", code == 0 and len(r) == 2 and
      close(r[0], [-0.25, 0.3, 0.6, 1, 0, 0, 1, 1, 0, 0, 0, 1, 0]), str(r) + err)
check("mesh_edge_normal", code == 0 and len(r) == 2 and
      close(r[1][:7], [-0.5, 1, 0.5, 1, 0.6, 0, 0.8]), str(r) + err)
vtk = os.path.join(TMP, "cube.vtk")
code, out, err = run([cube, "--vtk", vtk], "0.5 0.5 2\n")
text = open(vtk).read() if os.path.exists(vtk) else ""
check("mesh_vtk_written", code == 0 and "POLYGONS 12 48" in text, err)
write("open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
opn = write("open.inp", "*SURFACE, TYPE=MESH, NAME=tri, FILE=open.off\n")
code, out, err = run([opn], "0.2 0.2 0.5\n")
check("mesh_open_sheet_info", code == 0 and "warning" not in err and
      "info: " in err and "an open surface: 3 open boundary edges on 1 rim" in err, err)
# the cube less one of its triangles: a hole as wide as a face, a rim; the same cube of
# 10 x 10 quads a face, less one quad, a small hole: a warning
write("holed.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n"
      "0 1 1\n3 0 3 2\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n")
pts, quads = [], []
for face in range(6):
    axis, side = face // 2, float(face % 2)
    u, v = (axis + 1) % 3, (axis + 2) % 3
    for r in range(10):
        for c in range(10):
            if face == 0 and (r, c) == (3, 4):
                continue
            corners = [(c, r), (c + 1, r), (c + 1, r + 1), (c, r + 1)]
            if not face % 2:
                corners.reverse()
            ids = []
            for cu, cv in corners:
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = side, cu / 10.0, cv / 10.0
                ids.append(len(pts))
                pts.append(p)
            quads.append(ids)
write("fine.off", "OFF\n%d %d 0\n" % (len(pts), len(quads)) +
      "".join("%r %r %r\n" % tuple(p) for p in pts) +
      "".join("4 %d %d %d %d\n" % tuple(q) for q in quads))
for name, want in (("holed", "info: "), ("fine", "warning: ")):
    code, out, err = run([write(name + ".inp", "*SURFACE, TYPE=MESH, NAME=%s, FILE=%s.off\n"
                                % (name, name))], "0.5 0.5 0.5\n")
    check("mesh_open_%s_%s" % (name, want[:-2]), code == 0 and want in err and
          ("around 1 hole" in err) == (name == "fine"), err)

# Errors: one line, naming the file and the line, non-zero exit.
bad = write("bad.inp", "*SURFACE, TYPE=SEGMENTS, NAME=x\nSTART, 0, 0\nLINE, 1, zero\n")
code, out, err = run([bad], "0 0\n")
check("bad_surface_names_file_and_line", code != 0 and (bad + ":3") in err and err.count("\n") == 1, err)
badp = write("badp.txt", "0 0\n1 2 3\n")
code, out, err = run([seg, badp])
check("bad_points_names_file_and_line", code != 0 and (badp + ":2") in err, err)
code, out, err = run([os.path.join(TMP, "missing.inp")], "")
check("missing_surface_file", code != 0 and "missing.inp" in err, err)
hugep = write("hugep.txt", "0 0\n1e101 0\n")
code, out, err = run([seg, hugep])
check("point_beyond_1e100_names_file_and_line",
      code != 0 and (hugep + ":2") in err and "1e101" in err, err)
code, out, err = run([TMP], "")
check("directory_as_surface_file", code != 0 and "is a directory" in err, err)
code, out, err = run([drum, "--tracking", "nan"], "0 0 0\n")
check("tracking_nan", code != 0 and "--tracking" in err and "nan" in err, err)
code, out, err = run([drum, "--bogus"], "")
check("unknown_option", code != 0 and "--bogus" in err, err)

T.finish()
