#!/usr/bin/python3
"""law liggghts is LIGGGHTS's own contact models: every combination, against fix wall/gran.

`fix wall/rigid ... law liggghts WORDS` evaluates the model that the words of a
`fix wall/gran` line name (docs/fix_wall_rigid.md). The reference is fix wall/gran in
the same executable, which links the same libliggghts.

Matrix. The normal, tangential, cohesion and rolling models come from the executable's
own `-h` lists ("Normal models for pair gran:", ...), plus `off` for cohesion and
rolling, so a model that LIGGGHTS gains is tested or the test fails. Each combination
runs in stock wall/gran first; a combination that LIGGGHTS refuses is reported with
LIGGGHTS's own error (or its crash) and left out. LIGGGHTS 3.8 defines all 9 x 3 x 5 x 6
= 810 for walls; in contact, thornton_ning with easo/capillary/viscous or
washino/capillary/viscous ends stock LIGGGHTS with a segmentation fault, and
thornton_ning with tangential no_history stops with "ERROR: Atom types must start from 1
for granular simulations" (a message of a corrupted run, not of the deck): 54 of 810.
A combination that runs in the reference and is missing from the comparison is a
failure.

Trajectory of a case: a spinning sphere lands obliquely on the wall under gravity,
slides until friction makes it roll, rolls against the rolling resistance (phase 1),
then an upward force that grows from m g to 40 m g pulls it off (phase 2). Per normal
model one deck holds all its combinations, each sphere in its own group with its own
wall fix, the spheres 2 cm apart so that no two touch (the pair style never acts): the
plane z = 0 and, inside xcylinders of radius 2 cm, the cylinder's bottom (the sphere
starts off the lowest line and swings across it). The rigidsurf deck differs only in
the wall lines. Checks per case, on the reference run:
- it touched the wall (negative gap in some frame) and left it at the end (gap > 0,
  moving away);
- a cohesion model acted: the sphere's gap differs from that of the same combination
  without cohesion by more than 1e-4 R in some frame (edinburgh's overlaps are 1e-5 R:
sjkr changes its gap by 5e-4 R) (deeper at rest, held back in the
  pull; sjkr and sjkr2 scale with the contact area, so on a linear spring they deepen
  the rest and hold nothing at the pull-off);
- a rolling model acted: at the end of phase 1 a velocity differs by more than 1e-4 m/s
  from the same combination without rolling friction (not for thornton_ning, whose
  rolling models LIGGGHTS gives no stiffness: see INERT_ROLLING);
and every dumped position, velocity and angular velocity equals LIGGGHTS's to 1e-9
relative (scales R, 1 m/s, 1/R rad/s).

Mesh walls. hertz/history with each cohesion and each rolling model on a flat STL
floor of two triangles (fix mesh/surface + wall/gran mesh) against `surface inline
mesh` of the same file, one deck each (LIGGGHTS allows one mesh wall/gran per deck).
The sphere crosses the floor's diagonal edge, lands, slides and is pulled off; every
trajectory equals LIGGGHTS's to 1e-9 (measured 1e-16), but for one stretch named here.
easo/capillary/viscous's bridge, once the sphere has left the floor, damps by the
velocity of "atom j" (atom->v[j]): LIGGGHTS's mesh walls pass j = the triangle's index
(fix_wall_gran_base.h), so its bridge to a triangle takes the velocity of the atom of
that number; fix wall/rigid passes the wall's own velocity (as LIGGGHTS's primitive
walls mean to: theirs pass j = -type, a read before the atom arrays that valgrind
reports). There the two differ, so easo's trajectory is compared until the reference
sphere leaves the floor; after it the difference is reported (3.8e-5), not checked.

A particle with several contacts at a concave fold (the shares of docs/conventions.md)
under law liggghts: test_liggghts_folds.py.

Bad input: unknown model name, unknown setting, a missing material property
(LIGGGHTS's message), `props`, `area 2`, `temperature 300` and
`computeElasticPotential on` with law liggghts each end the run with exit 1 and one
ERROR naming the problem.

RS_LIGMODELS_PART (matrix | rest; unset: both) runs one part: the matrix, or the
mesh floor and the bad input.
"""
import itertools
import math
import os
import re
import subprocess
import time

import liglib as L

