#!/bin/bash
# Rounded polyhedra tumbling in a rotating drum in LAMMPS: bash examples/lammps_bodies/run.sh
# Builds lmp-rigidsurf in build/ (or $BUILD_DIR) when needed, writes the bodies' data file
# (make_bodies.py), runs in.bodies in examples/lammps_bodies/out/, plots the dynamic angle
# of repose and the kinetic energy and checks the run (bodies.py: the bodies stay inside
# the drum, the bed tumbles at a steady angle, the energy stays bounded), and writes the
# bodies' faces as VTK files (bodies_vtk.py). NP=2 runs on two MPI ranks. TRUN=ms shortens
# the rotation (default 600 ms); a rotation under 600 ms is too short for a steady angle,
# and bodies.py --short checks that the wall lifted the bed instead (the test suite runs
# 200 ms).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
engine=lammps
source "$here/../lib.sh"
trun=${TRUN:-600}
/usr/bin/python3 "$here/make_bodies.py" bodies.data
echo "lammps_bodies: 84 rounded polyhedra, 150 ms settling, 50 ms spin-up, $trun ms at 4 rad/s" \
     "(log: $out/log_bodies.lammps)"
rs_run bodies ../in.bodies -var trun "$trun"
/usr/bin/python3 "$here/bodies_vtk.py" bodies.data post/vertices.dump post post/bodies.dump
status=0
short=()
[ "$trun" -lt 600 ] && short=(--short)
/usr/bin/python3 "$here/bodies.py" "$out" "${short[@]}" || status=1
echo "ParaView: $out/post/drum_*.vtk (wall) and $out/post/bodies_*.vtk (the bodies' faces)"
echo "wall time: $(( $(date +%s) - start )) s"
exit $status
