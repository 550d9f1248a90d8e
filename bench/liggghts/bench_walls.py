#!/usr/bin/python3
"""LIGGGHTS-side benchmarks of fix wall/rigid, measured side by side in one run.

    bench_walls.py --exe liggghts-rigidsurf [--quick] [--max-n N] [--reps K] [--out FILE]
                   [--sections 1,1b,1c,1d,1e,1f,1g,2,3]

1. Wall cost, cylinder. N spheres (R = 1 mm) form a monolayer on the inside of a
   cylinder of radius 50 mm about z (rings of spheres 2.2 R apart, layers 2.2 R apart,
   so spheres never touch each other), pressed on the wall by a radial body force
   (fix addforce, 1 mN), Hertz with tangential history, fix nve/sphere, no gravity.
   Every sphere is in contact every step. The spheres of these beds move only along
   their radius, so the push keeps the direction each has at the start: an atom-style
   variable evaluated once and stored (fix store/state 0), which the push then copies
   each step. Evaluated every step, that variable cost twice the walls, and the wall
   cost, a difference of loop times, carried its noise. Variants, same deck otherwise:
     none   no wall, radial force 0: the spheres sit still (the baseline)
     prim   fix wall/gran ... primitive zcylinder
     ours   fix wall/rigid, REVOLUTION: a LINE at r = 50 mm
     mesh   fix wall/gran ... mesh, fix mesh/surface of a 4000-triangle STL cylinder
     ours_mesh  fix wall/rigid on that STL (surface inline mesh), section 1c
   Wall cost per particle-step = (loop time with the wall - loop time of 'none') /
   (N steps). The spheres move by micrometres (skin 0.5 mm), so no variant rebuilds its
   neighbour lists during the run (checked: 'Neighbor list builds' is reported), and
   the pair style, integrator and body force cost the same in all variants; the
   difference is the wall. Each variant runs REPS times, interleaved. A ratio of two
   walls is given from the fastest run of each variant, and as the median over the
   repetitions of the ratio within one repetition (each wall cost against the baseline
   run just before it), which cancels the slow drifts of a shared host.
1b. Wall cost, flowing bed: the same monolayer rolling around the cylinder. Every
   sphere starts at V = 0.5 m/s along the hoop direction, spinning at -V/R about z
   (rolling without slip), so the whole layer turns rigidly: spheres never touch each
   other, each moves its contact along the wall by V dt per step, and LIGGGHTS rebuilds
   its neighbour lists every ~50 steps (skin 0.5 mm), as in a real run. The push
   follows each sphere around (an atom-style variable every step, with 1/r stored at
   the start: the spheres stay on their circles). The baseline
   'none' has no wall and no outward push; a central body force m V^2 / r keeps its
   spheres on the same circles at the same speed, so it rebuilds as often as the wall
   variants (the report lists the builds). The wall cost then includes what a wall pays
   per rebuild: fix wall/rigid's candidate refresh, the mesh wall's own neighbour list.
1c. The mesh wall against its facets and the skin: section 1 again with 4000-triangle
   STL cylinders of other facet shapes (NTHETA x NZ quads 400 x 5 ... 63 x 32, from
   slivers to squares) and with a skin four times larger, which puts more facets in
   each sphere's mesh neighbour list. Shows what the mesh wall costs against the
   primitive, so against what a 1.5 x-the-primitive wall can gain on it.
1d. Spheres near the wall, not touching it: the monolayer at a gap of 0.3 mm, inside
   the tracking thickness (default: the skin, 0.5 mm), no push. fix wall/rigid passes
   these open contacts to the law every step, as Abaqus does (rdisp(1) < 0), so they
   cost what a touching contact does; 'ours_t0' is the same wall with tracking 0, where
   they are queried but not tracked.
1e. A bouncing bed, default keywords: 20000 spheres pressed on the wall (equilibrium
   overlap under the push), kicked inward at 0.2 m/s at the start. The push brings them
   back: they rebound inside the skin (0.2 mm high, 4 ms the first flight), hit the wall
   again at restitution 0.5, and bounce lower each time, 1000 steps (10 ms): most
   particle-steps are spheres in the skin, not touching. Variants none, prim, ours (no
   keyword beyond the law: tracking is the law's reach, 0 for hertz) and ours_skin
   (tracking = the skin, every sphere in the skin an open contact).
1f. A DEM code of one's own against the fix: examples/coupling/walls.c (the wall layer's
   calls over particles read from a dump, --walls PATH; bench/CMakeLists.txt builds it as
   bench_walls_client) on the static deck of section 1. The deck runs once with the fix
   and a dump of its last step; the client holds that bed for the deck's steps, its wall
   made from the fix's words, and prints its time per particle-step, which section 1's
   wall cost of the fix (loop time minus the baseline, measured in the same repetitions)
   is set against.
1g. A bouncing bed in a mesh: section 1e's bed (20000 spheres kicked inward at 0.2 m/s,
   all kept, 1000 steps) in the 4000-triangle STL cylinder of section 1c (200 x 10
   quads, wound inward: its facets' normals point to the axis), LIGGGHTS's mesh wall
   (fix mesh/surface + wall/gran ... mesh) against fix wall/rigid on the same STL, both
   sides acting (ours_mesh, the default of an STL) and the inward side alone
   (ours_mesh1, `sides 1`); ours, the analytic cylinder of section 1e, for scale.
2. Scaling: the same for N = 1e3 .. max-n (ours and prim; mesh at 1e4 only).
3. Strong scaling: a rotating drum (REVOLUTION mantle and end caps, 2 rad/s, gravity)
   with a settling bed of interacting spheres, 1 and 2 MPI ranks, loop time.
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
R, RHO, RC, F0, DT = 1.0e-3, 2500.0, 0.05, 1.0e-3, 1.0e-5
VFLOW = 0.5  # hoop speed of the flowing bed (m/s)
SKIN = 0.0005  # neighbour skin of the decks (m)
GAP_NEAR = 3.0e-4  # gap of the spheres of section 1d (m), inside the tracking thickness
SECTIONS = ["1", "1b", "1c", "1d", "1e", "1f", "1g", "2", "3"]
VKICK = 0.2  # inward speed of the bouncing bed at the start (m/s), section 1e
N_BOUNCE = 20000  # spheres of the bouncing bed
STEPS_BOUNCE = 1000  # its steps (10 ms: the first flight and the rebounds after it)
# Section 1c: the STL cylinder's quads (NTHETA x NZ, 4000 triangles) and the skin.
MESH_CASES = [((400, 5), SKIN), ((200, 10), SKIN), ((100, 20), SKIN), ((63, 32), SKIN),
              ((200, 10), 4 * SKIN)]
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
GAP = 2.2 * R
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}


# The start and the materials (Hertz with tangential history, two types) of every deck.
DECK_HEAD = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
"""
DECK_MATERIALS = """neighbor %r bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 1e7 1e8
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
"""


