#!/bin/bash
# Rotating drum in LAMMPS to steady avalanching: bash examples/lammps_drum/run.sh
# Builds lmp-rigidsurf in build/ (or $BUILD_DIR) when needed, runs in.drum in
# examples/lammps_drum/out/, plots the dynamic angle of repose (examples/drum/angle.py,
# the LIGGGHTS drum's) and writes the particles' VTK files. NP=2 runs on two MPI ranks.
# STOCK=1 also runs in.drum_region, the same drum made of LAMMPS's region walls (a
# cylinder and two planes, without fillets), in stock lmp, in out/stock/.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
engine=lammps
source "$here/../lib.sh"
echo "lammps_drum: 2364 spheres, 0.35 s settling and spin-up, 1.2 s at 3 rad/s" \
     "(log: $out/log_drum.lammps)"
rs_run drum ../in.drum
/usr/bin/python3 "$here/particles_vtk.py" post/vis.dump post
/usr/bin/python3 "$here/../drum/angle.py" "$out"
echo "ParaView: $out/post/drum_*.vtk (wall) and $out/post/particles_*.vtk (spheres)"
if [ "${STOCK:-0}" = 1 ]; then
    echo "the same drum of LAMMPS's region walls, in stock lmp (out/stock/)"
    mkdir -p stock/post
    (cd stock && lmp -in ../../in.drum_region -echo none -log log_drum_region.lammps \
        > screen_drum_region.txt)
    /usr/bin/python3 "$here/../drum/angle.py" "$out/stock" || true
fi
echo "wall time: $(( $(date +%s) - start )) s"
