#!/usr/bin/python3
"""rigidsurf-migrate on LAMMPS decks (rigidsurf_migrate_lammps*.py), without running them
(tests/lammps/test_migrate_*.py run them against stock lmp):

- the engine: told by the deck's commands, or --engine; a deck with both engines' walls
  is an error naming a line of each;
- the reader's LAMMPS rules: formulas (x^0, |^, $(...:%fmt)), triple quotes, `if` on
  words, format and internal variables, each against what stock lmp prints;
- the surfaces written: planes facing each bound, a zcylinder, a region cylinder's and
  cone's outline with its open faces, a sphere's two arcs, a union's and an
  intersection's outline against hand-drawn ones, a block's and a prism's mesh (its
  facets facing the region's inside, its open face left out), lattice units;
- the motion written: a wiggling plane (move variable along its normal, move linear
  along it), a moving and turning region (its rates from fix ave/time, its pose and
  rotation origin where the wall is made);
- what names a wall: unfix (every wall it became, and the rates' fix), fix_modify,
  f_ID[2-4] of contacts in dumps and formulas;
- exit 3 with each reason on the wall's line and the wall kept as written; exit 1 with the
  line and the command for what LAMMPS would stop at (an unknown keyword or region style,
  a missing file, wiggle with shear, a region that does not exist, f_ID without contacts),
  nothing written.

Usage: test_migrate_lammps.py PATH/TO/rigidsurf-migrate
"""
import math
import os
import re
import shutil
import subprocess
import sys

import clilib

LMP = shutil.which("lmp")
T = clilib.Tool(sys.argv[1], "rs_migrate_lmp_")
TMP = T.tmp
check, write, migrate = T.check, T.write, T.migrate


def flat(out):
    return " ".join(out.replace(" &\n    ", " ").split())


def stock(deck):
    p = subprocess.run([LMP, "-in", write("in.stock", deck), "-log", "none", "-echo",
                        "none"], capture_output=True, text=True, timeout=60, cwd=TMP,
                       errors="replace")
    return p.returncode, p.stdout + p.stderr


HEAD = ("atom_style sphere\nboundary f f f\nunits si\n"
        "region box block -0.1 0.1 -0.1 0.1 -0.05 0.15 units box\ncreate_box 2 box\n")
HOOKE = "hooke 2e5 NULL 50 NULL 0.5 1"
HERTZ = "hertz/history 2e8 NULL 5e3 NULL 0.5 1"


def wall_line(out, fid):
    """The wall/rigid line of fix fid, continuations joined."""
    m = re.search(r"^fix %s \S+ wall/rigid .*$" % re.escape(fid), flat_lines(out), re.M)
    return m.group(0) if m else ""


def flat_lines(out):
    return out.replace(" &\n    ", " ")


def profile(line):
    """The (r, z) or (x, y) points of a wall line's profile (LINE and START)."""
    m = re.search(r"profile (.*?) end", line)
    w = m.group(1).split() if m else []
    pts, k = [], 0
    while k < len(w):
        n = {"START": 2, "LINE": 2, "CIRCL": 4}[w[k]]
        pts.append(tuple(float(x) for x in w[k + 1:k + 3]))
        k += 1 + n
    return pts


def close(a, b, tol=1e-12):
    return len(a) == len(b) and all(
        abs(x - y) <= tol for p, q in zip(a, b) for x, y in zip(p, q))


# ---- the engine ----------------------------------------------------------------------
rc, out, err = migrate(HEAD + "fix w all wall/gran %s zplane 0 NULL\n" % HOOKE)
check("a deck with LAMMPS's model words on wall/gran is LAMMPS's: law lammps",
      rc == 0 and "law lammps " + HOOKE in flat(out) and
      "1 of 1 wall/gran and wall/gran/region fixes translated" in err, out + err)
rc, out, err = migrate(HEAD.replace("sphere", "granular") +
                       "fix w all wall/gran model hertz tangential history primitive type 1 "
                       "zplane 0\n")