def materials(skin=SKIN):
    return DECK_MATERIALS % skin


def hertz_overlap(force):
    """Equilibrium overlap of a sphere under a normal force (Hertz, the deck's materials)."""
    y1, y2, n1, n2 = 1.0e7, 1.0e8, 0.3, 0.3
    ystar = 1.0 / ((1 - n1 * n1) / y1 + (1 - n2 * n2) / y2)
    return (3.0 * force / (4.0 * ystar * math.sqrt(R))) ** (2.0 / 3.0)


def monolayer(n, gap=None):
    """Sphere centres: rings on r0 = RC - R + delta_eq (or RC - R - gap: spheres that
    do not touch the wall), layers along z. Returns the positions and the height of the
    layer stack."""
    r0 = RC - R + (hertz_overlap(F0) if gap is None else -gap)
    per_ring = int(2 * math.pi * r0 / GAP)
    layers = (n + per_ring - 1) // per_ring
    pts = []
    for k in range(layers):
        z = (k + 0.5) * GAP
        for j in range(per_ring):
            if len(pts) == n:
                break
            a = 2 * math.pi * (j + 0.5 * (k % 2)) / per_ring
            pts.append((r0 * math.cos(a), r0 * math.sin(a), z))
    return pts, layers * GAP


def write_data(path, pts, height):
    b = RC + 0.005
    with open(path, "w") as f:
        f.write("monolayer on a cylinder\n\n%d atoms\n2 atom types\n\n" % len(pts))
        f.write("%r %r xlo xhi\n%r %r ylo yhi\n%r %r zlo zhi\n\nAtoms\n\n"
                % (-b, b, -b, b, -0.005, height + 0.005))
        for i, (x, y, z) in enumerate(pts):
            f.write("%d 1 %r %r %.12g %.12g %.12g\n" % (i + 1, 2 * R, RHO, x, y, z))


