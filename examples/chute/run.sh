#!/bin/bash
# Spheres rolling and sliding down a curved chute: bash examples/chute/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, runs in.chute in
# examples/chute/out/ and checks the speeds against energy balance.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
echo "chute: 5 rolling and 5 sliding spheres released on the arc, 0.3 s"
rs_run chute ../in.chute
/usr/bin/python3 "$here/check.py" "$out"
echo "ParaView: $out/post/chute_*.vtk (wall) and $out/post/spheres_*.vtk"
echo "wall time: $(( $(date +%s) - start )) s"
