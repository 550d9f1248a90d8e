#!/bin/bash
# The Abaqus VUINTER example interface (law bonded_interface) in LIGGGHTS:
#   bash examples/vuinter_abaqus/liggghts/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, runs the normal,
# shear, plastic and thermal decks in examples/vuinter_abaqus/liggghts/out/ and checks
# each against its closed form (PASS/FAIL with the numbers).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
build=${BUILD_DIR:-$root/build}
exe=$build/coupling/liggghts-rigidsurf
start=$(date +%s)

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
fi
cmake --build "$build" -j"$(nproc)" --target liggghts-rigidsurf > /dev/null

out=$here/out
rm -rf "$out"
mkdir -p "$out/post"
cd "$out"
for case in normal shear plastic thermal; do
    if ! stdbuf -o0 "$exe" -in "../in.$case" -echo none -log "log_$case.liggghts" \
        > "screen_$case.txt" 2>&1; then
        grep -E "ERROR|WARNING" "screen_$case.txt" || tail -20 "screen_$case.txt"
        exit 1
    fi
done
/usr/bin/python3 "$here/check.py" "$out"
echo "wall time: $(( $(date +%s) - start )) s"
