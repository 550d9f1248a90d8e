#!/usr/bin/python3
"""predef: per-atom fields reach the law as preDefSlv, their changes as dpreDefSlv.

Two spheres rest on our plane without an integrator (they stay put). Two fix
property/atom scalars fa and fb are handed to a user C law (predef_echo.c) that echoes
preDefSlv(1) into stress(1), preDefSlv(2) into stress(3), and the running sum of
dpreDefSlv(1) into stress(2); the fix's per-atom output f_w[4..6] shows them.
Independent answers: the values set with `set ... property/atom`, and for the sum of the
increments, the total change of fa (telescoping sum), including a change made between
two runs (setup must neither count nor lose it).
"""
import os
import subprocess

import liglib as L

R, RHO, DT = 0.001, 2500.0, 1.0e-5
FA0, FB = (1.5, -2.0), (7.0, 8.0)
FA1 = (2.5, -4.0)
HERE = os.path.dirname(os.path.abspath(__file__))


def deck():
    d = L.header((-0.05, 0.05, -0.05, 0.05, -0.05, 0.05), DT)
    d += L.sphere(1, (0.0, 0.0, R - 1e-5), R, RHO)
    d += L.sphere(2, (0.01, 0.0, R - 1e-5), R, RHO)
    d += ("fix pa all property/atom fa scalar yes no no 0.0\n"
          "fix pb all property/atom fb scalar yes no no 0.0\n"
          "run 0\n")  # LIGGGHTS: 'set' on a new property/atom needs a prior run
    for i in (0, 1):
        d += "set atom %d property/atom fa %r\n" % (i + 1, FA0[i])
        d += "set atom %d property/atom fb %r\n" % (i + 1, FB[i])
    d += ("fix w all wall/rigid surface plane.inp law user ./libpredef.so predef_echo "
          "statev 1 predef fa fb type 2 peratom yes\n")
    d += "dump d all custom 10 first.dump id f_w[4] f_w[5] f_w[6]\n"
    d += "dump_modify d format \"%d %.17g %.17g %.17g\"\n"
    d += "run 20\nundump d\n"
    for i in (0, 1):
        d += "set atom %d property/atom fa %r\n" % (i + 1, FA1[i])
    d += "dump d2 all custom 10 second.dump id f_w[4] f_w[5] f_w[6]\n"
    d += "dump_modify d2 format \"%d %.17g %.17g %.17g\"\n"
    d += "run 20\n"
    return d


def body(s):
    lib = s.path("libpredef.so")
    subprocess.run(["gcc", "-O2", "-Wall", "-Wextra", "-Werror", "-shared", "-fPIC",
                    "-I" + os.path.join(HERE, "..", "..", "include"),
                    os.path.join(HERE, "predef_echo.c"), "-o", lib], check=True)
    s.write("plane.inp", L.plane_z(0.0, 1.0))
    s.run("predef", deck())
    first = L.read_dump(s.path("first.dump"))[-1][1]
    second = L.read_dump(s.path("second.dump"))[-1][1]
    for i in (1, 2):
        a, b = first[i], second[i]
        s.ck.check("atom %d: preDefSlv(1) = fa (%g, then %g)" % (i, FA0[i - 1], FA1[i - 1]),
                   a["f_w[4]"] == FA0[i - 1] and b["f_w[4]"] == FA1[i - 1],
                   "%r, %r" % (a["f_w[4]"], b["f_w[4]"]))
        s.ck.check("atom %d: preDefSlv(2) = fb (%g)" % (i, FB[i - 1]),
                   a["f_w[6]"] == FB[i - 1] and b["f_w[6]"] == FB[i - 1],
                   "%r, %r" % (a["f_w[6]"], b["f_w[6]"]))
        s.ck.check("atom %d: no increments while fa is constant" % i, a["f_w[5]"] == 0.0,
                   "%r" % a["f_w[5]"])
        change = FA1[i - 1] - FA0[i - 1]
        s.ck.check("atom %d: sum of dpreDefSlv(1) = total change of fa (%g)" % (i, change),
                   abs(b["f_w[5]"] - change) <= 1e-15, "%r" % b["f_w[5]"])


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
