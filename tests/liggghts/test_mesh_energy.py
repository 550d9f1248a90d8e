#!/usr/bin/python3
"""Mesh walls conserve energy and hold every sphere: elastic, frictionless spheres in
closed shells and on both sides of an open sheet, against LIGGGHTS's own mesh wall.

Each case runs the same deck three or more times for STEPS steps: with stock LIGGGHTS's
mesh wall (`fix mesh/surface` + `fix wall/gran model hertz tangential history mesh`),
with stock's wall again from a start perturbed by 1e-9 m, and with `fix wall/rigid ...
surface inline mesh FILE law hertz` (the default sides: both; and `sides 1` where the
spheres are on the winding's side). The STL files are written here:

- cube: a closed cube of 12 triangles, zero thickness, wound outward as CAD programs
  write a closed surface; the spheres are inside, behind its winding, so only the
  two-sided default applies.
- shell: a closed shell 8 mm thick, an outer cube wound outward and an inner cube wound
  inward (the outside of the solid between them); the spheres are in the cavity, on the
  inner cube's winding side: the default and `sides 1`.
- sheet: an open tilted plane of 32 triangles (edges and vertices inside the box) that
  reaches past the box's walls, so it parts the box in two; spheres on both sides with
  the default; spheres on the front (upper, winding) side only with `sides 1`. The box
  is LIGGGHTS's primitive walls in every run of this case.

Particles: 125 (the sheet's front-only case: those above the sheet) Hertz spheres,
R = 4 mm, on a lattice with random velocities, under gravity; the pair style is
`gran model hertz tangential history` with the same material, so the spheres also hit
each other and press each other into the walls. Restitution 1 (beta = 0: no damping,
elastic) and friction 0 (the tangential force is capped at mu Fn = 0): no force
dissipates energy, and no force turns a sphere (spins stay 0). Young's modulus 5e6 Pa
keeps a contact about 75 steps long at dt = 1e-5 s.

Energy: E = KE + rotational KE + sum m g z (z from the cavity's floor). The elastic
energy held in contacts is not in E: LIGGGHTS reports none for its mesh wall or its pair
style (ours for the wall is f_ID[8], printed for information), so every run is measured
alike, and E dips by what the contacts hold at the moment. Two figures per output, every
1000 steps: E(t) itself, and its window mean Ē (every 10 steps over the last 1000), in
which the collisions' timing averages out. E(0) is exact: at the start no sphere touches.

The bound ("within the spread of the same run against LIGGGHTS's mesh wall"). A DEM bed
is chaotic: two runs of one deck part after a few thousand steps, and from then on Ē(t) is
one sample of what the deck does. The spread comes from stock's two runs (as written, and
from the start perturbed by 1e-9 m), after the first tenth of the run (the common fall
from the lattice): the band [lo, hi] that their Ē - E(0) covers, of width W (about 1% of
E(0) here: the contacts' varying energy, and any drift of the integrator). Ours passes
when
  1. it gains no energy: max_t (Ē - E(0)) <= stock's max_t (Ē - E(0)) + W/4 (a mesh
     wall is no source of energy beyond what stock's is; the largest Ē is the first
     window's, the same in every run, so a steady gain of W/4, 0.25% of E(0), fails);
  2. it stays in the band: every Ē - E(0) after the first tenth within [lo - W/2,
     hi + W/2] (a third sample of a chaotic run may reach past the two);
  3. its mean Ē - E(0) over the last quarter is stock's two runs' mean within W/4 (the
     two stock runs' means lie 0.03 W apart here; a drift or a lost contact energy moves
     ours off by more).
Every run prints its figures and times, so a failure shows the numbers it came from.

Tunnelling, every step: a fix ave/time averages over every step the number of spheres
found outside the side they started on (the cavity's block; for the sheet, the half
spaces of its plane, against the groups above and below it at the start); an average of
non-negative integers is zero only if each is. Every output also counts the atoms: a
sphere that leaves LIGGGHTS's box is lost. A control run (spheres behind a one-sided
sheet, which pushes them through) shows that the count sees a crossing.
"""
import math
import random
import resource
import time