check("a deck with LIGGGHTS's wall/gran model is LIGGGHTS's: law hertz",
      rc == 0 and "law hertz" in flat(out) and "1 of 1 wall/gran fixes" in err, out + err)
write("in.lig", "fix w all wall/gran model hertz tangential history primitive type 1 "
      "zplane 0\n")
rc, out, err = migrate(HEAD + "include in.lig\nregion c cylinder z 0 0 0.05 -1 1\n"
                       "fix v all wall/gran/region %s region c\n" % HOOKE)
check("a deck with both engines' walls (one in an included file) is an error naming a "
      "line of each; nothing written",
      rc == 1 and out == "" and "LIGGGHTS's fix wall/gran model (LINE 1 of in.lig)" in err
      and "LAMMPS's fix wall/gran/region (LINE 8)" in err and "--engine" in err, err)
rc, out, err = migrate(HEAD + "region c cylinder z 0 0 0.05 -1 1\n", ["--engine", "lammps"])
check("--engine lammps: a deck without walls is copied as it is", rc == 0 and
      out == HEAD + "region c cylinder z 0 0 0.05 -1 1\n", err)
rc, out, err = migrate(HEAD, ["--engine", "lmp"])
check("--engine takes liggghts or lammps", rc == 1 and "--engine expects liggghts or "
      "lammps, got 'lmp'" in err, err)

# ---- the reader's LAMMPS rules, against stock lmp ------------------------------------
FORMULAS = ["2^0", "0^0", "-2^2", "1|^0", "1|^1", "0|^0", "2^3^2", "(1<2)|^(3<4)",
            "3>2 |^ 1==1 && 0", "ln(10)", "atan2(1,2)", "round(-2.5)"]
VARS = ('variable a equal 2\nvariable f format a %.3f\nvariable i internal 1.25\n'
        'variable g equal v_i*v_a\n')
if check("stock lmp present", LMP is not None):
    deck = HEAD + VARS + "".join('print "F%d $(%s)"\n' % (k, f)
                                 for k, f in enumerate(FORMULAS))
    PRINTS = ('print "X $(1/3:%.4f) ${f} ${g} $(v_g/3:%.9e)"\n'
              'print """T # $a ${a}"""\n'
              'if "${a} == 2 && yes == yes" then "print I1" else "print I0"\n'
              'if "no != no" then "print J1" else "print J0"\n')
    rc, lmp_out = stock(deck + PRINTS)
    want = dict(re.findall(r"^F(\d+) (\S+)$", lmp_out, re.M))
    got, vals = {}, []
    for k, f in enumerate(FORMULAS):
        rc2, out, err = migrate(HEAD + VARS + "region c cylinder z 0 0 $(%s) -1 1\nfix w all "
                                "wall/gran/region %s region c\n" % (f, HOOKE))
        pts = profile(wall_line(out, "w"))
        got[str(k)] = pts[1][0] if rc2 == 0 and len(pts) > 1 else None
    bad = ["%s: lmp %s, tool %s" % (f, want.get(str(k)), got[str(k)])
           for k, f in enumerate(FORMULAS)
           if got[str(k)] is None or str(k) not in want or float(want[str(k)]) != got[str(k)]]
    check("formulas as stock lmp evaluates them (x^0 = 1, unary minus before ^, |^), the "
          "tool's value a region's radius", rc == 0 and not bad, "; ".join(bad) + lmp_out[-400:])
    rc2, out, err = migrate(HEAD + VARS + PRINTS + "region c cylinder z 0 0 ${f} -1 "
                            "$(v_g/3:%.9e)\nfix w all wall/gran/region " + HOOKE +
                            " region c\n")
    x = re.search(r"^X (\S+) (\S+) (\S+) (\S+)$", lmp_out, re.M)
    pts = profile(wall_line(out, "w"))
    check("$(...:%fmt), format and internal variables, triple quotes (a # kept), if on "
          "words: as stock lmp", x is not None and x.groups()[:3] == ("0.3333", "2.000",
                                                                      "2.5") and
          "T # 2 2" in lmp_out and "I1" in lmp_out and "J0" in lmp_out and rc2 == 0 and
          close(pts, [(0, -1), (2.0, -1), (2.0, float(x.group(4))), (0, float(x.group(4)))]),
          "%s %s %s" % (x and x.groups(), pts, lmp_out[-300:] + err))
    check("format variable: the region's radius ${f} as lmp formats it", pts[1:2] and
          pts[1][0] == 2.0, str(pts))

