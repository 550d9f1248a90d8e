"""Shared helpers for the LAMMPS integration tests of fix wall/rigid (lmp-rigidsurf).

Every test script takes the arguments of liglib.Session (tests/liggghts/liglib.py), with
--exe PATH/lmp-rigidsurf, and --lmp PATH/lmp (Debian's stock LAMMPS, the reference walls
fix wall/gran and wall/gran/region) where it compares with it. lmp-rigidsurf links the
same liblammps.so.0 as lmp and runs every stock deck as it does, so a difference between
the two runs of a pair comes from the wall alone.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "liggghts"))
import liglib as L  # noqa: E402,F401
from liglib import read_dump, read_table, rel_diff  # noqa: E402,F401

STOCK = ("--lmp", "Debian's stock lmp")
COLS = "id x y z vx vy vz omegax omegay omegaz fx fy fz tqx tqy tqz"


def header(box, dt, ntypes=2, boundary="f f f", pair="pair_style none", pre=""):
    """A LAMMPS granular deck head: SI units, atom_style sphere, no pair forces unless
    pair says (spheres that touch only the wall keep each one's path its own). pre goes
    before create_box (processors, ...)."""
    return f"""atom_style sphere
atom_modify map array
boundary {boundary}
newton off
comm_modify vel yes
units si
{pre}region box block {box[0]} {box[1]} {box[2]} {box[3]} {box[4]} {box[5]} units box
create_box {ntypes} box
neighbor 0.002 bin
neigh_modify delay 0
{pair}
timestep {dt!r}
"""


def sphere(atom_id, x, r, rho, v=(0, 0, 0), omega=(0, 0, 0), atype=1):
    """create_atoms + set lines for one sphere (ids are given in creation order)."""
    return ("create_atoms %d single %.17g %.17g %.17g units box\n"
            "set atom %d diameter %.17g density %.17g vx %.17g vy %.17g vz %.17g "
            "omega %.17g %.17g %.17g\n"
            % (atype, x[0], x[1], x[2], atom_id, 2 * r, rho, v[0], v[1], v[2],
               omega[0], omega[1], omega[2]))


def dump_lines(dump_id, every, fname, cols=COLS, group="all"):
    """A 'dump custom' with full double precision, sorted by id."""
    return ("dump %s %s custom %d %s %s\n"
            "dump_modify %s format float %%.17g sort id\n"
            % (dump_id, group, every, fname, cols, dump_id))


def scales(length, speed=1.0, force=1.0, torque=1.0):
    """compare_frames scales for COLS: values below them count as zero."""
    out = {}
    for c in COLS.split()[1:]:
        out[c] = {"x": length, "y": length, "z": length, "v": speed, "o": speed / length,
                  "f": force, "t": torque}[c[0]]
    return out


def exact_frames(fa, fb):
    """The first (step, id, column) where two dumps differ in any bit, None when they
    agree; 'frames' when their frames or atoms differ."""
    if len(fa) != len(fb):
        return "frames"
    for (sa, aa), (sb, ab) in zip(fa, fb):
        if sa != sb or set(aa) != set(ab):
            return "frames"
        for i in aa:
            for c in aa[i]:
                if aa[i][c] != ab[i][c]:
                    return (sa, i, c, aa[i][c], ab[i][c])
    return None


ECOLS = ("id x y z vx vy vz angmomx angmomy angmomz fx fy fz tqx tqy tqz "
         "c_quat[1] c_quat[2] c_quat[3] c_quat[4]")


def ellipsoid_header(box, dt, ntypes=2, boundary="f f f", pre=""):
    """A deck head for LAMMPS's ellipsoids (atom_style ellipsoid: half-axes, quaternion,
    angular momentum, torque), SI units, no pair forces; compute quat gives the
    quaternions to dumps (ECOLS)."""
    return header(box, dt, ntypes, boundary, pre=pre).replace(
        "atom_style sphere", "atom_style ellipsoid") + \
        "compute quat all property/atom quatw quati quatj quatk\n"


def ellipsoid(atom_id, x, half, rho, axis=(0, 0, 1), angle=0.0, v=(0, 0, 0),
              angmom=(0, 0, 0), atype=1, hybrid=False):
    """create_atoms + set lines for one ellipsoid of half-axes half (LAMMPS's set shape
    takes diameters), turned by angle degrees about axis. hybrid: atom_style hybrid
    sphere ellipsoid, where the ellipsoid's sphere diameter is set to 0 first (set density
    takes a radius > 0 before a shape)."""
    return ("create_atoms %d single %.17g %.17g %.17g units box\n"
            "set atom %d shape %.17g %.17g %.17g\n%s"
            "set atom %d density %.17g\n"
            "set atom %d quat %.17g %.17g %.17g %.17g\n"
            "set atom %d vx %.17g vy %.17g vz %.17g angmom %.17g %.17g %.17g\n"
            % (atype, x[0], x[1], x[2], atom_id, 2 * half[0], 2 * half[1], 2 * half[2],
               "set atom %d diameter 0\n" % atom_id if hybrid else "",
               atom_id, rho, atom_id, axis[0], axis[1], axis[2], angle,
               atom_id, v[0], v[1], v[2], angmom[0], angmom[1], angmom[2]))


def check_ranks_sums(s, t1, t2, cols):
    """The wall's sums of a 2-rank run (table rows t2) against the 1-rank run's (t1) to
    1e-12 relative, each column (index, name) of cols, below 1e-3 of its largest value
    counting as zero."""
    for col, what in cols:
        floor = 1e-3 * max(abs(r[col]) for r in t1)
        d = max(rel_diff(a[col], b[col], floor) for a, b in zip(t1, t2))
        s.ck.check("the wall's %s, 2 ranks = 1 rank to 1e-12" % what, d <= 1e-12,
                   "worst rel %.3g" % d)
