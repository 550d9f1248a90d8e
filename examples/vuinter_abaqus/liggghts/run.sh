#!/bin/bash
# The Abaqus VUINTER example interface (law bonded_interface) in LIGGGHTS:
#   bash examples/vuinter_abaqus/liggghts/run.sh
# Builds liggghts-rigidsurf in build/ (or $BUILD_DIR) when needed, runs the normal,
# shear, plastic and thermal decks in examples/vuinter_abaqus/liggghts/out/ and checks
# each against its closed form (PASS/FAIL with the numbers).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../lib.sh"
for case in normal shear plastic thermal; do
    NP=1 rs_run "$case" "../in.$case"
done
/usr/bin/python3 "$here/check.py" "$out"
echo "wall time: $(( $(date +%s) - start )) s"
