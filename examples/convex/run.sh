#!/bin/bash
# Convex bodies in the standalone driver: bash examples/convex/run.sh
# Builds convex_tumble in build/ (or $BUILD_DIR) when needed, runs a rounded-box tablet,
# a capsule and a die in the main job's drum turning at 3 rad/s for 6 s, and down a
# faceted chute (a MESH) for 0.4 s; writes VTK in examples/convex/out/post/,
# out/convex.png and out/chute.png, and checks that no body passes the drum's wall and
# that the chute's accelerations are the closed forms'.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${BUILD_DIR:-$root/build}
start=$(date +%s)
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
fi
cmake --build "$build" -j"$(nproc)" --target convex_tumble convex_chute > /dev/null
out=$here/out
rm -rf "$out"
mkdir -p "$out/post"
"$build/examples/convex_tumble" "$root/examples/surfaces/drum.inp" "$out"
"$build/examples/convex_chute" "$out"
/usr/bin/python3 "$here/plot.py" "$out"
echo "ParaView: $out/post/wall_*.vtk, $out/post/bodies_*.vtk and $out/post/chute_*.vtk"
echo "wall time: $(( $(date +%s) - start )) s"