def wall_deck(variant, data, steps, height, flow=False, skin=SKIN, push=True, kick=0.0,
              push_every_step=False):
    """The deck of one variant. push_every_step: the radial push of a bed that moves only
    radially is evaluated at every step, as before 6d1c043 (push_ab.py), not stored."""
    d = DECK_HEAD + "read_data %s\n" % data + materials(skin) + "timestep %r\n" % DT
    f0 = F0 if push and variant != "none" else 0.0
    d += "variable f0 equal %r\n" % f0
    if not flow:
        d += "variable fx atom v_f0*x/sqrt(x*x+y*y)\nvariable fy atom v_f0*y/sqrt(x*x+y*y)\n"
    else:
        # Radial force f0 - k / r: the walls carry the push f0 and the centripetal load;
        # without a wall, k = m V^2 keeps the spheres on their circles (same formula, so
        # the same evaluation cost, in every variant).
        k = MASS * VFLOW ** 2 if variant == "none" else 0.0
        d += "variable k equal %r\n" % k
        # The spheres stay on their circles: 1/r is stored once, at the start.
        d += ("variable ir atom 1.0/sqrt(x*x+y*y)\nfix invr all store/state 0 v_ir\n"
              "variable fx atom (v_f0-v_k*f_invr)*x*f_invr\n"
              "variable fy atom (v_f0-v_k*f_invr)*y*f_invr\n")
        d += ("variable vx atom -%r*y/sqrt(x*x+y*y)\nvariable vy atom %r*x/sqrt(x*x+y*y)\n"
              % (VFLOW, VFLOW))
        d += "set group all vx v_vx vy v_vy omegaz %r\n" % (-VFLOW / R)
    if kick and variant != "none":
        d += ("variable kx atom -%r*x/sqrt(x*x+y*y)\nvariable ky atom -%r*y/sqrt(x*x+y*y)\n"
              "set group all vx v_kx vy v_ky\n" % (kick, kick))
    if flow or push_every_step:
        d += "fix push all addforce v_fx v_fy 0\n"
    else:
        # These beds move only radially: the push keeps the direction it has at the start,
        # stored once, so that its cost per step is a copy, not an evaluation of v_fx.
        d += ("fix pushdir all store/state 0 v_fx v_fy\n"
              "variable px atom f_pushdir[1]\nvariable py atom f_pushdir[2]\n"
              "fix push all addforce v_px v_py 0\n")
    if variant == "prim":
        d += "fix w all wall/gran model hertz tangential history primitive type 2 zcylinder %r 0 0\n" % RC
    elif variant == "ours":
        d += "fix w all wall/rigid surface cyl.inp law hertz type 2\n"
    elif variant == "ours_t0":
        d += "fix w all wall/rigid surface cyl.inp law hertz type 2 tracking 0\n"
    elif variant == "ours_skin":
        d += "fix w all wall/rigid surface cyl.inp law hertz type 2 tracking %r\n" % skin
    elif variant == "ours_mesh":
        d += "fix w all wall/rigid surface inline mesh cyl.stl law hertz type 2\n"
    elif variant == "ours_mesh1":
        d += "fix w all wall/rigid surface inline mesh cyl.stl sides 1 law hertz type 2\n"
    elif variant == "mesh":
        d += "fix cad all mesh/surface file cyl.stl type 2\n"
        d += "fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
    d += "fix integr all nve/sphere\nthermo %d\n" % steps
    d += "run %d\n" % steps
    return d


