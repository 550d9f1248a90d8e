#!/bin/bash
# Rotating drum to steady avalanching: bash examples/drum/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, runs in.drum in
# examples/drum/out/ and plots the dynamic angle of repose. NP=2 runs on two MPI
# ranks (the drum is split along its axis).
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
# Unbuffered, so that an ERROR line is not lost when LIGGGHTS aborts.
run=(stdbuf -o0 "$exe" -in ../in.drum -echo none -log log.liggghts)
if [ "$np" -gt 1 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    export OMPI_MCA_mpi_yield_when_idle=1
    run=(mpirun -np "$np" "${run[@]}")
fi
echo "drum: 2600 spheres, 0.35 s fill and spin-up, 1.2 s at 3 rad/s (log: $out/log.liggghts)"
if ! "${run[@]}" > screen.txt 2>&1; then
    grep -E "ERROR|WARNING" screen.txt || tail -20 screen.txt
    exit 1
fi
/usr/bin/python3 "$here/angle.py" "$out"
echo "ParaView: $out/post/drum_*.vtk (wall) and $out/post/particles_*.vtk (spheres)"
echo "wall time: $(( $(date +%s) - start )) s"
