#!/usr/bin/env bash
# LIGGGHTS-side benchmarks of fix wall/rigid: wall cost against LIGGGHTS's primitive
# and mesh cylinders, scaling in N, and 1 -> 2 rank strong scaling, all in one run.
#
#   bench/liggghts/run.sh [--quick] [--max-n N] [--reps K] [--sections 1,1b,1c,1d,1e,1f,1g,2,3]
#
# The executable is $LIGGGHTS_RIGIDSURF, else build/coupling/liggghts-rigidsurf, else
# build-itest/coupling/liggghts-rigidsurf. The report goes to stdout and to
# bench/out/liggghts_last_run.txt (ignored by git). Run it on an idle machine: the ratios are
# measured side by side, but the 2-rank figure needs both cores free.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="${LIGGGHTS_RIGIDSURF:-}"
if [[ -z "$exe" ]]; then
  for cand in "$root/build/coupling/liggghts-rigidsurf" "$root/build-itest/coupling/liggghts-rigidsurf"; do
    if [[ -x "$cand" ]]; then exe="$cand"; break; fi
  done
fi
if [[ -z "$exe" || ! -x "$exe" ]]; then
  echo "run.sh: liggghts-rigidsurf not found; build it or set LIGGGHTS_RIGIDSURF" >&2
  exit 2
fi
mkdir -p "$root/bench/out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
echo "# load average before: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"
walls="$(dirname "$(dirname "$exe")")/bench/bench_walls_client"
/usr/bin/python3 "$here/bench_walls.py" --exe "$exe" --walls "$walls" \
  --out "$root/bench/out/liggghts_last_run.txt" "$@"
echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