LOOP = re.compile(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")


def ratio(res, a, b):
    """Cost of wall a over wall b: from the fastest runs, and the median of the ratios
    of the repetitions (each against the baseline run just before it)."""
    c = res["cost"]
    rep = [p[a] / p[b] for p in res["per_rep"] if p[b] > 0]
    return "%.2f (fastest runs), %s (median of %d repetition%s)" % (
        c[a] / c[b], "%.2f" % statistics.median(rep) if rep else "n/a", len(rep),
        "" if len(rep) == 1 else "s")


def run_deck(exe, workdir, name, deck, np=1):
    path = os.path.join(workdir, name + ".in")
    with open(path, "w") as f:
        f.write(deck)
    cmd = [exe, "-in", path, "-log", "none", "-echo", "none"]
    if np > 1:
        cmd = ["mpirun", "-np", str(np)] + cmd
    env = dict(os.environ)
    env.update(MPI_ENV)
    p = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, errors="replace",
                       env=env)
    out = p.stdout + p.stderr
    loops = LOOP.findall(out)
    if p.returncode != 0 or not loops:
        sys.exit("bench: %s failed (exit %d):\n%s" % (name, p.returncode,
                                                      "\n".join(out.splitlines()[-12:])))
    builds = re.findall(r"Neighbor list builds = (\d+)", out)
    t, procs, steps, atoms = loops[-1]
    return {"loop": float(t), "steps": int(steps), "atoms": int(atoms),
            "builds": int(builds[-1]) if builds else -1}


def write_bed(workdir, n, gap=None, name="mono.data"):
    """The monolayer of n spheres as a data file and the REVOLUTION cylinder cyl.inp, in
    workdir; returns the data file's path and the bed's height."""
    pts, height = monolayer(n, gap)
    data = os.path.join(workdir, name)
    write_data(data, pts, height)
    with open(os.path.join(workdir, "cyl.inp"), "w") as f:
        f.write("*SURFACE, TYPE=REVOLUTION, NAME=cyl\n0, 0, 0, 0, 0, 1\n"
                "START, %r, -1\nLINE, %r, %r\n" % (RC, RC, height + 1.0))
    return data, height


def wall_costs(exe, workdir, n, variants, reps, log, flow=False, grid=(200, 10), skin=SKIN,
               gap=None, kick=0.0, steps=None):
    """Wall cost per particle-step of each variant. grid: the STL's NTHETA x NZ; gap:
    spheres that far from the wall and no push (None: pressed on the wall)."""
    data, height = write_bed(workdir, n, gap, "mono_%d.data" % n)
    if any("mesh" in v for v in variants):
        subprocess.run([sys.executable, os.path.join(HERE, "make_stl.py"),
                        os.path.join(workdir, "cyl.stl"), repr(RC), "-0.002",
                        repr(height + 0.002), str(grid[0]), str(grid[1])], check=True)
    steps = steps or int(min(10000, max(100, 1.0e7 / n)))
    best = {}
    per_rep = []  # loop times of each repetition, run back to back
    for rep in range(reps):
        loops = {}
        for v in ["none"] + variants:
            r = run_deck(exe, workdir, "%s_%d" % (v, n),
                         wall_deck(v, data, steps, height, flow, skin, gap is None, kick))
            if r["atoms"] != n:
                sys.exit("bench: %s lost atoms (%d of %d)" % (v, r["atoms"], n))
            loops[v] = r["loop"]
            if v not in best or r["loop"] < best[v]["loop"]:
                best[v] = r
        per_rep.append(loops)
    os.remove(data)
    res = {"n": n, "steps": steps, "height": height, "loop": {v: best[v]["loop"] for v in best},
           "builds": {v: best[v]["builds"] for v in best}}
    base = best["none"]["loop"]
    res["cost"] = {v: (best[v]["loop"] - base) / (n * steps) for v in variants}
    # Each repetition's wall costs against its own baseline, run seconds before, so that
    # the host's slow drifts cancel: ratio() also gives the median over repetitions.
    res["per_rep"] = [{v: (lp[v] - lp["none"]) / (n * steps) for v in variants}
                      for lp in per_rep]
    line = "N=%-8d steps=%-5d%s baseline %.3g us/particle-step" % (
        n, steps, " flowing" if flow else "", 1e6 * base / (n * steps))
    for v in variants:
        line += "  %s %.3g us" % (v, 1e6 * res["cost"][v])
    line += "  (neighbour builds %s)" % ",".join("%s:%d" % kv for kv in res["builds"].items())
    log(line)
    return res


