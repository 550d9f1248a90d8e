#!/bin/bash
# Spheres rolling and sliding down a curved chute: bash examples/chute/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, runs in.chute in
# examples/chute/out/ and checks the speeds against energy balance.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${BUILD_DIR:-$root/build}
exe=$build/coupling/liggghts-rigidsurf
np=${NP:-1}
start=$(date +%s)

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
fi
cmake --build "$build" -j"$(nproc)" --target liggghts-rigidsurf > /dev/null

out=$here/out
rm -rf "$out"
mkdir -p "$out/post"
cd "$out"
run=(stdbuf -o0 "$exe" -in ../in.chute -echo none -log log.liggghts)
if [ "$np" -gt 1 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    export OMPI_MCA_mpi_yield_when_idle=1
    run=(mpirun -np "$np" "${run[@]}")
fi
echo "chute: 5 rolling and 5 sliding spheres released on the arc, 0.3 s"
if ! "${run[@]}" > screen.txt 2>&1; then
    grep -E "ERROR|WARNING" screen.txt || tail -20 screen.txt
    exit 1
fi
/usr/bin/python3 "$here/check.py" "$out"
echo "ParaView: $out/post/chute_*.vtk (wall) and $out/post/spheres_*.vtk"
echo "wall time: $(( $(date +%s) - start )) s"
