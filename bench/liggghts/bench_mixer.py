#!/usr/bin/python3
"""Wall cost of a rotating mixer blade of many triangles (examples/mixer's blade,
make_blade.py with facets of CELL, default 0.5 mm: 232128 triangles) in the mixer's bowl,
LIGGGHTS's mesh wall against fix wall/rigid's MESH, side by side in one run.

    bench_mixer.py --exe liggghts-rigidsurf [--reps K] [--steps N] [--cell CELL]

LIGGGHTS keeps, per sphere, the triangles of its mesh neighbour list in one chunk of at
most `neigh_modify one` entries (2000 by default); a sphere near a blade of facets under
0.8 mm sees more, and the run stops in its setup ("mesh neighbor list overflow, boost
neigh_modify one and/or page", fix_contact_history_mesh.cpp, printed to a pipe only when
its output is unbuffered). The mesh variant therefore sets `neigh_modify one 10000 page
100000` (page at least 10 x one); at 0.8 mm that line changes LIGGGHTS's cost by less
than the noise.

The bed (3000 spheres) settles once around the still blade (fix wall/rigid walls) and
is written to a restart file. From it, each variant turns the blade at 12 rad/s for N
steps (default 1000):
  none       no blade (the baseline)
  mesh       neigh_modify one 10000 page 100000, fix mesh/surface + fix move/mesh rotate
             + fix wall/gran ... mesh
  ours_mesh  fix wall/rigid surface inline mesh ... rotate
The bowl is fix wall/rigid (REVOLUTION) in every variant. Wall cost per particle-step =
(loop time - the baseline's) / (N spheres); the fastest of K repetitions (default 3),
run in turn.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

from bench_walls import DECK_HEAD  # the decks' common start

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
MATERIALS = """neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.0e6 5.0e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m4 all property/global coefficientFriction peratomtypepair 2 0.4 0.4 0.4 0.4
pair_style gran model hertz tangential history
pair_coeff * *
timestep 4.0e-5
fix grav all gravity 9.81 vector 0 0 -1
fix bowl all wall/rigid surface bowl.inp law hertz type 2
"""


def run(exe, wd, name, deck):
    with open(os.path.join(wd, name + ".in"), "w") as f:
        f.write(deck)
    p = subprocess.run([exe, "-in", name + ".in", "-log", "none", "-echo", "none"], cwd=wd,
                       capture_output=True, text=True, errors="replace", env=ENV)
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms",
                       p.stdout + p.stderr)
    if p.returncode or not loops:
        sys.exit("bench_mixer: %s failed:\n%s" % (name, "\n".join((p.stdout + p.stderr).splitlines()[-8:])))
    return float(loops[-1][0]), int(loops[-1][2])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--steps", type=int, default=1000)
    ap.add_argument("--cell", default="0.0005")
    a = ap.parse_args()
    wd = tempfile.mkdtemp(prefix="rs_bench_mixer_")
    subprocess.run([sys.executable, os.path.join(ROOT, "examples", "mixer", "make_blade.py"),
                    os.path.join(wd, "blade.stl"), a.cell], check=True)
    with open(os.path.join(ROOT, "examples", "mixer", "bowl.inp")) as f, \
            open(os.path.join(wd, "bowl.inp"), "w") as g:
        g.write(f.read())
    settle = DECK_HEAD + "region box block -0.095 0.095 -0.095 0.095 -0.005 0.16 units box\n"
    settle += "create_box 2 box\n" + MATERIALS
    settle += "fix blade all wall/rigid surface inline mesh blade.stl law hertz type 2\n"
    settle += ("fix pts all particletemplate/sphere 15485863 atom_type 1 density constant 2500 "
               "radius constant 0.00275\nfix pdd all particledistribution/discrete 32452843 1 pts 1.0\n"
               "region fill cylinder z 0 0 0.075 0.06 0.15 units box\n"
               "fix ins all insert/pack seed 32452867 distributiontemplate pdd maxattempt 200 "
               "insert_every once overlapcheck yes all_in yes vel constant 0 0 -0.5 "
               "region fill particles_in_region 3000\nfix integr all nve/sphere\nrun 5000\n"
               "unfix blade\nunfix ins\nwrite_restart bed.restart\n")
    run(a.exe, wd, "settle", settle)
    start = "atom_modify map array\ncommunicate single vel yes\nread_restart bed.restart\nnewton off\n"
    start += "\n".join(l for l in MATERIALS.splitlines()) + "\nfix integr all nve/sphere\n"
    walls = {
        "none": "",
        "mesh": ("neigh_modify one 10000 page 100000\n"
                 "fix cad all mesh/surface file blade.stl type 2\n"
                 "fix spin all move/mesh mesh cad rotate origin 0 0 0 axis 0 0 1 period %r\n"
                 "fix blade all wall/gran model hertz tangential history mesh n_meshes 1 "
                 "meshes cad\n" % (2 * 3.141592653589793 / 12.0)),
        "ours_mesh": ("fix blade all wall/rigid surface inline mesh blade.stl law hertz "
                      "type 2 rotate origin 0 0 0 axis 0 0 1 omega 12\n"),
    }
    best = {}
    n = 0
    for rep in range(a.reps):
        for v, w in walls.items():
            t, n = run(a.exe, wd, v, start + w + "run %d\n" % a.steps)
            best[v] = min(best.get(v, t), t)
    cost = {v: (best[v] - best["none"]) / (n * a.steps) for v in ("mesh", "ours_mesh")}
    with open(os.path.join(wd, "blade.stl"), "rb") as f:  # binary: the count at byte 80
        ntri = int.from_bytes(f.read(84)[80:84], "little")
    print("# bench_mixer: %d spheres, %d steps, blade of %d triangles (cell %s m), in %s"
          % (n, a.steps, ntri, a.cell, wd))
    print("baseline %.3g us/particle-step; blade: mesh %.3g us, ours_mesh %.3g us; "
          "ours_mesh / mesh = %.2f (target <= 0.5)"
          % (1e6 * best["none"] / (n * a.steps), 1e6 * cost["mesh"], 1e6 * cost["ours_mesh"],
             cost["ours_mesh"] / cost["mesh"]))


if __name__ == "__main__":
    main()
