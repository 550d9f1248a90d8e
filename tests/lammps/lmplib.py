"""Shared helpers for the LAMMPS integration tests of fix wall/rigid (lmp-rigidsurf).

Every test script takes the arguments of liglib.Session (tests/liggghts/liglib.py), with
--exe PATH/lmp-rigidsurf, and --lmp PATH/lmp (Debian's stock LAMMPS, the reference walls
fix wall/gran and wall/gran/region) where it compares with it. lmp-rigidsurf links the
same liblammps.so.0 as lmp and runs every stock deck as it does, so a difference between
the two runs of a pair comes from the wall alone.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "liggghts"))
import liglib as L  # noqa: E402,F401
from liglib import read_dump, read_table, rel_diff  # noqa: E402,F401
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from lammps_bodies import box_body  # noqa: E402,F401

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


# ---- LAMMPS's rounded polyhedra (atom_style body rounded/polyhedron) -----------------

BCOLS = ("id x y z vx vy vz angmomx angmomy angmomz fx fy fz tqx tqy tqz "
         "c_quat[1] c_quat[2] c_quat[3] c_quat[4]")


def body_header(data, dt, nmax=8, boundary="f f f", pre="", pair=True):
    """A deck head for LAMMPS's rounded polyhedra read from the data file data (SI units,
    nmax: body_nmax), with pair body/rounded/polyhedron at zero stiffness (fix
    wall/body/polyhedron needs it; one body alone), else pair none (bodies that do not
    touch each other), and compute quat for the dumps (BCOLS)."""
    pair = ("pair_style body/rounded/polyhedron 0 0 0 0 0.001\npair_coeff * * 0 0" if pair
            else "pair_style none")
    return f"""atom_style body rounded/polyhedron 1 {nmax}