import liglib as L

R, RHO, DT = 0.004, 2500.0, 1.0e-5
STEPS = 200000
EVERY = 1000
HALF = 0.05          # the cavity is [-HALF, HALF]^3
THICK = 0.008        # the thick shell
YOUNG = 5.0e6
G = 9.81
NSIDE = 5            # 5^3 spheres on the lattice
SEED = 32
PERTURB = 1.0e-9
STEADY = STEPS // 10     # the band is taken after the start's common fall
LATE = STEPS * 3 // 4    # the late mean: the last quarter


# --- STL ----------------------------------------------------------------------------

def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def normal(t):
    return cross(sub(t[1], t[0]), sub(t[2], t[0]))


# The sheet: the plane through (0, 0, Z0) with normal N (up, tilted in x and y), over
# the square |x|, |y| <= HALF + 5 mm (through the box's walls, so no sphere passes its
# edges), as a 4 x 4 grid of parallelograms of two triangles wound so the normal is +N.
N_RAW = (0.30, 0.15, 1.0)
NN = tuple(x / math.sqrt(dot(N_RAW, N_RAW)) for x in N_RAW)
Z0 = -0.005


def sheet(n=4):
    ext = HALF + 0.005

    def point(x, y):
        return (x, y, Z0 - (NN[0] * x + NN[1] * y) / NN[2])

    tris = []
    for i in range(n):
        for j in range(n):
            x0, x1 = -ext + 2 * ext * i / n, -ext + 2 * ext * (i + 1) / n
            y0, y1 = -ext + 2 * ext * j / n, -ext + 2 * ext * (j + 1) / n
            a, b, c, d = point(x0, y0), point(x1, y0), point(x1, y1), point(x0, y1)
            for tri in ((a, b, c), (a, c, d)):
                if dot(normal(tri), NN) < 0:
                    tri = (tri[0], tri[2], tri[1])
                tris.append(tri)
    return tris


def sheet_side(p):
    """Signed distance of a point from the sheet's plane, > 0 on the front (upper) side."""
    return dot(sub(p, (0.0, 0.0, Z0)), NN)


# --- decks --------------------------------------------------------------------------

def lattice(case):
    """Sphere centres and velocities: a 5 x 5 x 5 lattice in the cavity, random
    velocities up to 0.5 m/s per component. For the sheet, the points closer than 1.5 R
    to its plane move off it along the normal; front_only keeps the upper ones."""
    rng = random.Random(SEED)
    lo, hi = -HALF + 1.5 * R, HALF - 1.5 * R
    out = []
    for i in range(NSIDE):
        for j in range(NSIDE):
            for k in range(NSIDE):
                p = [lo + (hi - lo) * q / (NSIDE - 1) for q in (i, j, k)]
                v = [rng.uniform(-0.5, 0.5) for _ in range(3)]
                if case.startswith("sheet"):
                    d = sheet_side(p)
                    if abs(d) < 2.5 * R:
                        p = [min(hi, max(lo, p[m] + (math.copysign(2.5 * R, d) - d) * NN[m]))
                             for m in range(3)]
                        if abs(sheet_side(p)) < 1.5 * R:
                            continue
                    if case == "sheet_front" and sheet_side(p) < 0:
                        continue
                out.append((tuple(p), tuple(v)))
    return out


def mesh_file(case):
    return {"cube": "cube.stl", "shell": "shell.stl"}.get(case, "sheet.stl")


