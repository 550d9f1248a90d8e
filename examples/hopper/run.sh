#!/bin/bash
# Discharge of a conical hopper: bash examples/hopper/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, runs in.hopper in
# examples/hopper/out/, plots the discharge rate and compares it with Beverloo.
# NP=2 runs on two MPI ranks.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
echo "hopper: 3500 spheres, 0.3 s fill with the outlet plugged, 0.5 s discharge"
rs_run hopper ../in.hopper
/usr/bin/python3 "$here/flow.py" "$out"
echo "ParaView: $out/post/hopper_*.vtk (wall) and $out/post/particles_*.vtk (spheres)"
echo "wall time: $(( $(date +%s) - start )) s"