atom_modify map array
boundary {boundary}
units si
{pre}read_data {data}
neighbor 0.002 bin
neigh_modify delay 0
{pair}
comm_modify vel yes
timestep {dt!r}
compute quat all property/atom quatw quati quatj quatk
"""


def body_nmax(bodies):
    """The nmax of atom_style body rounded/polyhedron 1 nmax that holds bodies: LAMMPS sizes
    a body's storage as 9 nmax + 2 doubles (3 a vertex, 2 an edge, 4 a face, each up to
    nmax), so a body of more edges or faces than vertices needs a larger nmax."""
    return max(max(len(b["V"]), -(-(3 * len(b["V"]) + 2 * len(b["E"]) + 4 * len(b["F"])) // 9))
               for b in bodies)


def rotate(v, axis, angle):
    """v turned by angle degrees about axis (Rodrigues)."""
    a = math.radians(angle)
    n = math.sqrt(sum(c * c for c in axis))
    k = [c / n for c in axis]
    c, s = math.cos(a), math.sin(a)
    d = sum(k[i] * v[i] for i in range(3))
    cr = (k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0])
    return tuple(v[i] * c + cr[i] * s + k[i] * d * (1 - c) for i in range(3))


def prism_body(n, radius, half_len):
    """A right prism of n sides inscribed in a circle of radius, its axis along y from
    -half_len to half_len: 2 n vertices, 3 n edges, n quadrilateral sides and its two
    n-gon ends as fans of triangles."""
    V = [(radius * math.cos(2 * math.pi * k / n), s * half_len,
          radius * math.sin(2 * math.pi * k / n)) for s in (-1, 1) for k in range(n)]
    E = [(k, (k + 1) % n) for k in range(n)] + [(n + k, n + (k + 1) % n) for k in range(n)] + \
        [(k, n + k) for k in range(n)]
    F = [(k, (k + 1) % n, n + (k + 1) % n, n + k) for k in range(n)]
    F += [(0, k + 1, k) for k in range(1, n - 1)] + [(n, n + k, n + k + 1) for k in range(1, n - 1)]
    return V, E, F


def body_data(bodies, box, ntypes=2):
    """A LAMMPS data file of rounded polyhedra: bodies is a list of dicts with V, E, F
    (vertices as displacements from the centre of mass, in the world frame), r (rounding
    radius), m (mass), I (6 moments of inertia ixx iyy izz ixy ixz iyz about the centre,
    world frame), x (centre) and optionally v and L (angular momentum)."""
    s = "LAMMPS data file: rounded polyhedra\n\n%d atoms\n%d bodies\n%d atom types\n" % (
        len(bodies), len(bodies), ntypes)
    s += "%r %r xlo xhi\n%r %r ylo yhi\n%r %r zlo zhi\n\nAtoms\n\n" % tuple(box)
    for k, b in enumerate(bodies):
        s += "%d 1 1 %.17g %.17g %.17g %.17g\n" % ((k + 1, b["m"]) + tuple(b["x"]))
    s += "\nVelocities\n\n"
    for k, b in enumerate(bodies):
        s += "%d %s\n" % (k + 1, " ".join("%.17g" % c for c in
                                          tuple(b.get("v", (0, 0, 0))) + tuple(b.get("L", (0, 0, 0)))))
    s += "\nBodies\n\n"
    for k, b in enumerate(bodies):
        vals = list(b["I"]) + [c for v in b["V"] for c in v] + \
            [c for e in b["E"] for c in e] + \
            [c for f in b["F"] for c in (list(f) + [-1] * (4 - len(f)))] + [2 * b["r"]]
        s += "%d 3 %d\n%d %d %d\n" % (k + 1, len(vals), len(b["V"]), len(b["E"]), len(b["F"]))
        line = ""
        for v in vals:  # LAMMPS reads at most 32 lines of 255 characters a body
            w = "%d" % v if v == int(v) and abs(v) < 1000 else "%.17g" % v
            if len(line) + len(w) + 1 > 250:
                s += line + "\n"
                line = ""
            line += (" " if line else "") + w
        s += line + "\n"
    return s


def check_ranks_sums(s, t1, t2, cols):
    """The wall's sums of a 2-rank run (table rows t2) against the 1-rank run's (t1) to
    1e-12 relative, each column (index, name) of cols, below 1e-3 of its largest value
    counting as zero."""
    for col, what in cols:
        floor = 1e-3 * max(abs(r[col]) for r in t1)
        d = max(rel_diff(a[col], b[col], floor) for a, b in zip(t1, t2))
        s.ck.check("the wall's %s, 2 ranks = 1 rank to 1e-12" % what, d <= 1e-12,
                   "worst rel %.3g" % d)


def check_restart(s, f1, fr, first):
    """A restarted run's frames (fr) against the uninterrupted run's (f1) from step first
    on: the same steps, and every dumped value to 1e-12 of its column's largest."""
    cont = [(st, f) for st, f in f1 if st >= first]
    if not s.ck.check("the restarted run's frames line up with the uninterrupted run's",
                      [st for st, _ in cont] == [st for st, _ in fr],
                      "%d vs %d" % (len(cont), len(fr))):
        return
    worst = (0.0, None)
    for (st, a), (_, b) in zip(cont, fr):
        for i in a:
            for c in a[i]:
                scale = max(abs(f[j][c]) for _, f in cont for j in f) or 1.0
                d = abs(a[i][c] - b[i][c]) / scale
                if d > worst[0]:
                    worst = (d, (st, i, c))
    s.ck.check("restart (1 rank, then 2 ranks) = the uninterrupted run to 1e-12",
               worst[0] <= 1e-12, "worst %.3g (of the column's largest) at %s" % worst)


def x_crossings(frames):
    """How many times particles cross the plane x = 0 between consecutive frames (the
    boundary between the ranks of a 2-rank run)."""
    n = 0
    for (_, a), (_, b) in zip(frames, frames[1:]):
        n += sum(1 for i in a if a[i]["x"] * b[i]["x"] < 0)
    return n


def run_ranks_restart(s, full, first, second):
    """The decks of a ranks-and-restart test: full (its outputs named by the word 'full')
    on 1 rank as np1 and on 2 ranks as np2, then first on 1 rank and second, which restarts
    from it, on 2 ranks. Returns the dumps of np1 and np2."""
    s.run("np1", full.replace("full", "np1"))
    s.run("np2", full.replace("full", "np2"), np=2)
    s.run("first", first)
    s.run("second", second, np=2)
    return read_dump(s.path("np1.dump")), read_dump(s.path("np2.dump"))