# ---- planes, zcylinder, wiggle, shear ------------------------------------------------
deck = HEAD + ("fix w all wall/gran %s zplane 0.0 0.1 # floor and lid\n"
               "fix x all wall/gran %s xplane NULL 0.05 shear y 0.3\n"
               "fix z all wall/gran %s zcylinder 0.08 wiggle z 0.001 0.01\n"
               "run 1000\n"
               "fix v all wall/gran %s yplane -0.05 NULL wiggle y 0.002 0.02\n" % (
                   HERTZ, HOOKE, HERTZ, HOOKE))
rc, out, err = migrate(deck)
w, w2 = wall_line(out, "w"), wall_line(out, "rs_w_2")
check("zplane lo hi: two planes of the same model, lo facing +z, hi facing -z, both sides; "
      "the line's comment kept", rc == 0 and
      "cylinder a 0 0 0.0 b 1 0 0.0 c 0 -1 0.0 sides 2 profile START -1 0 LINE 1 0 end law "
      "lammps " + HERTZ in w and "cylinder a 0 0 0.1 b 1 0 0.1 c 0 1 0.1 sides 2 profile "
      "START -1 0 LINE 1 0 end law lammps " + HERTZ in w2 and
      re.search(r"law lammps %s # floor and lid\n" % re.escape(HERTZ), flat_lines(out)) and
      "zplane" not in out, out + err)
check("xplane NULL hi with shear: the hi plane alone, facing -x, surface_vel along y",
      "fix x all wall/rigid surface inline cylinder a 0.05 0 0 b 0.05 1 0 c 0.05 0 1 sides 2 "
      "profile START -1 0 LINE 1 0 end law lammps " + HOOKE + " surface_vel 0 0.3 0" in
      flat(out), wall_line(out, "x"))
check("zcylinder with wiggle z: both sides, reff region, moved along its axis at LAMMPS's "
      "velocity from the step it was made at", "variable rs_z_w equal 0.001*(2*PI/0.01)*"
      "sin((2*PI/0.01)*(step-0)*dt)\n" in out and "revolution origin 0 0 0 axis 0 0 1 sides "
      "2 profile START 0.08 -1 LINE 0.08 1 end law lammps reff region " + HERTZ +
      " move linear 0 0 v_rs_z_w" in wall_line(out, "z"), out)
check("yplane with wiggle along its normal, made at step 1000: move variable, LAMMPS's "
      "place and velocity", "variable rs_v_w equal 0.002*(2*PI/0.02)*sin((2*PI/0.02)*"
      "(step-1000)*dt)\nvariable rs_v_d equal 0.002-0.002*cos((2*PI/0.02)*(step-1000)*dt)\n"
      in out and "move variable 0 v_rs_v_d 0 0 v_rs_v_w 0" in wall_line(out, "v"), out)

