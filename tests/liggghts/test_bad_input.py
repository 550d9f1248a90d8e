#!/usr/bin/python3
"""Malformed fix wall/rigid lines end the run with their own message, never a crash.

Each case is a deck that is valid except for one fix line. The run must exit with
status 1 (error->all: every rank stops cleanly; not a signal, not MPI_Abort's core),
print exactly one kind of ERROR line naming fix wall/rigid (or the surface file and
line), and that line must contain the text that identifies the mistake. One valid
line is run first so a failure of the deck itself cannot pass as a rejection.
"""
import liglib as L

BASE = "fix w all wall/rigid surface plane.inp law hertz type 2"
PLANE = "surface plane.inp"

# (name, fix line, [substrings the ERROR line must contain])
CASES = [
    ("unknown keyword", BASE + " colour red", ["unknown keyword 'colour'"]),
    ("missing surface file", "fix w all wall/rigid surface nosuch.inp law hertz type 2",
     ["nosuch.inp", "cannot open"]),
    ("no such surface name", "fix w all wall/rigid surface plane.inp name roof law hertz type 2",
     ["surface 'roof' not found", "floor"]),
    ("unknown law", "fix w all wall/rigid surface plane.inp law hurtz type 2",
     ["unknown law 'hurtz'", "hertz"]),
    ("wrong prop count", "fix w all wall/rigid " + PLANE + " law linear_softening props 1 2",
     ["law 'linear_softening' expects 1 properties", "got 2"]),
    ("bonded_interface prop count", "fix w all wall/rigid " + PLANE +
     " law bonded_interface props 1e-4 1e7 0.3", ["law 'bonded_interface' expects 7", "got 3"]),
    ("hooke prop count", "fix w all wall/rigid " + PLANE + " law hooke props 1 2 3 4 5 6 "
     "type 2", ["law 'hooke' expects 5 properties", "or 7 material properties", "got 6"]),
    ("hooke restitution 0", "fix w all wall/rigid " + PLANE + " law hooke props 5e7 0.3 "
     "2e8 0.25 0 0.5 1 type 2", ["property 'restitution' must be in (0, 1]"]),
    ("NaN prop", "fix w all wall/rigid " + PLANE + " law linear_softening props nan",
     ["props", "finite"]),
    ("non-numeric prop", "fix w all wall/rigid " + PLANE + " law linear_softening props stiff",
     ["'props' expects numbers", "stiff"]),
    ("negative tracking", BASE + " tracking -0.001", ["'tracking' expects a length >= 0"]),
    ("contacts 0", BASE + " contacts 0", ["'contacts' expects a capacity in 1..", "got 0"]),
    ("zero rotation axis", BASE + " rotate origin 0 0 0 axis 0 0 0 omega 1",
     ["axis", "non-zero"]),
    ("rotate without omega", BASE + " rotate origin 0 0 0 axis 0 0 1 speed 3",
     ["'omega W' or 'period P'", "speed"]),
    ("rotate period 0", BASE + " rotate origin 0 0 0 axis 0 0 1 period 0",
     ["non-zero period"]),
    ("rotate centre unknown", BASE + " rotate origin 0 0 0 axis 0 0 1 omega 1 centre still",
     ["'rotate ... centre' expects 'moving' or 'fixed'", "still"]),
    ("spin twice", BASE + " spin origin 0 0 0 axis 1 0 0 omega 1 spin origin 0 0 0 axis "
     "1 0 0 omega 2", ["'spin' is given once"]),
    ("spin zero axis", BASE + " spin origin 0 0 0 axis 0 0 0 omega 1", ["axis", "non-zero"]),
    ("spin without omega", BASE + " spin origin 0 0 0 axis 0 0 1", ["'spin' expects "
     "'omega W' or 'period P' after the axis"]),
    ("contact_area without conduction", BASE + " contact_area projection",
     ["'contact_area' sets the area of 'conduction liggghts'"]),
    ("contact_area constant 0", BASE + " temperature 400 conduction liggghts contact_area "
     "constant 0", ["'contact_area constant' expects an area > 0", "got 0"]),
    ("contact_area unknown", BASE + " contact_area circle", ["'contact_area' expects "
     "'overlap', 'projection' or 'constant A'", "circle"]),
    ("move not linear", BASE + " move circular 1 0 0", ["'move' expects 'linear VX VY VZ'"]),
    ("inline profile without end", "fix w all wall/rigid law hertz type 2 surface inline "
     "revolution origin 0 0 0 axis 0 0 1 profile START 0.05 -1 LINE 0.05 1",
     ["not closed by 'end'"]),
    ("inline unknown kind", "fix w all wall/rigid surface inline sphere origin 0 0 0 "
     "profile START 0 0 LINE 1 0 end law hertz type 2",
     ["'revolution', 'cylinder', 'segments' or 'mesh'", "sphere"]),
    ("inline mesh without file", "fix w all wall/rigid law hertz type 2 surface inline mesh",
     ["'surface inline mesh' expects a mesh FILE"]),
    ("mesh file missing", "fix w all wall/rigid surface inline mesh nothere.stl law hertz type 2",
     ["nothere.stl", "No such file"]),
    ("mesh file empty", "fix w all wall/rigid surface inline mesh empty.stl law hertz type 2",
     ["empty.stl is empty"]),
    ("mesh file a directory", "fix w all wall/rigid surface inline mesh sub.stl law hertz type 2",
     ["sub.stl is a directory"]),
    ("mesh file truncated", "fix w all wall/rigid surface inline mesh trunc.stl law hertz type 2",
     ["trunc.stl", "broken or truncated"]),
    ("mesh NaN coordinate (text)", "fix w all wall/rigid surface inline mesh nan.off law "
     "hertz type 2", ["nan.off", "not a readable OFF file"]),
    ("mesh NaN coordinate (binary STL)", "fix w all wall/rigid surface inline mesh nan.stl "
     "law hertz type 2", ["nan.stl", "facet 1 has coordinate nan", "finite"]),
    ("mesh scale negative", "fix w all wall/rigid surface inline mesh tri.off scale -2 "
     "law hertz type 2", ["SCALE > 0"]),
    ("mesh scale not a number", "fix w all wall/rigid surface inline mesh tri.off scale big "
     "law hertz type 2", ["surface inline", "big"]),
    ("mesh unknown format", "fix w all wall/rigid surface inline mesh part.step law hertz type 2",
     ["unknown mesh format '.step'"]),
    ("missing law", "fix w all wall/rigid surface plane.inp type 2", ["missing 'law LAW'"]),
    ("missing surface", "fix w all wall/rigid law hertz type 2", ["missing 'surface FILE'"]),
    ("wall type out of range", BASE.replace("type 2", "type 7"),
     ["'type' expects a material type in 1..2", "got 7"]),
    ("wall type not an integer", BASE.replace("type 2", "type steel"),
     ["'type' expects", "steel"]),
    ("negative area", BASE + " area -1", ["'area' expects a constant area > 0"]),
    ("negative wall capacity", BASE + " temperature 300 capacity -5",
     ["'capacity' expects a wall heat capacity > 0"]),
    ("vtk interval 0", BASE + " vtk wall.vtk 0", ["'vtk' expects an output interval N > 0"]),
    ("conduction unknown", BASE + " temperature 300 conduction fourier",
     ["'conduction' expects 'liggghts' or 'off'", "fourier"]),
    ("conduction without temperature", BASE + " conduction liggghts",
     ["'conduction liggghts' needs the wall's 'temperature T'"]),
    ("conduction without heat/gran", BASE + " temperature 300 conduction liggghts",
     ["'conduction liggghts' needs fix heat/gran"]),
    ("store_force unknown", BASE + " store_force maybe",
     ["'store_force' expects 'yes', 'no' or 'into ID'", "maybe"]),
    ("store_force into nothing", BASE + " store_force into",
     ["'store_force' expects 'into ID'"]),
    ("law given twice", BASE + " law hooke", ["'law' given twice"]),
    ("statev mismatch", "fix w all wall/rigid " + PLANE + " law bonded_interface props "
     "1e-4 1e7 0.3 1e9 0 1e-3 10 statev 5 type 2",
     ["law 'bonded_interface' has 3 state variables", "statev 5"]),
    ("missing user library", "fix w all wall/rigid " + PLANE + " law user /nonexistent/liblaw.so "
     "mylaw type 2", ["/nonexistent/liblaw.so", "cannot load"]),
    ("fric without normal law", "fix w all wall/rigid " + PLANE + " law fric libfric.so type 2",
     ["expects 'normal LAW'"]),
    ("uinter with unknown normal law", "fix w all wall/rigid " + PLANE +
     " law uinter libu.so normal glue type 2", ["'normal glue' is not a built-in law"]),
    ("surface file syntax error", "fix w all wall/rigid surface bad.inp law hertz type 2",
     ["bad.inp:4:", "expected a number", "zero"]),
    ("surface file wrong point count", "fix w all wall/rigid surface badpts.inp law hertz type 2",
     ["badpts.inp:2:", "6 numbers", "found 5"]),
]


