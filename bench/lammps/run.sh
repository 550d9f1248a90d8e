#!/usr/bin/env bash
# LAMMPS-side benchmark of fix wall/rigid: its cost per particle-step against stock
# LAMMPS's fix wall/gran/region on a cylinder region (and fix wall/gran zcylinder), on the
# same deck, side by side in one run (bench_lammps.py says what it runs).
#
#   bench/lammps/run.sh [--quick] [--n N] [--reps K]
#
# The executable is $LMP_RIGIDSURF, else build/coupling/lmp-rigidsurf. It runs the stock
# walls too: lmp-rigidsurf is Debian's lmp with wall/rigid added. The report goes to stdout
# and to bench/out/lammps_last_run.txt (ignored by git). Run it on an idle machine: the
# ratios are measured side by side, but a loaded host widens their spread.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="${LMP_RIGIDSURF:-$root/build/coupling/lmp-rigidsurf}"
if [[ ! -x "$exe" ]]; then
  echo "run.sh: lmp-rigidsurf not found; build it or set LMP_RIGIDSURF" >&2
  exit 2
fi
mkdir -p "$root/bench/out"
echo "# load average before: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"
/usr/bin/python3 "$here/bench_lammps.py" --exe "$exe" \
  --out "$root/bench/out/lammps_last_run.txt" "$@"
echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