# ---- regions -------------------------------------------------------------------------
deck = HEAD + """variable th equal 3*time
variable x equal 0.01+0.02*time
region c cylinder x 0.01 -0.02 0.05 -0.06 0.09 side in open 2 units box
fix c all wall/gran/region %s region c
region k cone z 0 0 0.02 0.06 0.0 0.1 side out units box
fix k all wall/gran/region %s region k
region s sphere 0 0 0.05 0.04 side out units box
fix s all wall/gran/region %s region s
lattice none 2
region m cylinder z 0 0 0.025 -0.01 0.04 move v_x NULL NULL rotate v_th 0 0.01 0 0 0 1
fix m all wall/gran/region %s region m
run 100
unfix m
""" % (HERTZ, HOOKE, HERTZ, HERTZ)
rc, out, err = migrate(deck)
c = wall_line(out, "c")
check("a cylinder along x with its hi cap open: about (x, 0.01, -0.02), its lo cap and "
      "side, both sides (an open region), reff region",
      rc == 0 and "revolution origin 0 0.01 -0.02 axis 1 0 0 sides 2" in c and
      close(profile(c), [(0, -0.06), (0.05, -0.06), (0.05, 0.09)]) and
      "reff region" in c, c + err)
k = wall_line(out, "k")
check("a cone side out: its outline reversed (the normals outward), one-sided",
      "sides 2" not in k and close(profile(k), [(0, 0.1), (0.06, 0.1), (0.02, 0), (0, 0)]),
      k)
s = wall_line(out, "s")
check("a sphere side out: two arcs from the top, one-sided, leaving alone the particles "
      "inside it (behind none), the exact effective radius (no reff)",
      "revolution origin 0 0 0.05 axis 0 0 1 profile START 0 0.04 CIRCL 0.04 0 0 0 CIRCL 0 "
      "-0.04 0 0 end behind none law lammps " + HERTZ in s, s)
m = wall_line(out, "m")
D0, th0 = 0.01, 0.0
check("a moving, turning cylinder in lattice units (lattice none 2): placed where the "
      "region stands when the wall is made (moved by x = 0.01), its rates the change of "
      "x and th over the step, kept by fix ave/time, rotating about its point moved by x",
      "fix rs_m_prev all ave/time 1 1 1 v_x v_th\nvariable rs_m_vx equal "
      "(v_x-f_rs_m_prev[1])/dt\nvariable rs_m_om equal (v_th-f_rs_m_prev[2])/dt\n" in out
      and "revolution origin 0.01 0 0 axis 0 0 1 profile" in m and
      close(profile(m), [(0, -0.02), (0.05, -0.02), (0.05, 0.08), (0, 0.08)]) and
      "move linear v_rs_m_vx 0 0 rotate origin 0.01 0.02 0 axis 0 0 1 omega v_rs_m_om" in m
      and "unfix m\nunfix rs_m_prev\n" in out, out + err)
check("a cone's NOTE states LAMMPS's wall radius and reff region's (not for hooke, which "
      "takes none)", "NOTE: fix k" not in err and "cone face" not in err, err)

# unions and intersections against hand-drawn outlines
deck = HEAD + """region k cone z 0 0 0.02 0.08 0 0.1 units box
region c cylinder z 0 0 0.08 0.1 0.2 units box
region h union 2 k c
fix h all wall/gran/region %s region h
region p plane 0 0 0.03 0 0 1 units box
region q plane 0 0 0.12 0 0 -1 units box
region d intersect 3 c2 p q
""" % HERTZ
deck = deck.replace("region d intersect 3 c2 p q\n",
                    "region c2 cylinder z 0 0 0.06 INF INF units box\n"
                    "region d intersect 3 c2 p q\nfix d all wall/gran/region %s region d\n"
                    "region a plane 0 0 0 1 0 1 units box\nregion b plane 0 0 0 -1 0 1 units "
                    "box\nregion v intersect 2 a b\nfix v all wall/gran/region %s region v\n"
                    "region u union 2 a b side out\nfix u all wall/gran/region %s region u\n"
                    % (HERTZ, HOOKE, HOOKE))
rc, out, err = migrate(deck)
h, d = wall_line(out, "h"), wall_line(out, "d")
check("a union of a cone and a cylinder on one axis: the hopper's outline, from the "
      "cone's tip cap to the cylinder's lid", rc == 0 and close(profile(h), [
          (0, 0), (0.02, 0), (0.08, 0.1), (0.08, 0.2), (0, 0.2)]) and "reff region" in h and
      "LINE 9: NOTE: fix h: region h is a union" in err, h + err)
