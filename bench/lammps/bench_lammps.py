#!/usr/bin/python3
"""LAMMPS-side benchmark of fix wall/rigid: its cost against LAMMPS's own region wall on
the same deck, measured side by side in one run.

    bench_lammps.py --exe lmp-rigidsurf [--quick] [--n N] [--reps K] [--out FILE]

The deck is section 1 of bench/liggghts/bench_walls.py in LAMMPS: N spheres (R = 1 mm)
form a monolayer on the inside of a cylinder of radius 50 mm about z (rings 2.2 R apart,
layers 2.2 R apart, so spheres never touch each other: pair_style none), pressed on the
wall by a radial body force (fix addforce, 1 mN, its direction stored once by fix
store/state 0), fix nve/sphere, no gravity. Every sphere is in contact every step, at the
equilibrium overlap of its push. The contact model is LAMMPS's `hertz/history` (kn =
4/3 Y* of the LIGGGHTS deck, damping, friction 0.5) in every wall but the last:

  none       no wall, no push: the spheres sit still (the baseline)
  region     fix wall/gran/region hertz/history ... region cyl, a `region cylinder z 0 0
             0.05 INF INF side in`: the wall of a LAMMPS user's deck (the reference)
  zcylinder  fix wall/gran hertz/history ... zcylinder 0.05: LAMMPS's primitive
  ours       fix wall/rigid, a REVOLUTION (one LINE at r = 50 mm), law lammps reff region
             hertz/history with the same words: what rigidsurf-migrate writes for the
             region wall, the same model code and the same numbers
  ours_hertz fix wall/rigid with rigidsurf's own law hertz (materials on the fix line),
             whose fused kernel runs on the revolved LINE

Wall cost per particle-step = (loop time with the wall - loop time of 'none') / (N
steps). The spheres move by nanometres (skin 0.5 mm), so no variant rebuilds its
neighbour lists during the run (the report lists the builds), and the integrator and the
body force cost the same in all variants: the difference is the wall. Each variant runs
REPS times, interleaved; a ratio of two walls is given from the fastest run of each, and
as the median over the repetitions of the ratio within one repetition (each wall's cost
against the baseline run just before it), which cancels the slow drifts of a shared host.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "liggghts"))
import bench_walls as B  # noqa: E402  (the monolayer, its data file, the loop-time parser)

VARIANTS = ["region", "zcylinder", "ours", "ours_hertz"]
# LAMMPS's hertz/history: F = kn delta sqrt(delta Reff) with kn = 4/3 Y*, Y* the LIGGGHTS
# deck's (Y = 1e7 and 1e8, nu = 0.3): the equilibrium overlap of bench_walls.monolayer;
# gamma_n damps a sphere's normal oscillation at about a fifth of critical.
YSTAR = 1.0 / ((1 - 0.3 ** 2) / 1.0e7 + (1 - 0.3 ** 2) / 1.0e8)
MODEL = "hertz/history %r NULL 1e8 NULL 0.5 1" % (4.0 / 3.0 * YSTAR)
MATERIALS = ("youngsModulus 1e7 1e8 poissonsRatio 0.3 0.3 coefficientRestitution 0.5 0.5 "
             "coefficientFriction 0.5 0.5")


def deck(variant, data, steps, height):
    """The deck of one variant."""
    d = """atom_style sphere