def body(s):
    s.write("plane.inp", L.plane_z(0.0, 1.0))
    s.write("bad.inp", "*SURFACE, TYPE=CYLINDER, NAME=floor\n0, 0, 0, 1, 0, 0\n"
            "0, -1, 0\nSTART, -1, zero\nLINE, 1, 0\n")
    s.write("badpts.inp", "*SURFACE, TYPE=REVOLUTION, NAME=drum\n0, 0, 0, 0, 0\n"
            "START, 0.05, -1\nLINE, 0.05, 1\n")
    s.write("empty.stl", "")
    s.write("part.step", "ISO-10303-21;\n")
    s.write("trunc.stl", "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n")
    s.write("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    import struct
    with open(s.path("nan.stl"), "wb") as f:
        f.write(b"binary".ljust(80, b" ") + struct.pack("<I", 1))
        f.write(struct.pack("<12fH", 0, 0, 1, 0, 0, 0, float("nan"), 0, 0, 0, 1, 0, 0))
    s.write("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    import os
    os.makedirs(s.path("sub.stl"), exist_ok=True)
    rc, out = s.run("valid", L.one_sphere_deck(BASE), expect_ok=False)
    if not s.ck.check("the valid line runs", rc == 0, "exit %s" % rc,
                      why="\n".join(out.splitlines()[-5:])):
        return
    s.ck.check("at least 20 malformed lines", len(CASES) >= 20, "%d" % len(CASES))
    for k, (name, line, want) in enumerate(CASES):
        rc, out = s.run("bad%02d" % k, L.one_sphere_deck(line), expect_ok=False,
                        timeout=60)
        L.check_rejected(s.ck, name, line, want, rc, out)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