check("an intersection of an INF cylinder and two planes normal to its axis: a closed "
      "drum", close(profile(d), [(0, 0.03), (0.06, 0.03), (0.06, 0.12), (0, 0.12)]), d)
v, u = wall_line(out, "v"), wall_line(out, "u")
r2 = math.sqrt(0.5)


def extruded(line):
    """An extrusion's profile: its points and each segment's normal (left of travel, the
    side it acts on), in global coordinates."""
    m = re.search(r"cylinder a (\S+) (\S+) (\S+) b (\S+) (\S+) (\S+) c (\S+) (\S+) (\S+)",
                  line)
    if not m:
        return [], []
    a, b, c = [[float(x) for x in m.groups()[3 * i:3 * i + 3]] for i in range(3)]
    ex = [q - p for p, q in zip(a, b)]
    ez = [q - p for p, q in zip(a, c)]
    ey = [ez[1] * ex[2] - ez[2] * ex[1], ez[2] * ex[0] - ez[0] * ex[2],
          ez[0] * ex[1] - ez[1] * ex[0]]
    pts2 = profile(line)
    pts = [[a[d] + u * ex[d] + w * ey[d] for d in range(3)] for u, w in pts2]
    normals = []
    for (u0, w0), (u1, w1) in zip(pts2, pts2[1:]):
        tu, tw = u1 - u0, w1 - w0
        normals.append([-tw * ex[d] + tu * ey[d] for d in range(3)])
    return pts, normals


def faces_toward(pts, normals, inside):
    """Whether each segment's normal points toward the point inside."""
    return len(normals) > 0 and all(
        sum(n[d] * (inside[d] - 0.5 * (p[d] + q[d])) for d in range(3)) > 0
        for n, p, q in zip(normals, pts, pts[1:]))


pv, nv = extruded(v)
pu, nu = extruded(u)
# the V trough z >= |x| (planes x + z >= 0 and z - x >= 0): its two faces through the
# apex, facing up into it; the union side out is the region below z = -|x|
check("an intersection of two planes (a V trough): an extruded profile of its two faces "
      "through the apex, each facing into the trough", rc == 0 and len(pv) == 3 and
      all(abs(p[2] - abs(p[0])) < 1e-12 and p[1] == 0 for p in pv) and
      faces_toward(pv, nv, (0.0, 0.3, 0.05)) and faces_toward(pv, nv, (0.0, -0.3, 0.05)),
      "%s %s" % (pv, v))
check("the union of the same planes, side out: the faces of z = -|x|, facing down",
      len(pu) == 3 and all(abs(p[2] + abs(p[0])) < 1e-12 for p in pu) and
      faces_toward(pu, nu, (0.0, 0.1, -0.05)), "%s %s" % (pu, u))

# blocks and prisms: meshes beside the deck
deck = HEAD + ("region b block -0.05 0.05 -0.05 0.05 0 0.1 units box\n"
               "fix b all wall/gran/region %s region b\n"
               "region o block -0.05 0.05 -0.05 0.05 0 0.1 open 6 units box\n"
               "fix o all wall/gran/region %s region o\n"
               "region p prism -0.05 0.05 -0.05 0.05 0 0.1 0.02 0.03 0 units box\n"
               "fix p all wall/gran/region %s region p\n" % (HOOKE, HOOKE, HOOKE))
for f in os.listdir(TMP):
    if f.endswith(".stl"):
        os.remove(os.path.join(TMP, f))
rc, out, err = migrate(deck, name="in.boxes")


def facets(name):
    path = os.path.join(TMP, name)
    if not os.path.isfile(path):
        return None
    v = [tuple(float(x) for x in l.split()[1:4]) for l in open(path)
         if l.split()[:1] == ["vertex"]]
    return [v[i:i + 3] for i in range(0, len(v), 3)]


