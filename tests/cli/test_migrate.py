#!/usr/bin/python3
"""rigidsurf-migrate on small decks: the placement against the hand translations of
docs/migration.md and against LIGGGHTS's transforms applied point by point, the lines it
must keep byte for byte, the walls, models and motions it translates, its reports (each
names its line), its exit status, and the outputs docs/migration.md shows.

Usage: test_migrate.py PATH/TO/rigidsurf-migrate
"""
import difflib
import math
import os
import random
import re
import sys

import clilib
from clilib import close

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "src", "cli"))
import rigidsurf_migrate_walls as M  # noqa: E402
T = clilib.Tool(sys.argv[1], "rs_migrate_")
TMP = T.tmp
check = T.check
# the meshes the decks below name: one triangle each
for name in ("a.stl", "b.stl", "p.stl", "plate.stl", "meshes/a.stl"):
    T.write(name, clilib.TRI)


def run(deck):
    return T.migrate(deck, cwd=None)


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
# (a wall kept as LIGGGHTS's: exit 3, each report on its wall's line)
BAD = """region reg block 0 1 0 1 0 1 units box
create_box 1 reg
fix w1 all wall/gran model hertz tangential history rolling_friction cdt primitive type 1 zplane 0
fix w2 all wall/gran model hertz tangential history primitive type 1 zplane 1 shear z 1.0
fix s1 all mesh/surface/stress/servo file a.stl type 1 com 0 0 0 ctrlPV force axis 0 0 1 target_val 10 vel_max 1
fix w3 all wall/gran model hertz tangential history mesh n_meshes 1 meshes s1
fix m2 all mesh/surface/stress file b.stl type 1
fix w4 all wall/gran model hooke tangential history mesh n_meshes 1 meshes m2
fix wig all move/mesh mesh m2 vibrot origin 0 0 0 axis 0 0 1 order 2 amplitude 0.1 phase 0 period 0.1
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
check("the rolling-friction wall becomes law liggghts with its model words",
      "fix w1 all wall/rigid surface inline cylinder a 0 0 0 b 1 0 0 c 0 -1 0 sides 2 "
      "profile START" in out.replace(" &\n    ", " ") and
      "law liggghts model hertz tangential history rolling_friction cdt type 1" in
      out.replace(" &\n    ", " ") and "LINE 3: fix w1:" not in err and
      lines[2] + "\n" not in out, out + err)
check("shear along a plane's normal and a vibrot it cannot read are reported and their "
      "walls kept",
      "LINE 4: fix w2: shear z of zplane is a velocity along the plane's normal" in err and
      "LINE 8: fix w4: mesh m2 (LINE 7): LINE 9: "
      "move/mesh vibrot arguments not understood" in err and
      all(l + "\n" in out for l in [lines[3]] + lines[6:9]), err)
check("the servo mesh becomes a wall/rigid with the servo's words",
      "LINE 6: fix w3:" not in err and "fix s1 all wall/rigid surface inline mesh a.stl law "
      "hertz type 1 servo com 0 0 0 ctrlPV force axis 0 0 1 target_val 10 vel_max 1" in
      out.replace(" &\n    ", " ") and lines[4] + "\n" not in out, out + err)
check("the other wall is translated, the rest kept", "fix ok all wall/rigid surface inline "
      "revolution origin 0 0.5 0.5 axis 1 0 0" in out.replace(" &\n    ", " ") and
      lines[10] + "\n" in out, out)
check("the summary says how many walls", "rigidsurf-migrate: 3 of 5 wall/gran fixes "
      "translated" in err, err)

SET = """region reg block 0 1 0 1 0 1 units box
create_box 1 reg
fix w all wall/gran model hooke tangential history primitive type 1 zplane 0 tangential_damping off
fix c all wall/gran model hertz tangential history cohesion sjkr primitive type 1 zplane 1
fix m all wall/gran model hertz tangential history surface multicontact primitive type 1 zplane 2
"""
rc, out, err = run(SET)
flat = out.replace(" &\n    ", " ")
check("a model setting turns law hooke into law liggghts with the setting",
      "law liggghts model hooke tangential history tangential_damping off type 1" in flat,
      out + err)
check("cohesion becomes law liggghts", "law liggghts model hertz tangential history "
      "cohesion sjkr type 1" in flat, out)
check("a surface model is reported and its wall kept",
      rc == 3 and "LINE 5: fix m: model words" in err and "surface multicontact needs "
      "LIGGGHTS's own wall" in err and SET.splitlines()[4] + "\n" in out, err)

# the servo's values (LIGGGHTS: force 1-3, torque about its centre 4-6, the centre 7-9
# and 10-12) from wall/rigid's (force 1-3, moment about the surface origin 4-6, the
# translation 15-17): where they differ a formula, through a variable outside formulas
SERVO = """region reg block 0 1 0 1 0 1 units box
create_box 1 reg
fix s all mesh/surface/stress/servo file a.stl type 1 com 0 0 0.5 ctrlPV force axis 0 0 1 target_val -2 vel_max 0.1 kp 0.5 ki 0.1
fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes s
fix f all ave/time 1 1 1 f_s[3] f_s[6] f_s[9]
variable z equal f_s[12]+f_s[4]
"""
rc, out, err = run(SERVO)
flat = out.replace(" &\n    ", " ")
check("a servo's force, torque about its centre and centre read wall/rigid's values",
      rc == 0 and "servo com 0 0 0.5 ctrlPV force axis 0 0 1 target_val -2 vel_max 0.1 kp "
      "0.5 ki 0.1" in flat and
      "fix f all ave/time 1 1 1 f_s[3] f_s[6] v_rs_s_9\n" in out and
      "variable rs_s_9 equal (0.5+f_s[17])" in out and
      "variable z equal (0.5+f_s[17])+(f_s[4]+0.5*f_s[2])\n" in out, out + err)

REF = """region reg block 0 1 0 1 0 1 units box
create_box 1 reg
fix m all mesh/surface/stress file b.stl type 1 move 0 0 0.5
fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes m
fix f all ave/time 1 1 1 f_m[1] f_m[3] f_m[7] f_m[9] f_m[4]
"""
rc, out, err = run(REF)
check("a stress mesh's reference point (the origin, the mesh placed 0.5 above it) is the "
      "wall's translation, its torque about it wall/rigid's moment moved",
      rc == 0 and "fix f all ave/time 1 1 1 f_m[1] f_m[3] f_m[15] f_m[17] v_rs_m_4\n" in out
      and "variable rs_m_4 equal (f_m[4]-0.5*f_m[2])" in out, out + err)
rc, out, err = run("fix a all wall/gran model hertz\n")
check("a wall/gran LIGGGHTS would refuse (no wall style): exit 1 naming the line, nothing "
      "written", rc == 1 and out == "" and "LINE 1: ERROR: fix a: expects 'primitive' or "
      "'mesh'" in err, err)
rc, out, err = run("")
check("an empty deck: exit 0, nothing out", rc == 0 and out == "", err)

# store_force yes: the same per-atom vector force_ID (wall/rigid's store_force, for the
# meshes of one wall/gran each adding into it); a wall's temperature under fix heat/gran:
# LIGGGHTS's conduction (conduction liggghts)
OUTS = """region reg block 0 1 0 1 0 1 units box
create_box 2 reg
fix p all wall/gran model hertz tangential history primitive type 2 zplane 0 store_force yes temperature 400
fix m1 all mesh/surface file a.stl type 2 temperature 350
fix m2 all mesh/surface file b.stl type 2
fix w all wall/gran model hertz tangential history mesh n_meshes 2 meshes m1 m2 store_force yes
fix heat all heat/gran initial_temperature 300
dump d all custom 10 d.dump id f_force_p[1] f_force_w[3] f_Temp[0]
unfix w
"""
rc, out, err = run(OUTS)
flat = out.replace(" &\n    ", " ")
check("store_force and a temperature under heat/gran are translated, their references kept",
      rc == 0 and "law hertz type 2 store_force yes temperature 400 conduction liggghts" in
      flat and "fix m1 all wall/rigid surface inline mesh a.stl law hertz type 2 temperature "
      "350 conduction liggghts store_force into w" in flat and
      "fix m2 all wall/rigid surface inline mesh b.stl law hertz type 2 store_force into w"
      in flat and OUTS.splitlines()[7] + "\n" in out and "LINE" not in err and
      out.endswith("unfix m2\nunfix m1\n"), out + err)
rc, out, err = run(OUTS.replace("fix heat all heat/gran initial_temperature 300\n", ""))
check("a temperature without fix heat/gran conducts nothing, as LIGGGHTS's",
      rc == 0 and "conduction" not in out and "temperature 400" in out, out + err)

# ---- oscillating move/mesh: the rates against LIGGGHTS's mesh movers ---------------------
# LIGGGHTS's mesh velocities (src/mesh_mover_linear.cpp, mesh_mover_rotation.cpp) at
# dTAbs, the time since the move fix was made; a rotation's in rad/time about the unit
# axis.
def lig_wiggle(amp, period, t):
    w = 2 * math.pi / period
    return [a * w * math.cos(w * t) for a in amp]


def lig_vib(amps, phases, periods, t):
    return -sum(a * (2 * math.pi / p) * math.sin(2 * math.pi / p * t + f)
                for a, f, p in zip(amps, phases, periods))


def lig_viblin(axis, amps, phases, periods, t):
    n = math.sqrt(sum(x * x for x in axis))
    return [x / n * lig_vib(amps, phases, periods, t) for x in axis]


def lig_riggle(period, amp_deg, t):
    w = 2 * math.pi / period
    return math.radians(amp_deg) * w * math.cos(w * t)


DT, T_A = 1e-4, 500
OSC = """region reg block -1 1 -1 1 -1 1 units box
create_box 1 reg
timestep 1e-4
fix m all mesh/surface file p.stl type 1
fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes m
run 500
fix a all move/mesh mesh m wiggle amplitude 0.1 -0.2 0 period 0.3
fix b all move/mesh mesh m viblin axis 1 2 2 order 2 amplitude 0.01 0.02 phase 0.5 -1 period 0.1 0.07
run 1000
unfix a
run 100
unfix b
fix r all move/mesh mesh m riggle origin 0.1 0.2 0.3 axis 0 0 1 period 0.2 amplitude 5
run 100
unfix r
fix r2 all move/mesh mesh m vibrot origin 0.1 0.2 0.3 axis 0 0 1 order 2 amplitude 0.1 0.05 phase 0.3 0 period 0.2 0.1
run 100
"""
WIG = ((0.1, -0.2, 0.0), 0.3)
VIB = ((1, 2, 2), (0.01, 0.02), (0.5, -1), (0.1, 0.07))
VROT = ((0.1, 0.05), (0.3, 0), (0.2, 0.1))
# the motions of each run: (t0 of each active fix, as a function of the step)
RUNS = [
    (500, lambda st: ([0, 0, 0], 0.0)),
    (1000, lambda st: ([x + y for x, y in zip(lig_wiggle(*WIG, (st - 500) * DT),
                                               lig_viblin(*VIB, (st - 500) * DT))], 0.0)),
    (100, lambda st: (lig_viblin(*VIB, (st - 500) * DT), 0.0)),
    (100, lambda st: ([0, 0, 0], lig_riggle(0.2, 5, (st - 1600) * DT))),
    (100, lambda st: ([0, 0, 0], lig_vib(*VROT, (st - 1700) * DT))),
]


def evaluate(expr, env, time):
    """An equal-style formula of the migrated deck (numbers, PI, time, v_ names, + - * /
    ^, sin, cos) as LIGGGHTS computes it."""
    t = re.sub(r"\bv_(\w+)", lambda m: "(%r)" % evaluate(env[m.group(1)], env, time), expr)
    t = t.replace("PI", "pi").replace("^", "**")
    return eval(t, {"__builtins__": {}}, {"pi": math.pi, "time": time, "sin": math.sin,
                                          "cos": math.cos, "sqrt": math.sqrt})


rc, out, err = run(OSC)
check("wiggle, viblin, riggle and vibrot translate: exit 0", rc == 0, err)
flat = out.replace(" &\n    ", " ")
env, step, worst, snaps = {}, 0, 0.0, 0
for line in flat.splitlines():
    w = line.split()
    if w[:1] == ["variable"] and w[2] == "equal":
        # $(time) is the time where the line stands, as LIGGGHTS substitutes it
        env[w[1]] = " ".join(w[3:]).replace("$(time)", repr(step * DT))
    elif w[:1] == ["run"]:
        n, want = RUNS[snaps]
        for st in range(step + 1, step + int(w[1]) + 1, 7):
            v, om = want(st)
            got = [evaluate("v_rs_m_%s" % k, env, st * DT) for k in ("vx", "vy", "vz")]
            got_om = evaluate("v_rs_m_om", env, st * DT)
            worst = max([worst, abs(got_om - om)] + [abs(p - q) for p, q in zip(got, v)])
        step += int(w[1])
        snaps += 1
check("each run's rates are LIGGGHTS's mesh velocities at the time since each move fix "
      "was made (superposed wiggle + viblin, then viblin, riggle, vibrot; every 7th step)",
      snaps == len(RUNS) and worst < 1e-12, "%d runs, worst %.3g" % (snaps, worst))
check("the time origins are set where the move fixes stand",
      [l for l in flat.splitlines() if l.endswith("$(time)")] ==
      ["variable rs_%s_t0 equal $(time)" % f for f in ("a", "b", "r", "r2")] and
      flat.index("rs_b_t0") > flat.index("rs_a_t0") > flat.index("\nrun 500"), flat)
# the rotation's origin: LIGGGHTS's fixed point, less the translation so far, summed as
# LIGGGHTS moves the mesh (v(k dt) dt at the k-th step)
D = [0.0, 0.0, 0.0]
for k in range(1, 1101):
    v = lig_viblin(*VIB, k * DT)
    if k <= 1000:
        v = [x + y for x, y in zip(v, lig_wiggle(*WIG, k * DT))]
    D = [d + x * DT for d, x in zip(D, v)]
mo = re.search(r"rotate origin (\S+) (\S+) (\S+) axis 0 0 1 omega v_rs_m_om", flat)
check("riggle and vibrot turn the wall about LIGGGHTS's fixed point less the translation "
      "before them", mo is not None and
      close([float(x) for x in mo.groups()], [p - d for p, d in zip((0.1, 0.2, 0.3), D)],
            1e-10), "%s vs %r" % (mo and mo.groups(), [p - d for p, d in
                                                        zip((0.1, 0.2, 0.3), D)]))

# what one wall/rigid cannot do: said with the line, the wall kept
CANNOT = {
    "a translation made while two rotations run":
    ("fix r all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1 period 4\n"
     "fix r2 all move/mesh mesh m rotate origin 0.1 0 0 axis 0 0 1 period 2\n"
     "fix a all move/mesh mesh m linear 0 0 1\n",
     "LINE 9 moves it while two rotations turn it: LIGGGHTS's translation, made after "
     "them, does not carry the second one's origin"),
    "a second rotation made after the first turned the wall":
    ("fix r all move/mesh mesh m riggle origin 0 0 0 axis 0 0 1 period 0.2 amplitude 5\n"
     "run 10\nfix r2 all move/mesh mesh m rotate origin 0.1 0 0 axis 0 0 1 period 2\n",
     "LINE 9 turns it while another move/mesh turns it, where wall/rigid's spin needs"),
    "a rotation's origin fixed in space, then carried by a translation":
    ("fix r all move/mesh mesh m riggle origin 0 0 0 axis 0 0 1 period 0.2 amplitude 5\n"
     "fix a all move/mesh mesh m linear 0 0 1\nrun 10\nunfix r\n"
     "fix r2 all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1 period 2\n",
     "LINE 11 makes a translation and a rotation run together with the rotation's origin "
     "carried by the translation, where before it was fixed in space"),
    "two rotation axes":
    ("fix r all move/mesh mesh m riggle origin 0 0 0 axis 0 0 1 period 0.2 amplitude 5\n"
     "run 10\nunfix r\n"
     "fix r2 all move/mesh mesh m vibrot origin 0 0 0 axis 1 0 0 order 1 amplitude 0.1 "
     "phase 0 period 0.2\n", "LINE 10 turns it about another axis"),
    "a second rotation after a translation running since the first carried it on":
    ("fix a all move/mesh mesh m linear 0 0 1\n"
     "fix r all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1 period 2\nrun 10\n"
     "unfix r\nfix r2 all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1 period 3\n",
     "LINE 11 turns it about another axis, or after it moved on since its first rotation"),
    "the time origin in a restart file":
    ("read_restart a.restart\n"
     "fix a all move/mesh mesh m wiggle amplitude 0 0 0.1 period 0.3\n",
     "LINE 8: move/mesh wiggle after read_restart (LINE 7)"),
    "a viblin without its periods":
    ("fix a all move/mesh mesh m viblin axis 0 0 1 order 2 amplitude 0.1 0.2 phase 0 0\n",
     "LINE 7: move/mesh viblin arguments not understood"),
}
head = "\n".join(OSC.splitlines()[:6]) + "\n"
for name, (tail, want) in CANNOT.items():
    deck = head + tail + "run 10\n"
    rc, out, err = run(deck)
    check("reported: " + name, rc == 3 and "LINE 5: fix w: mesh m (LINE 4): " + want in err
          and "LINE 5: fix w: the wall is kept as LIGGGHTS's" in err and out == deck, err)

# a rotation made while a translation runs turns about an origin the translation carries
# (LIGGGHTS's FixMesh::move carries the movers made after the caller): wall/rigid's move +
# rotate, the origin LIGGGHTS's fixed point less the translation before it
deck = head + ("fix a all move/mesh mesh m linear 0.5 0 0\nrun 100\n"
               "fix r all move/mesh mesh m rotate origin 0.1 0.2 0.3 axis 0 1 0 period 2\n"
               "run 10\n")
rc, out, err = run(deck)
flat = out.replace(" &\n    ", " ")
check("a rotation made while a translation runs: move linear and rotate about the origin "
      "less the translation so far",
      rc == 0 and "move linear v_rs_m_vx v_rs_m_vy v_rs_m_vz rotate origin 0.095 0.2 0.3 "
      "axis 0 1 0 omega v_rs_m_om" in flat and "variable rs_m_vx equal 0.5" in flat and
      "variable rs_m_om equal 2*PI/(2)" in flat, out + err)

# a translation made while a rotation runs, the rotation the mesh's first mover: the
# rotation's origin stays where LIGGGHTS puts it back each step, in space, the
# translation before the rotation included (rotate ... centre fixed)
deck = head + ("fix a all move/mesh mesh m linear 0.5 0 0\nrun 100\nunfix a\n"
               "fix r all move/mesh mesh m rotate origin 0.1 0.2 0.3 axis 0 1 0 period 2\n"
               "fix b all move/mesh mesh m linear 0 0 0.25\nrun 10\n")
rc, out, err = run(deck)
flat = out.replace(" &\n    ", " ")
check("a translation made while the first mover rotates it: rotate about the origin as "
      "given, centre fixed",
      rc == 0 and "move linear v_rs_m_vx v_rs_m_vy v_rs_m_vz rotate origin 0.1 0.2 0.3 "
      "axis 0 1 0 omega v_rs_m_om centre fixed" in flat and
      "variable rs_m_vz equal 0.25" in flat, out + err)

# two rotations at once: the second turns about an origin the first carries, its axis
# fixed in direction (LIGGGHTS's FixMesh::rotate): wall/rigid's rotate and spin
deck = head + ("fix r all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1 period 4\n"
               "fix r2 all move/mesh mesh m riggle origin 0.1 0 0 axis 1 0 0 period 0.2 "
               "amplitude 5\nrun 10\nunfix r2\nrun 10\n")
rc, out, err = run(deck)
flat = out.replace(" &\n    ", " ")
check("two rotations at once: rotate and spin, each with its rate",
      rc == 0 and "rotate origin 0 0 0 axis 0 0 1 omega v_rs_m_om spin origin 0.1 0 0 "
      "axis 1 0 0 omega v_rs_m_om2" in flat and "variable rs_m_om equal 2*PI/(4)" in flat
      and "variable rs_m_om2 equal 5*PI/180*" in flat and
      "variable rs_m_om2 equal 0" in flat.split("unfix r2")[0] + flat, out + err)

# wall/gran shear of primitive walls: in the tangent plane it is surface_vel
SHEAR = {"zplane 0 shear x 0.5": "surface_vel 0.5 0 0",
         "xplane 0 shear y -1": "surface_vel 0 -1 0",
         "zcylinder 0.5 0 0 shear z 2": "surface_vel 0 0 2",
         "zplane 0 shear z 0.5": "shear z of zplane is a velocity along the plane's normal",
         "zcylinder 0.5 0 0 shear x 2": "shear x of zcylinder is LIGGGHTS's spin"}
for args, want in SHEAR.items():
    deck = "fix w all wall/gran model hertz tangential history primitive type 1 %s\n" % args
    rc, out, err = run(deck)
    if want.startswith("surface_vel"):
        check("shear: %s is %s" % (args, want), rc == 0 and want in out.replace(" &\n    ", " "),
              out + err)
    else:
        check("shear: %s is reported, the wall kept" % args,
              rc == 3 and "LINE 1: fix w: " + want in err and out == deck, err)

# ---- the output shown in docs/migration.md is the tool's ---------------------------------
TUT = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
doc = open(os.path.join(HERE, "..", "..", "docs", "migration.md")).read()
m = re.search(r"<!-- migrate-output: (\S+) .*?-->\n```\n(.*?)```\n", doc, re.S)
if check("docs/migration.md shows the tool's output for a deck", m is not None) and \
        os.path.isfile(os.path.join(TUT, m.group(1))):
    deck = os.path.join(TUT, m.group(1))
    rc, out, err = T.run([deck])
    name = os.path.basename(deck)
    diff = "".join(difflib.unified_diff(open(deck).read().splitlines(True),
                                        out.splitlines(True), name, name + ".rigid", n=0))
    check("the doc's shown output equals the tool's", m.group(2) == err + diff,
          "\n--- tool\n%s%s" % (err, diff))
# each migrate-example of the page: the second block is the tool's output for the first
examples = re.findall(r"<!-- migrate-example .*?-->\n```\n(.*?)```\n```\n(.*?)```\n", doc,
                      re.S)
check("docs/migration.md shows examples of the tool's output", len(examples) > 0)
for deck, want in examples:
    rc, out, err = run(deck)
    check("the doc's example is the tool's output (%s)" % deck.splitlines()[2][:40],
          rc == 0 and out == want, "\n--- tool\n%s%s" % (out, err))
rc, out, err = T.run([])
check("no argument: usage, exit 1", rc == 1 and "usage" in err, err)
rc, out, err = T.run(["--help"])
doc_codes = re.search(r"<!-- exit-codes[^>]*-->\n```\n(.*?)```", doc, re.S)
check("--help states the exit codes, as docs/migration.md does", rc == 0 and
      "Exit status:" in out and doc_codes is not None and
      doc_codes.group(1) in out, out)

T.finish()
