# Shared by the examples' run.sh scripts: `source` it after `set -euo pipefail` and
# `here=<the example's folder>` (and `engine=lammps` for a LAMMPS example; LIGGGHTS's
# otherwise). It sets root, build ($BUILD_DIR, default build/), exe (liggghts-rigidsurf or
# lmp-rigidsurf) and start, builds the executable when needed, and empties the example's
# out/ (with out/post/) and enters it.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
engine=${engine:-liggghts}
target=liggghts-rigidsurf
[ "$engine" = lammps ] && target=lmp-rigidsurf
exe=$build/coupling/$target
start=$(date +%s)

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
fi
cmake --build "$build" -j"$(nproc)" --target "$target" > /dev/null

out=$here/out
rm -rf "$out"
mkdir -p "$out/post"
cd "$out"

# rs_run TAG INPUT [ARG...]: runs the executable on INPUT with log_TAG.<engine> and
# screen_TAG.txt, on $NP ranks (default 1). Unbuffered, so that an ERROR line is not lost
# when LIGGGHTS aborts; on failure prints the error lines and stops the script.
rs_run() {
    local tag=$1 input=$2
    shift 2
    local cmd=(stdbuf -o0 "$exe" -in "$input" -echo none -log "log_$tag.$engine" "$@")
    if [ "${NP:-1}" -gt 1 ]; then
        export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
        export OMPI_MCA_mpi_yield_when_idle=1
        cmd=(mpirun -np "$NP" "${cmd[@]}")
    fi
    if ! "${cmd[@]}" > "screen_$tag.txt" 2>&1; then
        grep -E "ERROR|WARNING" "screen_$tag.txt" || tail -20 "screen_$tag.txt"
        exit 1
    fi
}