def inward(tris, centre):
    """Whether every facet's right-hand normal points toward centre."""
    for a, b, c in tris:
        e1 = [q - p for p, q in zip(a, b)]
        e2 = [q - p for p, q in zip(a, c)]
        n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0]]
        if sum(x * (m - p) for x, m, p in zip(n, centre, a)) <= 0:
            return False
    return True


tb, to, tp = facets("in.boxes.b.stl"), facets("in.boxes.o.stl"), facets("in.boxes.p.stl")
check("a block: 12 facets facing its inside in in.boxes.b.stl, one-sided, leaving alone "
      "the particles outside it (behind none)",
      rc == 0 and tb is not None and len(tb) == 12 and inward(tb, (0, 0, 0.05)) and
      "surface inline mesh in.boxes.b.stl sides 1 behind none law lammps" in
      wall_line(out, "b") and
      "NOTE: fix b: region b's faces are written to in.boxes.b.stl" in err, out + err)
check("a block with face 6 open: 10 facets, none at its top, both sides, no behind",
      to is not None and len(to) == 10 and all(max(p[2] for p in t) < 0.1 or
                                              min(p[2] for p in t) < 0.1 for t in to) and
      not any(all(p[2] == 0.1 for p in t) for t in to) and
      "mesh in.boxes.o.stl sides 2" in wall_line(out, "o") and
      "behind" not in wall_line(out, "o"), str(to))
# LAMMPS's corners: lo + i a + j b + k c, a = (0.1, 0, 0), b = (xy, 0.1, 0), c = (xz, yz, 0.1)
corners = {(-0.05 + 0.1 * i + 0.02 * j + 0.03 * k, -0.05 + 0.1 * j, 0.1 * k)
           for i in (0, 1) for j in (0, 1) for k in (0, 1)}
check("a prism: 12 facets on its 8 corners lo + i a + j b + k c, facing inside",
      tp is not None and len(tp) == 12 and inward(tp, (0.025, 0.0, 0.05)) and
      {tuple(round(c, 12) for c in p) for t in tp for p in t} ==
      {tuple(round(c, 12) for c in p) for p in corners}, str(tp))

# ---- include ---------------------------------------------------------------------------
write("in.lwalls", "variable zf equal 0.02\nfix w all wall/gran %s zplane ${zf} NULL\n"
      % HOOKE)
rc, out, err = migrate(HEAD + "include in.lwalls\nrun 0\n")
check("a wall in an included file: the file's commands, migrated, in place of its include "
      "line", rc == 0 and "# rigidsurf-migrate: include in.lwalls, migrated\nvariable zf "
      "equal 0.02\nfix w all wall/rigid surface inline cylinder a 0 0 ${zf}" in out and
      "include in.lwalls\n" not in out.replace("# rigidsurf-migrate: include in.lwalls", ""),
      out + err)

# the periodicity change_box gives
rc, out, err = migrate(HEAD.replace("boundary f f f", "boundary p p p") +
                       "change_box all boundary p p f\nfix w all wall/gran %s zplane 0 NULL\n"
                       % HOOKE)
check("change_box ... boundary p p f: a zplane wall where z is not periodic",
      rc == 0 and "fix w all wall/rigid" in out, err)

# ---- what names a wall -----------------------------------------------------------------
deck = HEAD + ("fix w all wall/gran %s zplane 0.0 0.1 contacts\n"
               "fix_modify w energy no\n"
               "variable fz atom f_w[4]+0\n"
               "compute s all reduce sum f_w[2] f_w[3]\n"
               "dump d all custom 10 d.dump id f_w[2] f_w[3] f_w[4] v_fz\n"
               "run 10\nunfix w\n" % HOOKE)
