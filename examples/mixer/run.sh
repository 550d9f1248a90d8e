#!/bin/bash
# A rotating mixer blade (MESH) in a bowl (REVOLUTION): bash examples/mixer/run.sh
# Makes the blade's STL (make_blade.py, about 26000 triangles), runs in.mixer in
# examples/mixer/out/ and plots the blade torque and the mixing index (out/mixer.png).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
/usr/bin/python3 "$here/make_blade.py" "$out/blade.stl"
echo "mixer: 3000 spheres, 0.2 s fill, 1.2 s with the blade at 12 rad/s (log: $out/log_mixer.liggghts)"
rs_run mixer ../in.mixer
/usr/bin/python3 "$here/mixing.py" "$out" 0.2
echo "ParaView: $out/post/blade_*.vtk (blade) and $out/post/particles_*.vtk (spheres)"
echo "wall time: $(( $(date +%s) - start )) s"
