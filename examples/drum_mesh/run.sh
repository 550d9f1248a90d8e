#!/bin/bash
# The README's drum, analytic and tessellated: bash examples/drum_mesh/run.sh
# Runs examples/drum/in.drum twice, with the REVOLUTION wall of examples/drum/drum.inp
# and with the same drum as a MESH (make_stl.py: 14040 triangles), and prints and plots
# the steady dynamic angle of repose and the wall time of each (out/compare.png).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../lib.sh"
/usr/bin/python3 "$here/make_stl.py" "$out/drum.stl"
for kind in analytic mesh; do
    mkdir -p "$out/$kind/post"
    if [ "$kind" = analytic ]; then
        surf="surface $root/examples/drum/drum.inp"
    else
        surf="surface inline mesh $out/drum.stl"
    fi
    echo "drum_mesh: $kind wall: 2600 spheres, 0.35 s fill and spin-up, 1.2 s at 3 rad/s"
    (cd "$out/$kind" && rs_run "$kind" "$root/examples/drum/in.drum" -var surf "$surf")
    /usr/bin/python3 "$root/examples/drum/angle.py" "$out/$kind" > "$out/$kind/angle_summary.txt" || true
done
/usr/bin/python3 "$here/compare.py" "$out"
echo "wall time: $(( $(date +%s) - start )) s"