R, RHO, DT = 0.005, 2500.0, 1.0e-5
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
G = 9.81
TOL = 1e-9
BRIDGE_ATOM_J = "easo/capillary/viscous"  # reads atom j's velocity: see the docstring
RESTITUTION = 0.3         # the sphere settles early in phase 1
SCALES = {"x": R, "y": R, "z": R, "vx": 1.0, "vy": 1.0, "vz": 1.0,
          "omegax": 1.0 / R, "omegay": 1.0 / R, "omegaz": 1.0 / R}
N1, N2 = 1500, 700          # steps of phase 1 (land, slide, roll) and 2 (pull off)
EVERY = 10                   # dump interval
GAP = 2.13e-4                # start gap: not a whole number of steps of travel
RC = 0.02                    # cylinder radius
PULL = 40.0                  # phase 2 ends at PULL m g upward

# Material properties: LIGGGHTS's names, from its errors ("Could not locate a
# fix/property storing value(s) for NAME as requested by model M") and styles ("scalar
# style required ..."). Values make each model active at these scales: stiffnesses give
# overlaps of a few microns, cohesion (sjkr, sjkr2: cohesion energy density; capillary:
# surface tension) several m g, rolling friction a torque that visibly slows the roll.
MATERIALS = [
    # hooke: characteristic velocity
    ("characteristicVelocity", "scalar", 1.0),
    # hertz/stiffness, hooke/stiffness
    ("kn", "pair", 2.0e4), ("kt", "pair", 1.5e4), ("gamman", "pair", 50.0),
    ("gammat", "pair", 20.0),
    # hooke/hysteresis, luding, edinburgh
    ("coefficientMaxElasticStiffness", "pair", 2.0),
    ("coefficientAdhesionStiffness", "pair", 0.2),
    ("coefficientPlasticityDepth", "pair", 0.05),
    ("LoadingStiffness", "pair", 2.0e4), ("UnloadingStiffness", "pair", 5.0),
    ("pullOffForce", "pair", 0.0),
    ("adhesionExponent", "scalar", 1.0), ("overlapExponent", "scalar", 1.0),
    # edinburgh, thornton_ning
    ("surfaceEnergy", "pair", 0.1), ("coefficientYieldRatio", "type", 0.5),
    # tan_luding: dynamic/static friction, viscous ratio, stiffness ratio
    ("FluidViscosity", "pair", 0.8), ("FrictionViscosity", "pair", 0.5),
    ("coeffFrictionStiffness", "pair", 0.5),
    # sjkr, sjkr2
    ("cohesionEnergyDensity", "pair", 2.0e5),
    # easo/capillary/viscous, washino/capillary/viscous
    ("surfaceLiquidContentInitial", "scalar", 0.01), ("surfaceTension", "scalar", 5.0),
    ("fluidViscosity", "scalar", 0.001), ("contactAngle", "type", 0.5),
    ("minSeparationDistanceRatio", "scalar", 1.01),
    ("maxSeparationDistanceRatio", "scalar", 1.1),
    # rolling: cdt, epsd, epsd2, epsd3, luding
    ("coefficientRollingFriction", "pair", 0.1),
    ("coefficientRollingViscousDamping", "pair", 0.1),
    ("rollingStiffness", "scalar", 10.0), ("coeffRollingStiffness", "pair", 0.5),
]

# Per normal model, where a property means something else: hertz/stiffness multiplies
# kn (N/m^1.5 after sqrt(R)) and gamman by sqrt(R overlap) (Hertz-like), hooke/stiffness
# takes them as a linear spring (N/m) and a damping rate.
NORMAL_MATERIALS = {
    "hertz/stiffness": {"kn": 3.5e7, "kt": 3.0e7, "gamman": 1.0e6, "gammat": 5.0e5},
}

# LIGGGHTS's thornton_ning sets no normal stiffness (sidata.kn) for the other models: its
# rolling models act with zero stiffness (measured: the roll differs from rolling off by
# 1e-11 m/s at most), so the check that rolling friction acts skips it.
INERT_ROLLING = ("thornton_ning",)

HELP_LISTS = (("normal", "Normal models for pair gran"),
              ("tangential", "Tangential models for pair gran"),
              ("cohesion", "Cohesion models for pair gran"),
              ("rolling", "Rolling models for pair gran"))