def drum_deck(n_target):
    """A drum (radius 50 mm, length 40 mm, REVOLUTION mantle + caps) turning at 2 rad/s
    with gravity -y; spheres (R = 1 mm) start on a lattice in the lower half and settle."""
    d = DECK_HEAD + """processors * 1 1
region box block -0.052 0.052 -0.052 0.052 -0.022 0.022 units box
create_box 2 box
""" + materials() + """timestep 1e-5
lattice sc 0.00205
region bed cylinder z 0 0 0.0475 -0.0185 0.0185 units box
region low block INF INF INF 0.01 INF INF units box
region fill intersect 2 bed low
create_atoms 1 region fill
set group all diameter 0.002 density 2500
fix grav all gravity 9.81 vector 0 -1 0
fix w all wall/rigid surface drum.inp law hertz type 2 rotate origin 0 0 0 axis 0 0 1 omega 2
fix integr all nve/sphere
thermo 500
run 500
run 1500
"""
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--quick", action="store_true", help="small sizes, one repetition")
    ap.add_argument("--max-n", type=int, default=1000000)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--out", default=None, help="also write the report here")
    ap.add_argument("--walls", default=None,
                    help="the walls client (bench_walls_client), for section 1f")
    ap.add_argument("--sections", default=",".join(SECTIONS),
                    help="comma-separated sections to run (default: all, %s)" % ",".join(SECTIONS))
    args = ap.parse_args()
    want = args.sections.split(",")
    for sec in want:
        if sec not in SECTIONS:
            ap.error("unknown section '%s' (expected some of %s)" % (sec, ",".join(SECTIONS)))
    exe = os.path.abspath(args.exe)
    work = tempfile.mkdtemp(prefix="rs_bench_lig_")
    report = open(args.out, "w") if args.out else None

    def log(s):
        """Prints a report line, and writes it to --out at once, so that a run stopped
        part-way keeps what it measured."""
        print(s)
        sys.stdout.flush()
        if report:
            report.write(s + "\n")
            report.flush()

    reps = 1 if args.quick else args.reps
    log("# LIGGGHTS walls benchmark, %s, %s" % (time.strftime("%Y-%m-%d %H:%M"), exe))
    log("# wall cost per particle-step in microseconds (loop time minus the no-wall "
        "baseline), fastest of %d" % reps)

    n1 = 2000 if args.quick else 10000
    if "1" in want:
        log("## 1. cylinder wall cost, all walls side by side")
        r = wall_costs(exe, work, n1, ["prim", "ours", "mesh"], reps, log)
        log("ours / prim = %s (target <= 1.1)" % ratio(r, "ours", "prim"))
        log("mesh / ours = %s (target >= 20)" % ratio(r, "mesh", "ours"))

    if "1b" in want:
        log("## 1b. cylinder wall cost, flowing bed (rolling at %g m/s, neighbour rebuilds)"
            % VFLOW)
        r = wall_costs(exe, work, n1, ["prim", "ours", "mesh"], reps, log, flow=True)
        log("ours / prim = %s (target 1.05-1.27)" % ratio(r, "ours", "prim"))
        log("mesh / ours = %s (target >= 20)" % ratio(r, "mesh", "ours"))

    if "1c" in want:
        log("## 1c. the mesh wall against its facets and the skin (static deck, %d "
            "repetitions)" % min(reps, 3))
        for grid, skin in MESH_CASES:
            r = wall_costs(exe, work, n1, ["prim", "ours", "mesh", "ours_mesh"], min(reps, 3),
                           log, grid=grid, skin=skin)
            log("%d x %d quads (%d triangles, %.2g x %.2g mm), skin %g mm:"
                % (grid[0], grid[1], 2 * grid[0] * grid[1],
                   1e3 * 2 * math.pi * RC / grid[0], 1e3 * r["height"] / grid[1], 1e3 * skin))
            for a, b in (("mesh", "prim"), ("ours", "prim"), ("mesh", "ours"),
                         ("ours_mesh", "mesh"), ("ours_mesh", "ours")):
                log("  %s / %s = %s" % (a, b, ratio(r, a, b)))
            log("  (ours_mesh: fix wall/rigid on the same STL, target ours_mesh / mesh "
                "<= 0.5)")

    if "1d" in want:
        log("## 1d. spheres near the wall, not touching it (gap %g mm, inside the tracking "
            "thickness = skin %g mm; no push)" % (1e3 * GAP_NEAR, 1e3 * SKIN))
        r = wall_costs(exe, work, n1, ["prim", "ours", "ours_t0", "mesh", "ours_mesh"], reps,
                       log, gap=GAP_NEAR)
        c = r["cost"]
        log("ours (open contacts passed to the law) = %.3g us, ours with tracking 0 = %.3g us,"
            " prim = %.3g us, mesh = %.3g us, ours_mesh = %.3g us"
            % tuple(1e6 * c[v] for v in ("ours", "ours_t0", "prim", "mesh", "ours_mesh")))

    if "1e" in want:
        nb = 2000 if args.quick else N_BOUNCE
        log("## 1e. a bouncing bed, default keywords (kicked inward at %g m/s: rebounds "
            "inside the skin, %d spheres, %d steps)" % (VKICK, nb, STEPS_BOUNCE))
        r = wall_costs(exe, work, nb, ["prim", "ours", "ours_skin"], reps, log, kick=VKICK,
                       steps=STEPS_BOUNCE)
        log("ours / prim = %s (target <= 1.2)" % ratio(r, "ours", "prim"))
        log("ours_skin / prim = %s" % ratio(r, "ours_skin", "prim"))

    if "1f" in want:
        if not args.walls:
            ap.error("section 1f needs --walls PATH (bench_walls_client)")
        log("## 1f. a DEM code of one's own (examples/coupling/walls.c) against the fix, "
            "static deck")
        client(exe, os.path.abspath(args.walls), work, n1, reps, log)

    if "1g" in want:
        nb = 2000 if args.quick else N_BOUNCE
        log("## 1g. a bouncing bed in a %d-triangle STL cylinder (kicked inward at %g m/s, "
            "%d spheres, %d steps)" % (2 * 200 * 10, VKICK, nb, STEPS_BOUNCE))
        r = wall_costs(exe, work, nb, ["ours", "mesh", "ours_mesh", "ours_mesh1"], reps, log,
                       kick=VKICK, steps=STEPS_BOUNCE)
        log("mesh / ours_mesh = %s (target >= 10)" % ratio(r, "mesh", "ours_mesh"))
        log("mesh / ours_mesh1 = %s (target >= 10)" % ratio(r, "mesh", "ours_mesh1"))
        log("ours_mesh1 / ours_mesh = %s (one side against two, target <= 1)"
            % ratio(r, "ours_mesh1", "ours_mesh"))
        log("ours_mesh / ours = %s (the mesh against the analytic cylinder)"
            % ratio(r, "ours_mesh", "ours"))

    if "2" in want:
        scaling(exe, work, args, reps, log)
    if "3" in want:
        strong_scaling(exe, work, reps, log)
    if report:
        report.close()