def deck(case, wall, perturb=0.0):
    """wall: 'stock', 'default' (two-sided) or 'sides1'."""
    b = HALF + THICK + 0.01  # holds the shell and the sheet
    d = L.header((-b, b, -b, b, -b, b), DT, young=(YOUNG, YOUNG), poisson=(0.3, 0.3),
                 e=1.0, mu=0.0)
    atoms = lattice(case)
    for n, (p, v) in enumerate(atoms, 1):
        p = (p[0] + perturb * (n % 3 - 1), p[1] + perturb * ((n // 3) % 3 - 1), p[2])
        d += L.sphere(n, p, R, RHO, v=v)
    d += "fix grav all gravity %r vector 0 0 -1\n" % G
    f = mesh_file(case)
    if wall == "stock":
        d += ("fix cad all mesh/surface file %s type 2\n"
              "fix w all wall/gran model hertz tangential history mesh n_meshes 1 "
              "meshes cad\n" % f)
    else:
        d += ("fix w all wall/rigid surface inline mesh %s%s law hertz type 2\n"
              % (f, " sides 1" if wall == "sides1" else ""))
    if case.startswith("sheet"):
        for k, ax in enumerate("xyz"):
            for sgn in (-1, 1):
                d += ("fix box%s%d all wall/gran model hertz tangential history primitive "
                      "type 2 %splane %r\n" % (ax, sgn + 1, ax, sgn * HALF))
    d += "fix integr all nve/sphere\n"
    # tunnelling: the spheres found outside the side they started on
    if case.startswith("sheet"):
        plane = "plane 0 0 %r %r %r %r" % (Z0, NN[0], NN[1], NN[2])
        d += "region above %s side in\nregion below %s side out\n" % (plane, plane)
        d += "group front region above\ngroup back region below\n"
        d += "variable nout equal count(front,below)+count(back,above)\n"
    else:
        d += ("region cavity block %r %r %r %r %r %r units box\n"
              % (-HALF, HALF, -HALF, HALF, -HALF, HALF))
        d += "variable nout equal count(all)-count(all,cavity)\n"
    d += "fix nout all ave/time 1 %d %d v_nout\n" % (EVERY, EVERY)
    d += "compute rke all erotate/sphere\ncompute tke all ke\n"
    d += "variable pe equal mass(all)*%r*(xcm(all,z)+%r)\n" % (G, HALF)
    d += "variable etot equal c_tke+c_rke+v_pe\n"
    d += "fix eavg all ave/time 10 %d %d v_etot\n" % (EVERY // 10, EVERY)
    se = "f_w[8]" if wall != "stock" else "v_pe"
    d += "thermo_style custom step atoms c_tke c_rke v_pe v_etot f_nout f_eavg %s\n" % se
    d += "thermo_modify lost ignore norm no format float %.10g\n"
    d += "thermo %d\nrun %d\n" % (EVERY, STEPS)
    return d, len(atoms)


def read_energy(out):
    """Rows (step, atoms, ke, rke, pe, etot, nout, eavg, se) of the thermo output."""
    rows = []
    for l in out.splitlines():
        t = l.split()
        if len(t) == 9 and t[0].isdigit():
            try:
                rows.append([float(x) for x in t])
            except ValueError:
                pass
    return rows


def run_case(s, case, walls):
    res = {}
    for tag, wall, pert in [("stock", "stock", 0.0), ("stock_perturbed", "stock", PERTURB)] + \
            [(w, w, 0.0) for w in walls]:
        text, natoms = deck(case, wall, pert)
        t0, c0 = time.time(), resource.getrusage(resource.RUSAGE_CHILDREN)
        _, out = s.run("%s_%s" % (case, tag), text, timeout=600)
        c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        took = "%.1f s, CPU %.1f s" % (time.time() - t0, c1.ru_utime + c1.ru_stime
                                       - c0.ru_utime - c0.ru_stime)
        rows = read_energy(out)
        res[tag] = rows
        ok = s.ck.check("%s %s: ran %d steps" % (case, tag, STEPS),
                        len(rows) == STEPS // EVERY + 1 and rows[-1][0] == STEPS,
                        "%d outputs, %s" % (len(rows), took))
        if not ok:
            continue
        e0, eavg = rows[0][5], [r[7] for r in rows[1:]]
        print("     E0 %.7g J; window means from %.7g to %.7g J, end %.7g J; instantaneous "
              "from %.7g to %.7g J; largest spin KE %.3g J%s"
              % (e0, min(eavg), max(eavg), eavg[-1], min(r[5] for r in rows),
                 max(r[5] for r in rows), max(r[3] for r in rows),
                 "; wall contacts' elastic energy up to %.3g J" % max(r[8] for r in rows)
                 if wall != "stock" else ""))
        s.ck.check("%s %s: every sphere stays on its side at every step" % (case, tag),
                   all(r[1] == natoms for r in rows) and all(r[6] == 0 for r in rows),
                   "%d spheres" % natoms,
                   why="atom counts %s, largest mean count outside %g" % (
                       sorted(set(int(r[1]) for r in rows)), max(r[6] for r in rows)))
    return res


def window_means(rows):
    """(step, Ē - E(0)) of every output after the first, E(0) the start's energy."""
    return [(r[0], r[7] - rows[0][5]) for r in rows[1:]]


def judge(s, case, res, walls):
    if not all(len(res.get(t, ())) == STEPS // EVERY + 1 for t in ["stock", "stock_perturbed"]
               + walls):
        return
    stock = [window_means(res[t]) for t in ("stock", "stock_perturbed")]
    rise = max(e for run in stock for _, e in run)
    band = [e for run in stock for st, e in run if st > STEADY]
    lo, hi = min(band), max(band)
    W = hi - lo
    late = [sum(e for st, e in run if st > LATE) / sum(1 for st, _ in run if st > LATE)
            for run in stock]
    e0 = res["stock"][0][5]
    print("  %s: E0 %.7g J; stock's band after step %d: Ē - E0 in [%.4g, %.4g] J, W = %.4g J "
          "= %.2g%% of E0; largest rise %.4g J; late means - E0 %.4g and %.4g J"
          % (case, e0, STEADY, lo, hi, W, 100 * W / e0, rise, late[0], late[1]))
    for w in walls:
        ours = window_means(res[w])
        up = max(e for _, e in ours)
        s.ck.check("%s %s: no energy gain beyond stock's (+ W/4)" % (case, w),
                   up <= rise + 0.25 * W,
                   "largest rise %.4g J, stock's %.4g J" % (up, rise))
        steady = [(st, e) for st, e in ours if st > STEADY]
        worst = max(steady, key=lambda se: max(lo - se[1], se[1] - hi))
        s.ck.check("%s %s: energy within stock's band (+- W/2)" % (case, w),
                   all(lo - 0.5 * W <= e <= hi + 0.5 * W for _, e in steady),
                   "Ē - E0 in [%.4g, %.4g] J" % (min(e for _, e in steady),
                                                   max(e for _, e in steady)),
                   why="step %d: %.4g J" % worst)
        mine = [e for st, e in ours if st > LATE]
        mine = sum(mine) / len(mine)
        s.ck.check("%s %s: late mean energy as stock's (W/4)" % (case, w),
                   abs(mine - 0.5 * sum(late)) <= 0.25 * W,
                   "late mean - E0 %.4g J, stock's %.4g J" % (mine, 0.5 * sum(late)))


def body(s):
    s.write("cube.stl", L.stl_text(L.cube_triangles(HALF), "cube"))
    s.write("shell.stl", L.stl_text(L.cube_triangles(HALF + THICK) +
                                      L.cube_triangles(HALF, outward=False), "shell"))
    s.write("sheet.stl", L.stl_text(sheet(), "sheet"))
    for case, walls in (("cube", ["default"]), ("shell", ["default", "sides1"]),
                        ("sheet", ["default"]), ("sheet_front", ["sides1"])):
        res = run_case(s, case, walls)
        judge(s, case, res, walls)
    # The detector sees a crossing: the spheres behind a one-sided sheet are pushed
    # through it (the test's own check, not a property of the wall).
    text, natoms = deck("sheet", "sides1")
    text = text.replace("run %d\n" % STEPS, "run 5000\n")
    _, out = s.run("sheet_back_sides1", text)
    rows = read_energy(out)
    s.ck.check("control: spheres behind a one-sided sheet are seen crossing it",
               any(r[6] > 0 for r in rows), "largest mean count outside %g"
               % max(r[6] for r in rows))


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