rc, out, err = migrate(deck)
check("contacts: store_force into the wall's ID on both planes; f_w[2-4] read "
      "f_force_w[1-3] in formulas, computes and dumps; fix_modify and unfix of every wall "
      "(the last made first)", rc == 0 and "store_force into w" in wall_line(out, "w") and
      "store_force into w" in wall_line(out, "rs_w_2") and
      "variable fz atom f_force_w[3]+0\n" in out and
      "compute s all reduce sum f_force_w[1] f_force_w[2]\n" in out and
      "dump d all custom 10 d.dump id f_force_w[1] f_force_w[2] f_force_w[3] v_fz\n" in out
      and "fix_modify w energy no\nfix_modify rs_w_2 energy no\n" in out and
      "unfix rs_w_2\nunfix w\n" in out, out + err)

# a wall made again with its ID (LAMMPS replaces a fix by one of its style)
deck = HEAD + ("fix w all wall/gran %s zplane 0 0.1\nrun 10\n"
               "fix w all wall/gran %s zplane 0.01 NULL\nrun 10\n"
               "fix c all wall/gran %s zcylinder 0.05 shear x 0.1\nrun 10\n"
               "fix c all wall/gran %s zcylinder 0.05\nrun 10\n") % ((HOOKE,) * 4)
rc, out, err = migrate(deck)
check("a wall made again with its ID: the old walls the new one does not replace unfixed "
      "first (rs_w_2), and a kept wall/gran unfixed before the wall/rigid of its ID",
      rc == 3 and "run 10\nunfix rs_w_2\nfix w all wall/rigid" in out and
      "run 10\nunfix c\nfix c all wall/rigid" in out and
      "fix c all wall/gran %s zcylinder 0.05 shear x 0.1\n" % HOOKE in out, out + err)

# ---- exit 3: walls kept as LAMMPS's, each with its reason on its line -------------------
KEPT = [
    ("zcylinder shear x", "fix w all wall/gran %s zcylinder 0.05 shear x 0.1" % HOOKE,
     "does not reset between particles"),
    ("a rotation axis not of unit length", "variable t equal step\nregion c cylinder z 0 0 "
     "0.05 -1 1 rotate v_t 0 0 0 0 0 2\nfix w all wall/gran/region %s region c" % HOOKE,
     "its rotation axis has length 2"),
    ("a cone along y with its end caps", "region c cone y 0 0 0.01 0.05 -0.1 0.1\nfix w all "
     "wall/gran/region %s region c" % HOOKE, "cone along y push along z"),
    ("a union of cylinders on two axes", "region a cylinder z 0 0 0.05 -1 1\nregion b "
     "cylinder z 0.01 0 0.05 -1 1\nregion u union 2 a b\nfix w all wall/gran/region %s "
     "region u" % HOOKE, "do not share one axis"),
    ("planes of no common direction", "region a plane 0 0 0 1 0 0\nregion b plane 0 0 0 0 1 "
     "0\nregion c plane 0 0 0 0 0 1\nregion u intersect 3 a b c\nfix w all wall/gran/region "
     "%s region u" % HOOKE, "not all normal to one direction"),
    ("a union with a sphere", "region s sphere 0 0 0 0.05\nregion c cylinder z 0 0 0.05 -1 "
     "1\nregion u union 2 s c\nfix w all wall/gran/region %s region u" % HOOKE,
     "its member s is a sphere"),
    ("a region whose shape changes", "variable r equal 0.05\nregion c cylinder z 0 0 v_r -1 "
     "1\nfix w all wall/gran/region %s region c" % HOOKE, "its shape changes with v_r"),
    ("a region moved by a variable defined after the wall", "region c cylinder z 0 0 "
     "0.05 -1 1 move v_later NULL NULL\nfix w all wall/gran/region %s region c\nvariable "
     "later equal 0.001*time" % HOOKE, "v_later where the wall is made: v_later: Invalid "
     "variable name"),
    ("a contacts column wall/rigid does not keep", "fix w all wall/gran %s zplane 0 NULL "
     "contacts\ndump d all custom 1 d.dump id f_w[5] f_w[2]" % HOOKE,
     "reads f_w[5], LAMMPS's contacts column 5 (the contact point's x)"),
]
for name, lines, why in KEPT:
    deck = HEAD + lines + "\nfix f all wall/gran %s zplane -0.04 NULL\nrun 0\n" % HOOKE
    rc, out, err = migrate(deck)
    n = len(HEAD.splitlines()) + 1 + [k for k, x in enumerate(lines.splitlines())
                                      if "wall/gran" in x][0]
    check("exit 3, %s: the reason and 'kept as LAMMPS's' on the wall's line, the wall as "
          "written, the other migrated" % name, rc == 3 and why in err and
          "LINE %d: fix w: the wall is kept as LAMMPS's" % n in err and
          re.search(r"^LINE %d: fix w: .*%s" % (n, re.escape(why)), err, re.M) and
          [x for x in lines.splitlines() if "wall/gran" in x][0] + "\n" in out and
          "fix f all wall/rigid" in out and "1 of 2 wall/gran and wall/gran/region fixes "
          "translated; 1 kept as LAMMPS's (above)" in err, out + err)

