#!/usr/bin/python3
"""rigidsurf-migrate reads a deck as LIGGGHTS 3.8 reads it (rigidsurf_migrate_deck.py,
rigidsurf_migrate_expr.py, rigidsurf_migrate_commands.py):

- formulas: every formula of FORMULAS evaluated by stock LIGGGHTS (`print "$(...)"`,
  which writes 20 digits) and by the tool, to 1e-15 relative, and the formulas LIGGGHTS
  stops at (x^0, x/0, sqrt(-1), ...) are errors of the tool too;
- variables (`${}`, `$x`, `$()`, index variables defined once, `-var`), `include`
  (walls written into the deck in place of the line), loops of `label`, `jump`, `next`,
  and `if`, each against what LIGGGHTS runs: the deck's `print` lines as stock LIGGGHTS
  prints them are the tool's values;
- control flow it cannot follow (a condition that depends on the run) is an error
  naming the line when a wall's command may run after it, a NOTE when none does;
- what LIGGGHTS refuses on a wall (an unknown word, a word after the settings, an
  unknown model, a missing mesh file) is an error naming the word and the line, and
  nothing is written.

Usage: test_migrate_reader.py PATH/TO/rigidsurf-migrate
"""
import os
import re
import shutil
import subprocess
import sys

import clilib

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "src", "cli"))
import rigidsurf_migrate_expr as E  # noqa: E402

LIGGGHTS = shutil.which("liggghts")
T = clilib.Tool(sys.argv[1], "rs_reader_")
TMP = T.tmp
check, write, migrate = T.check, T.write, T.migrate
for name in ("a.stl", "b.stl"):
    write(name, clilib.TRI)


def stock(deck, args=()):
    p = subprocess.run([LIGGGHTS, "-in", write("in.stock", deck), "-log", "none", "-echo",
                        "none"] + list(args), capture_output=True, text=True, timeout=60, errors="replace",
                       cwd=TMP)
    return p.returncode, p.stdout + p.stderr


BOX = "region reg block -1 1 -1 1 -1 1 units box\ncreate_box 1 reg\n"
PLANE = "fix %s all wall/gran model hertz tangential history primitive type 1 zplane %s\n"
MESH = ("fix m all mesh/surface file a.stl type 1 %s\n"
        "fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes m\n")


def flat(out):
    return out.replace(" &\n    ", " ")


def place(out):
    """The placement a b c of the deck's first mesh wall."""
    m = re.search(r"place((?: \S+){9})", flat(out))
    return [float(x) for x in m.group(1).split()] if m else None


# ---- formulas ------------------------------------------------------------------------
FORMULAS = ["-2^2", "2^-2", "2^3^2", "-2^2*3", "2*-3^2", "-(2^2)", "!0+1", "!1*5",
            "5%3", "-7%3", "2*3%4", "1+2*3-4/8", "1<2==1", "2>1&&0||1", "3>=3", "1!=1",
            "(1+2)*(3-4)", "-v_a^2", "v_a^v_a^v_a", "PI", "sqrt(2)", "exp(1)", "ln(10)",
            "log(1000)", "abs(-3.5)", "sin(PI/6)", "cos(1)", "tan(0.3)", "asin(0.5)",
            "acos(-1)", "atan(1)", "atan2(-1,-1)", "ceil(-2.5)", "floor(-2.5)",
            "round(2.5)", "round(-2.5)", "round(-2.6)", "1e3*2", "1.5e-3+.5", "2.e1",
            "v_b*2", "v_c", "-v_a--v_a", "2^0.5^2", "(-8)^(1/3)"]
# (a ${} inside $() is not substituted first: LIGGGHTS reads its $ as a formula's)
ERRORS = ["2^0", "1/0", "1%0", "sqrt(-1)", "ln(0)", "log(-1)", "asin(2)", "2+*3", "(1+2",
          "v_nosuch", "foo(1)", "1 2", "${b}+1"]
VARS = 'variable a equal 2\nvariable b index 3.5\nvariable c equal "v_a*v_b"\n'