atom_modify map array
boundary f f f
newton off
comm_modify vel yes
units si
read_data %s
neighbor %r bin
neigh_modify delay 0
pair_style none
timestep %r
""" % (data, B.SKIN, B.DT)
    f0 = B.F0 if variant != "none" else 0.0
    # The beds move only radially: the push keeps the direction it has at the start,
    # stored once, so that its cost per step is a copy.
    d += ("variable f0 equal %r\n"
          "variable fx atom v_f0*x/sqrt(x*x+y*y)\nvariable fy atom v_f0*y/sqrt(x*x+y*y)\n"
          "fix pushdir all store/state 0 v_fx v_fy\n"
          "variable px atom f_pushdir[1]\nvariable py atom f_pushdir[2]\n"
          "fix push all addforce v_px v_py 0\n" % f0)
    if variant == "region":
        d += "region cyl cylinder z 0 0 %r INF INF side in units box\n" % B.RC
        d += "fix w all wall/gran/region %s region cyl\n" % MODEL
    elif variant == "zcylinder":
        d += "fix w all wall/gran %s zcylinder %r\n" % (MODEL, B.RC)
    elif variant in ("ours", "ours_hertz"):
        law = ("lammps reff region %s" % MODEL if variant == "ours"
               else "hertz type 2 %s" % MATERIALS)
        d += ("fix w all wall/rigid surface inline revolution origin 0 0 0 axis 0 0 1 "
              "profile START %r -1 LINE %r %r end law %s\n" % (B.RC, B.RC, height + 1.0, law))
    d += "fix integr all nve/sphere\nthermo %d\nrun %d\n" % (steps, steps)
    return d


def wall_costs(exe, work, n, reps, log):
    """Each variant's wall cost per particle-step, the fastest and per repetition."""
    pts, height = B.monolayer(n)
    data = os.path.join(work, "mono_%d.data" % n)
    B.write_data(data, pts, height)
    steps = int(min(10000, max(100, 2.0e7 / n)))
    best, per_rep = {}, []
    for rep in range(reps):
        loops = {}
        for v in ["none"] + VARIANTS:
            r = B.run_deck(exe, work, "%s_%d" % (v, n), deck(v, data, steps, height))
            if r["atoms"] != n:
                sys.exit("bench: %s lost atoms (%d of %d)" % (v, r["atoms"], n))
            loops[v] = r["loop"]
            if v not in best or r["loop"] < best[v]["loop"]:
                best[v] = r
        per_rep.append(loops)
    os.remove(data)
    base = best["none"]["loop"]
    res = {"cost": {v: (best[v]["loop"] - base) / (n * steps) for v in VARIANTS},
           "per_rep": [{v: (lp[v] - lp["none"]) / (n * steps) for v in VARIANTS}
                       for lp in per_rep]}
    line = "N=%-8d steps=%-5d baseline %.3g us/particle-step" % (
        n, steps, 1e6 * base / (n * steps))
    for v in VARIANTS:
        line += "  %s %.3g us" % (v, 1e6 * res["cost"][v])
    log(line)
    log("(neighbour builds %s)" % ", ".join("%s %d" % (v, best[v]["builds"]) for v in best))
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True, help="lmp-rigidsurf")
    ap.add_argument("--quick", action="store_true", help="2000 spheres, one repetition")
    ap.add_argument("--n", type=int, default=10000, help="spheres (default 10000)")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--out", default=None, help="also write the report here")
    args = ap.parse_args()
    exe = os.path.abspath(args.exe)
    work = tempfile.mkdtemp(prefix="rs_bench_lmp_")
    report = open(args.out, "w") if args.out else None

    def log(s):
        """A report line, written to --out at once (a run stopped part-way keeps it)."""
        print(s)
        sys.stdout.flush()
        if report:
            report.write(s + "\n")
            report.flush()

    reps = 1 if args.quick else args.reps
    n = 2000 if args.quick else args.n
    log("# LAMMPS walls benchmark, %s, %s" % (time.strftime("%Y-%m-%d %H:%M"), exe))
    log("# wall cost per particle-step in microseconds (loop time minus the no-wall "
        "baseline), fastest of %d; model %s" % (reps, MODEL))
    log("## cylinder wall cost, a monolayer pressed on the inside, all walls side by side")
    r = wall_costs(exe, work, n, reps, log)
    log("ours / region = %s (target <= 1.0)" % B.ratio(r, "ours", "region"))
    log("ours_hertz / region = %s" % B.ratio(r, "ours_hertz", "region"))
    log("zcylinder / region = %s" % B.ratio(r, "zcylinder", "region"))
    log("ours / zcylinder = %s" % B.ratio(r, "ours", "zcylinder"))
    if report:
        report.close()


if __name__ == "__main__":
    main()