def materials(normal=None, nt=2):
    out = []
    over = NORMAL_MATERIALS.get(normal, {})
    for name, kind, v in MATERIALS:
        v = over.get(name, v)
        if kind == "scalar":
            vals = "scalar %r" % v
        elif kind == "type":
            vals = "peratomtype " + " ".join([repr(v)] * nt)
        else:
            vals = "peratomtypepair %d %s" % (nt, " ".join([repr(v)] * nt * nt))
        out.append("fix p_%s all property/global %s %s\n" % (name, name, vals))
    return "".join(out)


def model_lists(s):
    """{kind: [names]} from the executable's -h."""
    p = subprocess.run([s.exe, "-h"], capture_output=True, text=True, errors="replace",
                       cwd=s.dir)
    text = p.stdout
    lists = {}
    for kind, title in HELP_LISTS:
        m = re.search(r"\* " + re.escape(title) + r":\s*\n(.*?)\n\s*\n\*", text, re.S)
        lists[kind] = m.group(1).split() if m else []
    return lists


def words(combo):
    n, t, c, r = combo
    return "model %s tangential %s cohesion %s rolling_friction %s" % (n, t, c, r)


# Geometry ---------------------------------------------------------------------------
# LIGGGHTS allows at most 32 groups, so the cases of a deck share the group all and
# each has its own wall out of reach of the other spheres: plane k is z = k DZ with its
# sphere above it (the spheres in one column 2 cm apart); cylinder k is an xcylinder on
# a grid of axes 5 cm apart in y and z below the planes, its sphere inside.

DZ = 0.02
PLANE_Y = 0.2
CYL_COLS = 5


def plane_z(k):
    return k * DZ