if check("stock liggghts present", LIGGGHTS is not None):
    deck = VARS + "".join('print "F%d $(%s)"\n' % (k, f) for k, f in enumerate(FORMULAS))
    rc, out = stock(deck)
    lig = {int(m.group(1)): m.group(2) for m in re.finditer(r"^F(\d+) (\S+)$", out, re.M)}

    class Env:
        vals = {"a": 2.0, "b": 3.5}

        def variable(self, name):
            if name == "c":
                return float("%.15g" % (2.0 * 3.5))
            if name not in self.vals:
                raise E.FormulaError("Invalid variable name in variable formula")
            return self.vals[name]

        def thermo(self, word):
            raise E.Unknown(word)

    worst, bad = 0.0, []
    for k, f in enumerate(FORMULAS):
        try:
            mine = E.evaluate(f, Env())
        except Exception as e:  # noqa: BLE001
            mine = "%s" % e
        want = lig.get(k)
        try:
            want = float(want)
            ok = isinstance(mine, float) and (mine == want or (want != want and mine != mine)
                                              or abs(mine - want) <= 1e-15 * abs(want))
        except (TypeError, ValueError):
            ok = False
        if not ok:
            bad.append("%s: LIGGGHTS %s, tool %s" % (f, lig.get(k), mine))
    check("%d formulas evaluate as stock LIGGGHTS evaluates them (precedence, unary minus "
          "before ^, left-to-right ^, %%, functions, variables)" % len(FORMULAS),
          rc == 0 and len(lig) == len(FORMULAS) and not bad, "; ".join(bad) + out[-300:])
    errs = []
    for f in ERRORS:
        rc, out = stock(VARS + 'print "$(%s)"\n' % f)
        try:
            E.evaluate(f, Env())
            errs.append("%s: the tool evaluates it, LIGGGHTS exits %d" % (f, rc))
        except E.FormulaError:
            if rc == 0:
                errs.append("%s: LIGGGHTS evaluates it" % f)
    check("formulas LIGGGHTS stops at are errors of the tool (%s)" % " ".join(ERRORS),
          not errs, "; ".join(errs))
    BOOLS = ["1 < 2", "-1 > -2", "!1", "2 == 2 && 3 != 3", "(1 < 2) || 0", "1.5e1 >= 15"]
    deck = "".join('if "%s" then "print B%d_1" else "print B%d_0"\n' % (b, k, k)
                   for k, b in enumerate(BOOLS))
    rc, out = stock(deck)
    lig = dict(re.findall(r"^B(\d+)_(\d)$", out, re.M))
    mine = {str(k): "1" if E.evaluate_boolean(b) else "0" for k, b in enumerate(BOOLS)}
    check("if conditions: the tool's are LIGGGHTS's (%d)" % len(BOOLS), lig == mine,
          "%r vs %r" % (lig, mine))

# ---- variables and substitution, as LIGGGHTS substitutes them ---------------------------
# each deck prints what the tool computes; the tool's placement must be LIGGGHTS's numbers
SUBST = BOX + VARS + """variable b index 9
variable d index 0.25
variable e string "0.5"
variable x loop 2 10 pad
variable z equal $(v_a*v_d+v_e)
variable y equal ${d}+$e
print "P ${z} $x ${b} ${y}"
""" + MESH % "move 0 ${d} $(-v_a^2*0.01) scale $(v_z*2)"
rc, out = stock(SUBST.replace(MESH % "move 0 ${d} $(-v_a^2*0.01) scale $(v_z*2)", "") +
                'print "Q $(-v_a^2*0.01) $(v_z*2)"\n')
m = re.search(r"^P (\S+) (\S+) (\S+) (\S+)$", out, re.M)
q = re.search(r"^Q (\S+) (\S+)$", out, re.M)
rc2, mig, err = migrate(SUBST)
if check("stock liggghts prints the deck's values", m is not None and q is not None, out):
    s = float(q.group(2))
    want = [0.0, 0.25 * s, float(q.group(1)) * s]
    got = place(mig)
    check("${}, $x, $(): an index variable keeps its first value, a loop pads, the "
          "placement's values are LIGGGHTS's", rc2 == 0 and
          m.groups() == ("1", "02", "3.5", "0.75")
          and "scale %g" % s in flat(mig) and got is not None and
          all(abs(g - w) < 1e-12 for g, w in zip(got[:3], want)),
          "%s %s %s" % (m.groups(), got, err))
rc, mig, err = migrate(BOX + "variable s index 1\n" + MESH % "scale ${s}", ["-var", "s", "3"])
check("-var defines an index variable before the deck, as on LIGGGHTS's command line",
      rc == 0 and "scale 3 " in flat(mig), mig + err)

# ---- include -----------------------------------------------------------------------------
write("in.walls", "variable zw equal 0.1\n" + PLANE % ("w2", "${zw}"))
write("in.vars", "variable h equal 0.3\n")
deck = BOX + "include in.vars\n" + PLANE % ("w1", "${h}") + "include in.walls # walls\n" \
    + "run 0\n"
