#!/usr/bin/python3
"""Every fix wall/rigid keyword, fed bad values, ends the run with one ERROR line that
names the keyword, and LIGGGHTS exits cleanly.

For each keyword the deck is valid except for that keyword's value, which is missing,
negative (where a negative value is meaningless), NaN, overflowing, beyond the
keyword's limit, of the wrong type, or a file that is missing, empty or a directory. The
run must exit with status 1 (not a signal, not an abort), print exactly one error message,
and that line must name the keyword and, where there is one, the bad value. One valid
line runs first so a failure of the deck itself cannot pass as a rejection.
"""
import concurrent.futures
import os

import liglib as L

SURF = "surface plane.inp"
LAW = "law hertz type 2"
HERTZ = "fix w all wall/rigid " + SURF + " " + LAW
SOFT = "fix w all wall/rigid " + SURF + " law linear_softening props 1e4 type 2"

# Bad values of a real number, of a count, and of a keyword word.
REAL = [("missing", ""), ("NaN", "nan"), ("overflowing", "1e400"),
        ("beyond 1e100", "-2e100"), ("wrong type", "steel")]
COUNT = [("missing", ""), ("negative", "-3"), ("NaN", "nan"), ("overflowing", "2147483648"),
         ("fractional", "3.5"), ("wrong type", "many")]


def cases():
    """(name, fix line, [substrings of the ERROR line])"""
    out = []

    def add(kw, label, line, value, shown=True):
        want = ["'%s'" % kw]
        if value and shown:
            want.append(value)
        out.append(("%s: %s" % (kw, label), line, want))

    # real-valued keywords: (keyword as named in the message, line with {} for the value,
    # whether a negative value is an error)
    reals = [
        ("tracking", HERTZ + " tracking {}", True),
        ("area", HERTZ + " area {}", True),
        ("temperature", HERTZ + " temperature {}", False),
        ("capacity", HERTZ + " temperature 300 capacity {}", True),
        ("move linear", HERTZ + " move linear {} 0 0", False),
        ("surface_vel", HERTZ + " surface_vel {} 0 0", False),
        ("rotate origin", HERTZ + " rotate origin {} 0 0 axis 0 0 1 omega 1", False),
        ("rotate axis", HERTZ + " rotate origin 0 0 0 axis 0 0 {} omega 1", False),
        ("rotate omega", HERTZ + " rotate origin 0 0 0 axis 0 0 1 omega {}", False),
        ("rotate period", HERTZ + " rotate origin 0 0 0 axis 0 0 1 period {}", False),
        ("props", "fix w all wall/rigid " + SURF + " law linear_softening props {} type 2",
         True),
    ]
    for kw, line, neg in reals:
        for label, v in REAL + ([("negative", "-1")] if neg else []):
            shown = label not in ("negative", "missing")
            add(kw, label, line.format(v).replace("  ", " ").rstrip(), v, shown)
    counts = [
        ("type", "fix w all wall/rigid " + SURF + " law hertz type {}"),
        ("statev", SOFT + " statev {}"),
        ("contacts", HERTZ + " contacts {}"),
        ("vtk", HERTZ + " vtk wall.vtk {}"),
    ]
    for kw, line in counts:
        for label, v in COUNT:
            add(kw, label, line.format(v).rstrip(), v, label != "missing")
    add("statev", "beyond the limit", SOFT + " statev 100000000", "100000000")
    add("statev", "largest int", SOFT + " statev 2147483647", "2147483647")
    add("contacts", "beyond the limit", HERTZ + " contacts 100000", "100000")
    # history beyond what LIGGGHTS's atom exchange can carry for a fix (600 doubles)
    add("contacts", "with its state variables beyond the exchange buffer",
        "fix w all wall/rigid " + SURF + " law bonded_interface props 1e-4 1e7 0.3 1e9 0 "
        "1e-3 10 contacts 40 type 2", "40 contacts")
    add("type", "beyond the material types", "fix w all wall/rigid " + SURF +
        " law hertz type 9", "9")
    # words
    add("curvature", "missing", HERTZ + " curvature", "")
    add("curvature", "wrong word", HERTZ + " curvature maybe", "maybe")
    add("pnewdt", "missing", HERTZ + " pnewdt", "")
    add("pnewdt", "wrong word", HERTZ + " pnewdt halt", "halt")
    add("area", "wrong word", HERTZ + " area nodes", "nodes")
    add("move", "wrong word", HERTZ + " move circular 1 0 0", "")
    add("move", "missing", HERTZ + " move", "")
    add("rotate", "missing", HERTZ + " rotate", "")
    add("law", "missing", "fix w all wall/rigid " + SURF + " type 2 law", "")
    add("law", "unknown", "fix w all wall/rigid " + SURF + " law hurtz type 2", "hurtz")
    add("name", "missing", HERTZ + " name", "")
    add("surface", "unknown name", HERTZ + " name roof", "roof")
    add("predef", "missing", HERTZ + " predef", "")
    add("predef", "no such fix", HERTZ + " predef nosuchfix", "nosuchfix")
    add("law", "vuinter missing source", "fix w all wall/rigid " + SURF +
        " law vuinter nosuch.f type 2", "nosuch.f: cannot read")
    # files
    for label, f in (("missing file", "nosuch.inp"), ("empty file", "empty.inp"),
                     ("directory", "subdir")):
        add("surface", label, "fix w all wall/rigid surface %s %s" % (f, LAW), f)
    add("surface", "missing", "fix w all wall/rigid " + LAW + " surface", "")
    for law in ("vuinter", "user"):
        for label, f in (("missing file", "nosuch.so"), ("empty file", "empty.so"),
                         ("directory", "subdir")):
            extra = " mylaw" if law == "user" else ""
            add("law", "%s %s" % (law, label),
                "fix w all wall/rigid %s law %s %s%s type 2" % (SURF, law, f, extra), f)
        add("law", "%s missing library" % law,
            "fix w all wall/rigid %s law %s" % (SURF, law), "")
    add("vtk", "a directory", HERTZ + " vtk subdir 1", "subdir")
    add("vtk", "missing folder", HERTZ + " vtk nodir/wall.vtk 1", "nodir/wall.vtk")
    add("vtk", "missing", HERTZ + " vtk", "")
    return out


def body(s):
    s.write("plane.inp", L.plane_z(0.0, 1.0))
    s.write("empty.inp", "")
    s.write("empty.so", "")
    os.mkdir(s.path("subdir"))
    rc, out = s.run("valid", L.one_sphere_deck(HERTZ + " tracking 0.001 vtk wall.vtk 5"), expect_ok=False)
    if not s.ck.check("the valid line runs", rc == 0, "exit %s" % rc,
                      why="\n".join(out.splitlines()[-5:])):
        return
    cs = cases()
    s.ck.check("at least 100 bad values", len(cs) >= 100, "%d" % len(cs))
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        runs = list(pool.map(lambda kc: s.run("bad%03d" % kc[0], L.one_sphere_deck(kc[1][1]),
                                              expect_ok=False, timeout=60),
                             enumerate(cs)))
    for (name, line, want), (rc, out) in zip(cs, runs):
        L.check_rejected(s.ck, name, line, want, rc, out)

if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
