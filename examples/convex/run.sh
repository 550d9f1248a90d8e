#!/bin/bash
# Convex bodies in the standalone driver: bash examples/convex/run.sh
# Builds convex_tumble in build/ (or $BUILD_DIR) when needed, runs a rounded-box tablet,
# a capsule and a die in the main job's drum turning at 3 rad/s for 6 s, writes VTK of
# the drum and the bodies in examples/convex/out/post/ and out/convex.png, and checks
# that no body passes the wall.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${BUILD_DIR:-$root/build}
start=$(date +%s)
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
fi
cmake --build "$build" -j"$(nproc)" --target convex_tumble > /dev/null
out=$here/out
rm -rf "$out"
mkdir -p "$out/post"
"$build/examples/convex_tumble" "$root/examples/surfaces/drum.inp" "$out"
/usr/bin/python3 "$here/plot.py" "$out"
echo "ParaView: $out/post/wall_*.vtk and $out/post/bodies_*.vtk"
echo "wall time: $(( $(date +%s) - start )) s"