rc, mig, err = migrate(deck)
check("include: a file without walls stays an include; one with walls is written in place "
      "of its line, migrated, between comments naming it",
      rc == 0 and "include in.vars\n" in mig and "include in.walls" not in mig.replace(
          "# rigidsurf-migrate: include in.walls # walls, migrated", "") and
      "# rigidsurf-migrate: include in.walls # walls, migrated\nvariable zw equal 0.1\n"
      "fix w2 all wall/rigid" in mig and "# rigidsurf-migrate: end of in.walls\nrun 0\n"
      in mig and "zplane" not in mig and "a 0 0 ${h}" in flat(mig) and
      "NOTE: in.walls holds walls" in err, mig + err)
rc, mig, err = migrate(BOX + "include in.nosuch\n")
check("include of a missing file: exit 1 naming the line", rc == 1 and mig == "" and
      "LINE 3: ERROR: Cannot open input script in.nosuch" in err, err)
write("in.jumpy", "label a\n" + PLANE % ("w3", "0"))
rc, mig, err = migrate(BOX + "include in.jumpy\n")
check("an included file with walls and labels: exit 1 (its jumps would mean the deck)",
      rc == 1 and "LINE 3: ERROR: the included in.jumpy holds walls and jump or label" in err,
      err)

# ---- loops and if ------------------------------------------------------------------------
LOOP = BOX + """variable i loop 3
label top
fix w$i all wall/gran model hertz tangential history primitive type 1 zplane $(0.1*v_i)
print "W w$i $(0.1*v_i)"
next i
print "the exhausted next skips the next jump, not the next command"
jump SELF top
if "${a} > 1" then "print A1" elif "${a} > 0" "print A0" else "print A-"
"""
rc, out = stock("variable a equal 2\n" + LOOP.replace(
    "fix w$i all wall/gran model hertz tangential history primitive type 1 zplane $(0.1*v_i)\n",
    ""))
rc2, mig, err = migrate("variable a equal 2\n" + LOOP)
check("a loop (label, next, a command, jump SELF) runs its wall line 3 times, as LIGGGHTS "
      "does; the line is written once, with its words as written",
      out.count("\nW ") == 3 and rc2 == 0 and "fix w$i all wall/rigid surface inline cylinder "
      "a 0 0 $(0.1*v_i)" in flat(mig) and "1 of 1 wall/gran fixes translated" in err,
      out + mig + err)
rc, mig, err = migrate("variable a equal 2\n" + LOOP.replace(
    "fix w$i all wall/gran model hertz tangential history primitive type 1 zplane $(0.1*v_i)",
    "fix m all mesh/surface file a.stl type 1 move 0 0 $(0.1*v_i)\n"
    "fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes m\n"
    "run 1\nunfix w\nunfix m"))
check("a loop whose mesh's placement differs at each pass: exit 1 (one line, three "
      "placements)", rc == 1 and "runs more than once and would be written differently"
      in err, err)
LONG = BOX + """timestep 1e-4
""" + MESH % "" + """fix mv all move/mesh mesh m linear 0.1 0 0
variable n loop 100000
label pass
run 10
next n
jump SELF pass
unfix mv
fix r all move/mesh mesh m rotate origin 1 0 0 axis 0 0 1 period 2
"""
rc, mig, err = migrate(LONG)
check("a loop of 100000 passes: its steps counted (the mesh moved 0.1 m/s x 100 s when "
      "the rotation is made: the origin 1 - 10 in the wall's reference)",
      rc == 0 and "rotate origin -9 0 0 axis 0 0 1" in flat(mig), err + flat(mig)[-400:])
STOP = BOX + PLANE % ("w", "0") + """label settle
run 100
variable k equal ke
if "${k} < 1e-8" then "jump SELF done"
jump SELF settle
label done
"""
rc, mig, err = migrate(STOP + "run 100\n")
check("an if that depends on the run (ke) and jumps, with no wall command after it: exit 0 "
      "and a NOTE naming it", rc == 0 and "LINE 7: NOTE: the tool follows the deck up to "
      "this line" in err and "fix w all wall/rigid" in mig, err)
rc, mig, err = migrate(STOP + "unfix w\n")
check("the same with a wall's unfix after it: exit 1 naming the if and the line that may "
      "run", rc == 1 and mig == "" and "LINE 7: ERROR: the tool cannot follow the deck past "
      "this line" in err and "LINE 10 ('unfix w')" in err, err)
