#!/bin/bash
# Discharge of a conical hopper: bash examples/hopper/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, runs in.hopper in
# examples/hopper/out/, plots the discharge rate and compares it with Beverloo.
# NP=2 runs on two MPI ranks.
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
run=(stdbuf -o0 "$exe" -in ../in.hopper -echo none -log log.liggghts)
if [ "$np" -gt 1 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    export OMPI_MCA_mpi_yield_when_idle=1
    run=(mpirun -np "$np" "${run[@]}")
fi
echo "hopper: 3500 spheres, 0.3 s fill with the outlet plugged, 0.5 s discharge"
if ! "${run[@]}" > screen.txt 2>&1; then
    grep -E "ERROR|WARNING" screen.txt || tail -20 screen.txt
    exit 1
fi
/usr/bin/python3 "$here/flow.py" "$out"
echo "ParaView: $out/post/hopper_*.vtk (wall) and $out/post/particles_*.vtk (spheres)"
echo "wall time: $(( $(date +%s) - start )) s"