def client(exe, walls, work, n, reps, log):
    """Section 1f: the static deck's wall cost in the fix and in the walls client, each
    repetition the baseline, the fix (with a dump of its last step) and the client holding
    that bed, back to back."""
    data, height = write_bed(work, n, None, "mono_client.data")
    steps = int(min(10000, max(100, 1.0e7 / n)))
    words = "surface cyl.inp law hertz type 2 props 1e7 0.3 1e8 0.3 0.5 0.5 0"
    with open(os.path.join(work, "client.scene"), "w") as f:
        f.write("dt %r\nskin %r\nbox %r %r %r %r %r %r\nwall w %s\n" % (
            DT, SKIN, -RC - 0.005, RC + 0.005, -RC - 0.005, RC + 0.005, -0.005,
            height + 0.005, words))
    fix_cost, ours = [], []
    for rep in range(reps):
        base = run_deck(exe, work, "none_client", wall_deck("none", data, steps, height))
        d = wall_deck("ours", data, steps, height)
        d = d.replace("law hertz type 2\n", "law hertz type 2 props 1e7 0.3 1e8 0.3 0.5 0.5 0\n")
        d = d.replace("run %d\n" % steps, "dump bed all custom %d bed.dump id x y z vx vy vz "
                      "omegax omegay omegaz radius mass\ndump_modify bed sort id format "
                      "\"%%d%s\"\nrun %d\n" % (steps, " %.17g" * 11, steps))
        r = run_deck(exe, work, "ours_client", d)
        fix_cost.append((r["loop"] - base["loop"]) / (n * steps))
        # the dump's last frame: the bed as the fix held it
        with open(os.path.join(work, "bed.dump")) as f:
            frames = f.read().split("ITEM: TIMESTEP\n")
        with open(os.path.join(work, "bed_last.dump"), "w") as f:
            f.write("ITEM: TIMESTEP\n" + frames[-1])
        p = subprocess.run([walls, "client.scene", "bed_last.dump", "--hold", str(steps)],
                           cwd=work, capture_output=True, text=True)
        m = re.search(r"([0-9.eE+-]+) ns per particle-step", p.stdout)
        if p.returncode != 0 or not m:
            sys.exit("bench: the walls client failed:\n" + p.stdout + p.stderr)
        ours.append(float(m.group(1)) * 1e-9)
    os.remove(data)
    rep = [a / b for a, b in zip(ours, fix_cost) if b > 0]
    log("N=%-8d steps=%-5d fix %.3g us, client %.3g us per particle-step (fastest)"
        % (n, steps, 1e6 * min(fix_cost), 1e6 * min(ours)))
    log("client / fix = %.2f (fastest runs), %s (median of %d repetitions) (target <= 1.05)"
        % (min(ours) / min(fix_cost), "%.2f" % statistics.median(rep) if rep else "n/a",
           len(rep)))


