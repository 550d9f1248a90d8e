#!/bin/bash
# Rotating drum to steady avalanching: bash examples/drum/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, runs in.drum in
# examples/drum/out/ and plots the dynamic angle of repose. NP=2 runs on two MPI
# ranks (the drum is split along its axis).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
echo "drum: 2600 spheres, 0.35 s fill and spin-up, 1.2 s at 3 rad/s (log: $out/log_drum.liggghts)"
rs_run drum ../in.drum
/usr/bin/python3 "$here/angle.py" "$out"
echo "ParaView: $out/post/drum_*.vtk (wall) and $out/post/particles_*.vtk (spheres)"
echo "wall time: $(( $(date +%s) - start )) s"
