#!/usr/bin/python3
"""The particles of a LAMMPS dump as legacy VTK files for ParaView (Debian's LAMMPS has no
dump vtk): one polydata file per frame, OUTDIR/particles_STEP.vtk, a vertex per sphere
with its radius, type, velocity and angular velocity as point data (a Glyph filter scaled
by radius draws the spheres).

Usage: particles_vtk.py DUMP OUTDIR  (the dump's columns: id type radius x y z vx vy vz
omegax omegay omegaz)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from liggghts_out import read_dump  # noqa: E402


def write(path, atoms):
    rows = list(atoms.values())
    with open(path, "w") as f:
        f.write("# vtk DataFile Version 3.0\nparticles\nASCII\nDATASET POLYDATA\n")
        f.write("POINTS %d double\n" % len(rows))
        f.writelines("%.9g %.9g %.9g\n" % (a["x"], a["y"], a["z"]) for a in rows)
        f.write("VERTICES %d %d\n" % (len(rows), 2 * len(rows)))
        f.writelines("1 %d\n" % k for k in range(len(rows)))
        f.write("POINT_DATA %d\n" % len(rows))
        for name in ("radius", "type"):
            f.write("SCALARS %s double 1\nLOOKUP_TABLE default\n" % name)
            f.writelines("%.9g\n" % a[name] for a in rows)
        for name, c in (("velocity", "v"), ("omega", "omega")):
            f.write("VECTORS %s double\n" % name)
            f.writelines("%.9g %.9g %.9g\n" % (a[c + "x"], a[c + "y"], a[c + "z"])
                         for a in rows)


def main():
    dump, out = sys.argv[1], sys.argv[2]
    frames = read_dump(dump)
    for step, atoms in frames:
        write(os.path.join(out, "particles_%d.vtk" % step), atoms)
    print("%d VTK files of the particles in %s" % (len(frames), out))


if __name__ == "__main__":
    main()