def scaling(exe, work, args, reps, log):
    log("## 2. scaling (ours and prim)")
    sizes = [1000, 10000] if args.quick else [1000, 10000, 100000, 1000000]
    rows = []
    for n in sizes:
        if n > args.max_n:
            log("N=%d skipped (--max-n %d)" % (n, args.max_n))
            continue
        rows.append(wall_costs(exe, work, n, ["prim", "ours"], reps, log))
    ours = [row["cost"]["ours"] for row in rows]
    log("ours per particle-step: min %.3g us, max %.3g us, max/min = %.2f (target <= 1.15)"
        % (1e6 * min(ours), 1e6 * max(ours), max(ours) / min(ours)))
    worst = max(row["cost"]["ours"] / row["cost"]["prim"] for row in rows)
    log("ours / prim at most %.2f over the sizes (target <= 0.9 at every N)" % worst)


def strong_scaling(exe, work, reps, log):
    log("## 3. strong scaling, rotating drum with a settling bed")
    with open(os.path.join(work, "drum.inp"), "w") as f:
        f.write("*SURFACE, TYPE=REVOLUTION, NAME=drum\n0, 0, 0, 0, 0, 1\n"
                "START, 0, -0.02\nLINE, 0.05, -0.02\nLINE, 0.05, 0.02\nLINE, 0, 0.02\n")
    t = {}
    for np in (1, 2):
        best = None
        for rep in range(reps):
            rr = run_deck(exe, work, "drum_np%d" % np, drum_deck(0), np=np)
            if best is None or rr["loop"] < best["loop"]:
                best = rr
        t[np] = best
        log("np=%d: %d atoms, %d steps, loop %.3f s" % (np, best["atoms"], best["steps"], best["loop"]))
    log("speed-up %.2f, parallel efficiency %.0f %%"
        % (t[1]["loop"] / t[2]["loop"], 100 * t[1]["loop"] / (2 * t[2]["loop"])))


if __name__ == "__main__":
    main()