# ---- exit 1: what LAMMPS stops at, with its line and command; nothing written ----------
ERRORS = [
    ("an unknown keyword after the wall", "fix w all wall/gran %s zplane 0 NULL bogus 1"
     % HOOKE, "LINE 6: ERROR: fix w: fix wall/gran: 'bogus' is not one of its keywords"),
    ("an unknown granular model keyword", "fix w all wall/gran granular hooke 1 2 friction 1 "
     "zplane 0 NULL", "LINE 6: ERROR: fix w: fix wall/gran granular: 'friction' is neither"),
    ("a region style LAMMPS has not", "region r ellipsoid 0 0 0 1 1 1\nfix w all wall/gran "
     "%s zplane 0 NULL" % HOOKE, "LINE 6: ERROR: region: LAMMPS 29Sep2021 has no region "
     "style 'ellipsoid'"),
    ("a missing included file", "include nothere.in\nfix w all wall/gran %s zplane 0 NULL"
     % HOOKE, "LINE 6: ERROR: Cannot open input script nothere.in"),
    ("wiggle with shear", "fix w all wall/gran %s zplane 0 NULL wiggle z 1 1 shear x 1"
     % HOOKE, "LINE 6: ERROR: fix w: fix wall/gran: wiggle and shear together"),
    ("a region that does not exist", "fix w all wall/gran/region %s region nothere" % HOOKE,
     "LINE 6: ERROR: fix w: region nothere does not exist"),
    ("f_ID without contacts", "fix w all wall/gran %s zplane 0 NULL\ndump d all custom 1 "
     "d.dump id f_w[2]" % HOOKE, "LINE 7: ERROR: f_w[2]: fix w keeps no per-atom array"),
    ("fix_modify energy yes", "fix w all wall/gran %s zplane 0 NULL\nfix_modify w energy "
     "yes" % HOOKE, "LINE 7: ERROR: fix_modify w: fix wall/gran takes 'energy no'"),
    ("a plane wall in a periodic dimension", "fix w all wall/gran %s zplane 0 NULL" % HOOKE,
     "LINE 6: ERROR: fix w: zplane in a periodic dimension"),
    ("a wall/gran/region without its region", "fix w all wall/gran/region %s zplane 0 NULL"
     % HOOKE, "LINE 6: ERROR: fix w: fix wall/gran/region: expects 'region ID' as its wall"),
]
for name, lines, msg in ERRORS:
    head = HEAD if "periodic" not in name else HEAD.replace("boundary f f f", "boundary f f p")
    for f in os.listdir(TMP):
        if f.endswith(".stl"):
            os.remove(os.path.join(TMP, f))
    rc, out, err = migrate(head + lines + "\n")
    check("exit 1, %s: the line and the command named, nothing written" % name,
          rc == 1 and out == "" and msg in err and "nothing written" in err and
          not any(f.endswith(".stl") for f in os.listdir(TMP)), err)

T.finish()
