#!/bin/bash
# Rounded polyhedra tumbling in a rotating drum in LAMMPS: bash examples/lammps_bodies/run.sh
# Builds lmp-rigidsurf in build/ (or $BUILD_DIR) when needed, writes the bodies' data file
# (make_bodies.py), runs in.bodies in examples/lammps_bodies/out/, plots the dynamic angle
# of repose and the kinetic energy and checks the run (bodies.py: the bodies stay inside
# the drum, the bed tumbles at a steady angle, the energy stays bounded), and writes the
# bodies' faces as VTK files (bodies_vtk.py). NP=2 runs on two MPI ranks. TRUN=s shortens
# the rotation (default 0.6 s; the test suite runs 0.3 s).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
engine=lammps
source "$here/../lib.sh"
trun=${TRUN:-0.6}
/usr/bin/python3 "$here/make_bodies.py" bodies.data
echo "lammps_bodies: 0.15 s settling, 0.05 s spin-up, $trun s at 4 rad/s" \
     "(log: $out/log_bodies.lammps)"
rs_run bodies ../in.bodies -var trun "$trun"
/usr/bin/python3 "$here/bodies_vtk.py" bodies.data post/vertices.dump post post/bodies.dump
status=0
/usr/bin/python3 "$here/bodies.py" "$out" || status=1
echo "ParaView: $out/post/drum_*.vtk (wall) and $out/post/bodies_*.vtk (the bodies' faces)"
echo "wall time: $(( $(date +%s) - start )) s"
exit $status
