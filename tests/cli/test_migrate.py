#!/usr/bin/python3
"""rigidsurf-migrate on small decks: the placement against the hand translations of
docs/migration.md and against LIGGGHTS's transforms applied point by point, the lines it
must keep byte for byte, its reports (each names its line) and its exit status.

Usage: test_migrate.py PATH/TO/rigidsurf-migrate
"""
import difflib
import importlib.util
import math
import os
import random
import re
import subprocess
import sys
import tempfile

EXE = sys.argv[1]
HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location(
    "rigidsurf_migrate", os.path.join(HERE, "..", "..", "src", "cli", "rigidsurf_migrate.py"))
M = importlib.util.module_from_spec(spec)
spec.loader.exec_module(M)
TMP = tempfile.mkdtemp(prefix="rs_migrate_")
passed = failed = 0


def check(name, cond, detail=""):
    """Counts and prints one check; returns cond."""
    global passed, failed
    if cond:
        passed += 1
        print("ok   " + name)
    else:
        failed += 1
        print("FAIL " + name + (": " + detail if detail else ""))
    return cond


def run(deck):
    path = os.path.join(TMP, "in.deck")
    with open(path, "w", newline="") as f:
        f.write(deck)
    p = subprocess.run([EXE, path], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def close(a, b, tol=1e-12):
    return all(abs(x - y) <= tol * max(1.0, abs(x), abs(y)) for x, y in zip(a, b))


# ---- placement --------------------------------------------------------------------------
# The hand translations of docs/migration.md and tests/liggghts/test_tutorial_meshes.py
# (each run there against stock LIGGGHTS).
HAND = [
    ("meshGran: scale 0.001 move 0 0 0 rotate axis 1 0 0 angle -90",
     [("scale", 0.001), ("move", (0, 0, 0)), ("rotate", (1, 0, 0), -90)],
     0.001, [0, 0, 0, 1, 0, 0, 0, 0, -1]),
    ("movingMeshGran: move -50 -250 0 scale 0.002 rotate y 90 rotate z 90",
     [("move", (-50, -250, 0)), ("scale", 0.002), ("rotate", (0, 1, 0), 90),
      ("rotate", (0, 0, 1), 90)],
     0.002, [0.5, 0, 0.1, 0.5, 0, -0.9, -0.5, 0, 0.1]),
]
for name, ops, s_want, abc_want in HAND:
    s, a, b, c = M.compose_placement(ops)
    check("placement " + name, abs(s - s_want) < 1e-15 and close(a + b + c, abc_want),
          "%r %r" % (s, a + b + c))


def liggghts_point(ops, X):
    """LIGGGHTS's mesh/surface: each op applied to the node in the order written."""
    x = list(X)
    for op in ops:
        if op[0] == "scale":
            x = [op[1] * v for v in x]
        elif op[0] == "move":
            x = [v + m for v, m in zip(x, op[1])]
        else:  # Rodrigues about the axis through the origin
            n = math.sqrt(sum(v * v for v in op[1]))
            k = [v / n for v in op[1]]
            t = math.radians(op[2])
            kx = [k[1] * x[2] - k[2] * x[1], k[2] * x[0] - k[0] * x[2], k[0] * x[1] - k[1] * x[0]]
            kd = sum(p * q for p, q in zip(k, x))
            x = [x[i] * math.cos(t) + kx[i] * math.sin(t) + k[i] * kd * (1 - math.cos(t))
                 for i in range(3)]
    return x


rng = random.Random(3)
worst = 0.0
for trial in range(200):
    ops = []
    for _ in range(rng.randint(1, 5)):
        kind = rng.choice(("scale", "move", "rotate"))
        if kind == "scale":
            ops.append(("scale", rng.uniform(0.1, 3)))
        elif kind == "move":
            ops.append(("move", [rng.uniform(-2, 2) for _ in range(3)]))
        else:
            ops.append(("rotate", [rng.uniform(-1, 1) for _ in range(3)], rng.uniform(-180, 180)))
    s, a, b, c = M.compose_placement(ops)
    ex = [q - p for p, q in zip(a, b)]
    ey = [q - p for p, q in zip(a, c)]
    ez = [ex[1] * ey[2] - ex[2] * ey[1], ex[2] * ey[0] - ex[0] * ey[2], ex[0] * ey[1] - ex[1] * ey[0]]
    for _ in range(5):
        X = [rng.uniform(-1, 1) for _ in range(3)]
        want = liggghts_point(ops, X)
        got = [a[i] + s * (X[0] * ex[i] + X[1] * ey[i] + X[2] * ez[i]) for i in range(3)]
        worst = max(worst, max(abs(p - q) for p, q in zip(want, got)))
check("placement: x = a + s (X ex + Y ey + Z ez) is LIGGGHTS's scale/move/rotate in the "
      "order written (200 random sequences)", worst < 1e-12, "worst %.3g" % worst)

# ---- lines kept byte for byte ---------------------------------------------------------
DECK = """# a deck with comments, continuations, tabs and blank lines
atom_style\tgranular   # trailing comment
region\t\treg block -0.05 0.05 -0.05 0.05 0. 0.15 units box
create_box\t1 reg

variable  h equal 0.15 # height
fix m1 all property/global youngsModulus &
    peratomtype 5.e6
fix  zwalls1 all wall/gran model hertz tangential history primitive type 1  zplane 0.0 # floor
fix zwalls2 all wall/gran model hertz tangential history &
\tprimitive type 1 zplane ${h}
fix\t\tcad all mesh/surface file meshes/a.stl type 1 scale 0.001 & 
\t\trotate axis 1 0 0 angle -90 # the chute

fix walls all wall/gran model hooke tangential history mesh n_meshes 1 meshes cad
fix mv all move/mesh mesh cad linear 0. 0. -0.1
run 1000
unfix mv
run 1000   # settle
"""
WALL_LINES = {9, 10, 11, 12, 13, 15, 16, 18}   # the wall, mesh and move/mesh lines


def strip_new(out):
    """The output without the commands the tool wrote: wall/rigid fixes (with their
    continuation lines) and its rs_ variables."""
    keep, cont = [], False
    for line in out.splitlines(keepends=True):
        new = cont or re.match(r"fix\s+\S+\s+\S+\s+wall/rigid\b", line) or \
            re.match(r"variable rs_", line)
        cont = bool(new) and line.rstrip().endswith("&")
        if not new:
            keep.append(line)
    return "".join(keep)


rc, out, err = run(DECK)
check("a deck whose walls all translate: exit 0", rc == 0, err)
# a removed command's comment stays on a line of its own; a translated one's on its line
orig = "".join("# the chute\n" if i == 12 else "" if i in WALL_LINES else l
               for i, l in enumerate(DECK.splitlines(keepends=True), 1))
kept = strip_new(out)
check("every other line byte for byte, comments included", kept == orig,
      "\n--- got\n%s--- want\n%s" % (kept, orig))
check("the wall lines' comments are kept", "# floor" in out and "# the chute" in out, out)
check("the primitive walls keep their IDs, on both sides",
      len(re.findall(r"^fix (zwalls1|zwalls2) all wall/rigid .*", out, re.M)) == 2 and
      out.count("sides 2") == 2 and "zplane" not in out, out)
check("the mesh wall takes its mesh's ID and placement, and the motion as rates",
      re.search(r"fix cad all wall/rigid surface inline mesh meshes/a.stl scale 0.001\s*&?\s*"
                r"place 0 0 0 1 0 0 0 0 -1 law hooke type 1", out) is not None and
      "move linear v_rs_cad_vx v_rs_cad_vy v_rs_cad_vz" in out.replace(" &\n    ", " ") and
      "variable rs_cad_vz equal -0.1" in out and out.count("variable rs_cad_vz equal 0") == 2,
      out)

# ---- reports ------------------------------------------------------------------------------
BAD = """region reg block 0 1 0 1 0 1 units box
create_box 1 reg
fix w1 all wall/gran model hertz tangential history rolling_friction cdt primitive type 1 zplane 0
fix w2 all wall/gran model hertz tangential history primitive type 1 zplane 1 shear x 1.0
fix s1 all mesh/surface/stress/servo file a.stl type 1 com 0 0 0 ctrlPV force axis 0 0 1 target_val 10 vel_max 1
fix w3 all wall/gran model hertz tangential history mesh n_meshes 1 meshes s1
fix m2 all mesh/surface/stress file b.stl type 1
fix w4 all wall/gran model hooke tangential history mesh n_meshes 1 meshes m2
fix wig all move/mesh mesh m2 wiggle amplitude 0.1 0 0 period 0.1
fix ok all wall/gran model hertz tangential history primitive type 1 xcylinder 0.5 0.5 0.5
fix f all ave/time 1 1 1 f_w1
"""
rc, out, err = run(BAD)
lines = BAD.splitlines()
reps = [l for l in err.splitlines() if l.startswith("LINE")]
check("walls kept: exit 3", rc == 3, "exit %d" % rc)
check("every report names its line, and that line is the wall's", reps and all(
    re.match(r"LINE (\d+): fix (\S+): ", l) and
    (" %s " % re.match(r"LINE (\d+): fix (\S+): ", l).group(2)) in
    lines[int(re.match(r"LINE (\d+)", l).group(1)) - 1] for l in reps), err)
check("the rolling-friction wall is reported with its model words and kept as written",
      "LINE 3: fix w1: model words 'model hertz tangential history rolling_friction cdt' "
      "have no wall/rigid law yet" in err and "LINE 3: fix w1: the wall is kept as "
      "LIGGGHTS's" in err and lines[2] + "\n" in out, err)
check("shear, the servo and wiggle are reported and their walls kept",
      "LINE 4: fix w2: wall/gran keyword 'shear x'" in err and "LINE 6: fix w3:" in err and
      "mesh/surface/stress/servo" in err and "LINE 8: fix w4: mesh m2 (LINE 7): LINE 9: "
      "move/mesh wiggle has no wall/rigid motion yet" in err and
      all(l + "\n" in out for l in lines[3:9]), err)
check("the other wall is translated, the rest kept", "fix ok all wall/rigid surface inline "
      "revolution origin 0 0.5 0.5 axis 1 0 0" in out.replace(" &\n    ", " ") and
      lines[10] + "\n" in out, out)
check("the summary says how many walls", "rigidsurf-migrate: 1 of 5 wall/gran fixes "
      "translated" in err, err)

REF = """region reg block 0 1 0 1 0 1 units box
create_box 1 reg
fix m all mesh/surface/stress file b.stl type 1 move 0 0 0.5
fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes m
fix f all ave/time 1 1 1 f_m[1] f_m[3] f_m[7] f_w
"""
rc, out, err = run(REF)
check("a reference it cannot keep is named, one it can is not",
      rc == 3 and "LINE 5: f_m[7]" in err and "LINE 5: f_w:" in err and "f_m[1]" not in err
      and "f_m[3]" not in err, err)
rc, out, err = run("fix a all wall/gran model hertz\n")
check("a line it cannot read is kept and reported", rc == 3 and out == "fix a all wall/gran "
      "model hertz\n" and "LINE 1: fix a:" in err, err)
rc, out, err = run("")
check("an empty deck: exit 0, nothing out", rc == 0 and out == "", err)

# ---- the output shown in docs/migration.md is the tool's ---------------------------------
TUT = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
doc = open(os.path.join(HERE, "..", "..", "docs", "migration.md")).read()
m = re.search(r"<!-- migrate-output: (\S+) .*?-->\n```\n(.*?)```\n", doc, re.S)
if check("docs/migration.md shows the tool's output for a deck", m is not None) and \
        os.path.isfile(os.path.join(TUT, m.group(1))):
    deck = os.path.join(TUT, m.group(1))
    p = subprocess.run([EXE, deck], capture_output=True, text=True, timeout=60)
    name = os.path.basename(deck)
    diff = "".join(difflib.unified_diff(open(deck).read().splitlines(True),
                                        p.stdout.splitlines(True), name, name + ".rigid", n=0))
    check("the doc's shown output equals the tool's", m.group(2) == p.stderr + diff,
          "\n--- tool\n%s%s" % (p.stderr, diff))
p = subprocess.run([EXE], capture_output=True, text=True)
check("no argument: usage, exit 2", p.returncode == 2 and "usage" in p.stderr, p.stderr)

print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