def cyl_axis(k):
    """Below the lowest plane: LIGGGHTS's primitive planes are infinite."""
    return (-0.2 + 0.05 * (k % CYL_COLS), -0.1 - 0.05 * (k // CYL_COLS))


def case_start(geom, k):
    """Start position and velocity of case k."""
    if geom == "plane":
        return (0.0, PLANE_Y, plane_z(k) + R + GAP), (0.1, 0.05, -0.05)
    # inside its xcylinder, off the lowest line by th: it swings across it
    yc, zc = cyl_axis(k)
    th = 0.3
    rad = RC - R - GAP
    e = (0.0, math.sin(th), -math.cos(th))  # from the axis to the sphere
    pos = (0.0, yc + rad * e[1], zc + rad * e[2])
    vel = (0.1, 0.05 * e[2] + 0.05 * e[1], -0.05 * e[1] + 0.05 * e[2])
    return pos, vel


def gap_of(geom, k, at):
    """The gap between case k's sphere (dump row) and its wall (< 0: overlap)."""
    if geom == "plane":
        return at["z"] - plane_z(k) - R
    yc, zc = cyl_axis(k)
    return RC - R - math.hypot(at["y"] - yc, at["z"] - zc)


def away_speed(geom, k, at):
    """The sphere's speed away from its wall."""
    if geom == "plane":
        return at["vz"]
    yc, zc = cyl_axis(k)
    return -((at["y"] - yc) * at["vy"] + (at["z"] - zc) * at["vz"])


def lig_wall(geom, k):
    if geom == "plane":
        return "primitive type 2 zplane %r" % plane_z(k)
    yc, zc = cyl_axis(k)
    return "primitive type 2 xcylinder %r %r %r" % (RC, yc, zc)


def rs_wall(geom, k):
    if geom == "plane":
        z = plane_z(k)
        return ("surface inline cylinder a 0 0 %r b 1 0 %r c 0 -1 %r "
                "profile START -1 0 LINE 1 0 end" % (z, z, z))
    yc, zc = cyl_axis(k)
    return ("surface inline revolution origin 0 %r %r axis 1 0 0 "
            "profile START %r -1 LINE %r 1 end" % (yc, zc, RC, RC))


BOX = (-0.05, 0.05, -0.25, 0.25, -1.1, 1.9)


def deck(cases, wall_lines, tag, dump_every=EVERY, extra="", n1=N1, n2=N2, box=BOX,
         gravity="0 0 -1", omega=(20.0, -30.0, 40.0), normal=None):
    """cases: [(pos, vel)], one sphere each (ids 1, 2, ... in order); wall_lines: the
    wall fixes."""
    d = L.header(box, DT, e=RESTITUTION, extra_props=materials(normal))
    d += "thermo 100000\n"
    for k, (pos, vel) in enumerate(cases):
        d += L.sphere(k + 1, pos, R, RHO, v=vel, omega=omega)
    d += "".join(w + "\n" for w in wall_lines)
    d += extra
    d += "fix grav all gravity %r vector %s\n" % (G, gravity)
    d += "fix integr all nve/sphere\n"
    d += L.dump_lines("d", dump_every, tag + ".dump")
    d += "run %d\n" % n1
    if n2:
        d += "variable fup equal %r*(1.0+%r*(step-%d)/%d)\n" % (MASS * G, PULL - 1.0, n1, n2)
        d += "fix up all addforce 0 0 v_fup\nrun %d\n" % n2
    return d


def compare(s, name, fa, fb, tol=TOL):
    return L.check_trajectories(s, name, fa, fb, SCALES, tol)


# The matrix ---------------------------------------------------------------------------

GEOMS = ("plane", "cylinder")


def matrix_decks(combos, tag):
    """The reference and rigidsurf decks of combos, each on a plane and in a cylinder:
    atom k + 1 is combos[k] on its plane, atom n + k + 1 in its cylinder."""
    n = len(combos)
    starts = [case_start(g, k) for g in GEOMS for k in range(n)]
    ref = ["fix w%s%d all wall/gran %s %s" % (g[0], k, words(c), lig_wall(g, k))
           for g in GEOMS for k, c in enumerate(combos)]
    ours = ["fix w%s%d all wall/rigid %s law liggghts %s type 2" % (
        g[0], k, rs_wall(g, k), words(c)) for g in GEOMS for k, c in enumerate(combos)]
    nm = combos[0][0]
    return (deck(starts, ref, tag + "_gran", normal=nm),
            deck(starts, ours, tag + "_rigid", normal=nm))


def run_matrix(s, lists, report):
    normals = lists["normal"]
    tans = lists["tangential"]
    cohs = ["off"] + lists["cohesion"]
    rolls = ["off"] + lists["rolling"]
    full = list(itertools.product(normals, tans, cohs, rolls))
    s.ck.check("the model lists of -h are read",
               all(len(lists[k]) for k, _ in HELP_LISTS),
               "%d normal x %d tangential x %d cohesion x %d rolling = %d combinations"
               % (len(normals), len(tans), len(cohs), len(rolls), len(full)))
    compared = set()
    refused = {}
    worst = {"plane": 0.0, "cylinder": 0.0}
    for nm in normals:
        combos = [c for c in full if c[0] == nm]
        tag = "m_" + nm.replace("/", "_")
        ref, ours = matrix_decks(combos, tag)
        rc, out = s.run(tag + "_gran", ref, expect_ok=False)
        if rc != 0:
            # name the refused combinations, one deck each, and run the others
            combos = [c for c in combos if accepted(s, c, refused)]
            if not combos:
                continue
            ref, ours = matrix_decks(combos, tag)
            s.run(tag + "_gran", ref)
        s.run(tag + "_rigid", ours)
        fb = L.read_dump(s.path(tag + "_gran.dump"))
        fa = L.read_dump(s.path(tag + "_rigid.dump"))
        check_physics(s, nm, combos, fb)
        n = len(combos)
        for g0, geom in enumerate(GEOMS):
            ids = set(range(g0 * n + 1, g0 * n + n + 1))
            sub = lambda fr: [(st, {i: a for i, a in at.items() if i in ids}) for st, at in fr]
            d = compare(s, "%s on %d %ss" % (nm, n, geom), sub(fa), sub(fb))
            if d is not None:
                worst[geom] = max(worst[geom], d)
                compared.update((c, geom) for c in combos)
    missing = [(c, g) for c in full for g in GEOMS
               if (c, g) not in compared and c not in refused]
    s.ck.check("every combination LIGGGHTS accepts is compared on a plane and a cylinder",
               not missing, "%d compared, %d refused" % (len(compared), len(refused)),
               why="missing: " + "; ".join("%s (%s)" % (words(c), g) for c, g in missing[:10]))
    for c, err in sorted(refused.items()):
        print("refused by LIGGGHTS: %s: %s" % (words(c), err))
    report["matrix"] = (len(full), len(refused), worst)


def accepted(s, c, refused):
    """Whether LIGGGHTS runs combination c alone (plane and cylinder); if not, its
    error goes to refused."""
    tag = "alone_" + words(c).replace(" ", "_").replace("/", "_")
    ref, _ = matrix_decks([c], tag)
    rc, out = s.run(tag + "_gran", ref, expect_ok=False)
    if rc != 0:
        errs = L.error_lines(out)
        refused[c] = errs[0] if errs else "exit %s" % rc
    return rc == 0


def check_physics(s, name, combos, frames):
    """Contact, leaving, cohesion and rolling acted in the reference run."""
    n = len(combos)
    steps = [st for st, _ in frames]
    end1 = max(j for j, st in enumerate(steps) if st <= N1)
    for g0, geom in enumerate(GEOMS):
        ids = {c: g0 * n + k + 1 for k, c in enumerate(combos)}
        gaps = {c: [gap_of(geom, k, at[ids[c]]) for _, at in frames]
                for k, c in enumerate(combos)}
        bad_touch, bad_leave, bad_coh, bad_roll, deep = [], [], [], [], 0.0
        coh_gain, roll_diff = [], []
        for k, c in enumerate(combos):
            g = gaps[c]
            deep = max(deep, -min(g))
            if not min(g) < 0.0:
                bad_touch.append(words(c))
            if not (g[-1] > 0.0 and away_speed(geom, k, frames[-1][1][ids[c]]) > 0.0):
                bad_leave.append(words(c))
            nm, t, co, r = c
            if co != "off" and (nm, t, "off", r) in ids:
                # the cohesion changed the sphere's distance to its wall (deeper at rest,
                # held back in the pull, or both)
                g0 = gaps[(nm, t, "off", r)]
                dg = max(abs(x - y) for x, y in zip(g, g0))
                coh_gain.append(dg / R)
                if not dg > 1e-4 * R:
                    bad_coh.append("%s: gap differs by %.3g R at most" % (words(c), dg / R))
            if r != "off" and (nm, t, co, "off") in ids and nm not in INERT_ROLLING:
                a = frames[end1][1][ids[c]]
                b = frames[end1][1][ids[(nm, t, co, "off")]]
                dv = max(abs(a[f] - b[f]) * (R if f.startswith("omega") else 1.0)
                         for f in ("vx", "vy", "vz", "omegax", "omegay", "omegaz"))
                roll_diff.append(dv)
                if not dv > 1e-4:
                    bad_roll.append("%s: %.3g" % (words(c), dv))
        what = "%s, %s" % (name, geom)
        s.ck.check(what + ": every reference sphere touched its wall", not bad_touch,
                   "deepest overlap %.3g R" % (deep / R), why="; ".join(bad_touch[:5]))
        s.ck.check(what + ": every reference sphere was pulled off", not bad_leave,
                   why="; ".join(bad_leave[:5]))
        s.ck.check(what + ": cohesion changes the sphere's gap", not bad_coh,
                   "largest change of the gap: %.3g .. %.3g R" % (
                       min(coh_gain or [0]), max(coh_gain or [0])),
                   why="; ".join(bad_coh[:5]))
        s.ck.check(what + ": rolling friction changes the roll", not bad_roll,
                   "velocity change at step %d: %.3g .. %.3g m/s" % (
                       N1, min(roll_diff or [0]), max(roll_diff or [0])),
                   why="; ".join(bad_roll[:5]))
        s.ck.check(what + ": overlaps stay small (the values suit every model)",
                   deep < 0.1 * R, "deepest %.3g R" % (deep / R))


# Mesh walls ---------------------------------------------------------------------------

def run_mesh(s, lists, report):
    """hertz/history with each cohesion and rolling model on a flat two-triangle floor.
    LIGGGHTS allows one mesh wall/gran per deck: one deck per combination."""
    combos = [("hertz", "history", c, r) for c in ["off"] + lists["cohesion"]
              for r in ["off"] + lists["rolling"]]
    tris = [((-0.05, -0.05, 0.0), (0.05, -0.05, 0.0), (0.05, 0.05, 0.0)),
            ((-0.05, -0.05, 0.0), (0.05, 0.05, 0.0), (-0.05, 0.05, 0.0))]
    s.write("floor.stl", L.stl_text(tris))
    # the sphere starts over the triangle y > x and slides across the diagonal y = x
    starts = [((-0.0001, 0.0001, R + GAP), (0.1, -0.05, -0.05))]
    worst, bridge, bad_touch, bad_cross = 0.0, 0.0, [], []
    for k, c in enumerate(combos):
        tag = "mesh%d" % k
        ref = ["fix floor all mesh/surface file floor.stl type 2",
               "fix w all wall/gran %s mesh n_meshes 1 meshes floor" % words(c)]
        ours = ["fix w all wall/rigid surface inline mesh floor.stl law liggghts %s type 2"
                % words(c)]
        s.run(tag + "_gran", deck(starts, ref, tag + "_gran", normal="hertz"))
        s.run(tag + "_rigid", deck(starts, ours, tag + "_rigid", normal="hertz"))
        fb = L.read_dump(s.path(tag + "_gran.dump"))
        fa = L.read_dump(s.path(tag + "_rigid.dump"))
        if not min(at[1]["z"] - R for _, at in fb) < 0:
            bad_touch.append(words(c))
        if not any(at[1]["y"] < at[1]["x"] for _, at in fb):
            bad_cross.append(words(c))
        if c[2] == BRIDGE_ATOM_J:
            # until the reference sphere leaves the floor in the pull (phase 2)
            off = next((st for st, at in fb if st > N1 and at[1]["z"] > R), None)
            if off is None:
                bad_touch.append(words(c) + " (never left the floor)")
                off = 0
            w = L.compare_frames(fa, fb, SCALES)
            after = max(v[0] for v in w.values()) if w else float("inf")
            bridge = max(bridge, after)
            fa = [f for f in fa if f[0] < off]
            fb = [f for f in fb if f[0] < off]
        w = L.compare_frames(fa, fb, SCALES)
        d = max(v[0] for v in w.values()) if w else float("inf")
        worst = max(worst, d)
    s.ck.check("mesh floor: every reference sphere touched it", not bad_touch,
               why="; ".join(bad_touch[:5]))
    s.ck.check("mesh floor: every reference sphere crossed the diagonal edge",
               not bad_cross, why="; ".join(bad_cross[:5]))
    s.ck.check("mesh floor, hertz/history x %d cohesion x rolling: trajectories equal "
               "LIGGGHTS's to %g (%s until the sphere leaves the floor; after it, with "
               "LIGGGHTS's atom-j velocity, %.3g)" % (len(combos), TOL, BRIDGE_ATOM_J,
                                                      bridge),
               worst <= TOL, "worst rel %.3g" % worst)
    report["mesh"] = worst


# Bad input -----------------------------------------------------------------------------

def run_bad_input(s):
    base = "fix w all wall/rigid surface plane.inp law liggghts %s type 2"
    good = "model hertz tangential history"
    s.write("plane.inp", L.plane_z(0.0, 0.2))
    cases = [
        ("valid line", base % good, None),
        ("unknown model name", base % "model hurtz tangential history",
         ["law liggghts", "hurtz", "LIGGGHTS does not know"]),
        ("unknown setting", base % (good + " tangential_dampening off"),
         ["tangential_dampening"]),
        ("missing material property", base % "model hooke tangential history",
         ["characteristicVelocity"]),
        ("props", base % good + " props 1 2", ["law liggghts", "'props' does not apply"]),
        ("area 2", base % good + " area 2", ["law liggghts", "'area' does not apply"]),
        ("temperature 300", base % good + " temperature 300",
         ["law liggghts", "'temperature'"]),
        ("computeElasticPotential on", base % (good + " computeElasticPotential on"),
         ["computeElasticPotential on", "fix mesh/surface"]),
    ]
    for name, line, want in cases:
        d = L.header((-0.1, 0.1, -0.1, 0.1, -0.05, 0.2), 1e-5)
        d += L.sphere(1, (0, 0, 0.0052), R, RHO)
        d += line + "\nfix integr all nve/sphere\nrun 10\n"
        rc, out = s.run("bad_" + name.replace(" ", "_"), d, expect_ok=False)
        if want is None:
            s.ck.check("bad input: the " + name + " runs", rc == 0,
                       why=" | ".join(out.splitlines()[-4:]))
        else:
            L.check_rejected(s.ck, "bad input: " + name, line, want, rc, out)


def body(s):
    part = os.environ.get("RS_LIGMODELS_PART", "")
    t0 = time.time()
    report = {}
    lists = model_lists(s)
    if part in ("", "matrix"):
        run_matrix(s, lists, report)
    if part in ("", "rest"):
        run_mesh(s, lists, report)
        run_bad_input(s)
    print("run time %.0f s" % (time.time() - t0))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