rc, mig, err = migrate(BOX + PLANE % ("w", "0") + "run 10\nvariable k equal ke\n"
                       'if "${k} > 1" then "unfix w"\n')
check("an if that depends on the run and would unfix a wall: exit 1 naming it",
      rc == 1 and "LINE 6: ERROR: the tool cannot follow this if" in err, err)
rc, mig, err = migrate(BOX + "jump SELF nowhere\n" + PLANE % ("w", "0"))
check("a jump to a label that is not there: exit 1", rc == 1 and "Label wasn't found" in err,
      err)
rc, mig, err = migrate(BOX + "# a comment &\n" + PLANE % ("w", "0"))
check("a comment ending in & takes the next line into the comment, as LIGGGHTS reads it: "
      "no wall", rc == 0 and "0 of 0 wall/gran" in err and "wall/gran" in mig, err)

# ---- what LIGGGHTS refuses on a wall -----------------------------------------------------
REFUSED = {
    "zplane 0 wiggle 3": "'wiggle' is neither a keyword of the wall nor a setting of model "
                         "hertz tangential history",
    "zplane 0 tangential_damping off temperature 300": "'temperature' is neither a keyword",
    "zplane 0 limitForce maybe": "setting 'limitForce' expects on or off, got 'maybe'",
    "zplane": "'primitive' expects 4 values",
    "zblob 0": "'zblob' is not a primitive wall of LIGGGHTS",
}
rc, mig, err = migrate(BOX + "fix w all wall/gran model hertz tangential history shear x 1 "
                       "primitive type 1 zplane 0\n")
check("refused: shear before the primitive wall (LIGGGHTS's order)", rc == 1 and
      "shear needs the primitive wall before it" in err, err)
for args, want in REFUSED.items():
    rc, mig, err = migrate(BOX + "fix w all wall/gran model hertz tangential history "
                           "primitive type 1 " + args + "\n")
    check("refused: '%s': exit 1 naming the word and the line, nothing written" % args,
          rc == 1 and mig == "" and "LINE 3: ERROR: fix w: fix wall/gran: " in err and
          want in err, err)
rc, mig, err = migrate(BOX + "fix w all wall/gran model hertz tangential hystory primitive "
                       "type 1 zplane 0\n")
check("an unknown model name: exit 1 naming it", rc == 1 and "tangential 'hystory' is not "
      "one of LIGGGHTS's" in err, err)
rc, mig, err = migrate(BOX + "fix w all wall/gran model hertz tangential history primitive "
                       "type 1 zplane 0 tangential_damping off\n")
check("a setting of the model: law liggghts with it", rc == 0 and "law liggghts model hertz "
      "tangential history tangential_damping off type 1" in flat(mig), err)
rc, mig, err = migrate(BOX + "fix w all wall/gran model hertz primitive type 1 zplane 0\n")
check("model words without tangential: LIGGGHTS's selector takes no tangential model, so "
      "law liggghts with the words as written (not law hertz)", rc == 0 and
      "law liggghts model hertz type 1" in flat(mig), mig + err)
rc, mig, err = migrate(BOX + "fix m all mesh/surface file nosuch.stl type 1\n"
                       "fix w all wall/gran model hertz tangential history mesh n_meshes 1 "
                       "meshes m\n")
check("a missing mesh file: exit 1 naming the mesh's line and the file", rc == 1 and
      "LINE 3: ERROR: fix m: cannot open mesh file nosuch.stl" in err, err)
rc, mig, err = migrate(BOX + "fix m all mesh/surface file a.stl type 1 scale 2 curvature_x 3\n")
check("an unknown mesh/surface keyword: exit 1 naming it", rc == 1 and "'curvature_x' is not "
      "one of its keywords" in err, err)
# LIGGGHTS's order (FixMesh, then FixMeshSurface): type before scale, curvature after it
for args, want in (("scale 1 type 1", "'type' is not one of its keywords, or comes "
                                     "after"),
                   ("type 1 curvature 0.1 scale 1", "'scale' is not one of its keywords, "
                                                    "or comes after"),
                   ("scale 1", "expects 'type T'")):
    rc, mig, err = migrate(BOX + "fix m all mesh/surface file a.stl %s\n" % args)
    check("mesh/surface '%s': exit 1, as LIGGGHTS stops" % args, rc == 1 and want in err, err)

T.finish()
