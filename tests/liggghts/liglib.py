"""Shared helpers for the LIGGGHTS integration tests of fix wall/rigid.

Every test script takes the same arguments:
    test_x.py --exe PATH/liggghts-rigidsurf [--keep]
The reference walls (fix wall/gran primitive/mesh) run in the same executable: it is a
drop-in for Debian's liggghts and links the same libliggghts, so a difference between
the two runs of a pair comes from the wall alone.
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from liggghts_out import read_dump, read_table  # noqa: E402

MPI_ENV = {
    "OMPI_ALLOW_RUN_AS_ROOT": "1",
    "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
    "OMPI_MCA_rmaps_base_oversubscribe": "1",
}


class Checker:
    """Counts named checks and ends the script with 'N passed, M failed'."""

    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, name, cond, detail="", why=""):
        """detail (measured values) is printed always, why only on failure."""
        if cond:
            self.passed += 1
            print("ok   " + name + (" (" + detail + ")" if detail else ""))
        else:
            self.failed += 1
            msg = "; ".join(m for m in (detail, why) if m)
            print("FAIL " + name + (": " + msg if msg else ""))
        sys.stdout.flush()
        return cond

    def finish(self):
        print("%d passed, %d failed" % (self.passed, self.failed))
        sys.exit(1 if self.failed or not self.passed else 0)


class Session:
    """A scratch directory and the executable under test (extra: more options, (flag, help)
    pairs, each an executable's path, in self.args)."""

    def __init__(self, description, extra=()):
        ap = argparse.ArgumentParser(description=description)
        ap.add_argument("--exe", required=True, help="liggghts-rigidsurf")
        ap.add_argument("--keep", action="store_true", help="keep the scratch directory")
        ap.add_argument("--mpirun", default="mpirun")
        for flag, what in extra:
            ap.add_argument(flag, required=True, help=what)
        self.args = ap.parse_args()
        self.exe = os.path.abspath(self.args.exe)
        self.dir = tempfile.mkdtemp(prefix="rs_lig_")
        self.ck = Checker()

    def path(self, name):
        return os.path.join(self.dir, name)

    def write(self, name, text):
        with open(self.path(name), "w") as f:
            f.write(text)
        return self.path(name)

    def run(self, name, deck, np=1, timeout=300, prefix=None, expect_ok=True, exe=None):
        """Writes deck to NAME.in and runs it in the scratch directory with exe (default:
        the executable under test).

        Returns (returncode, stdout+stderr). With expect_ok a failed run is reported
        with the tail of its output and raises RunError."""
        inp = self.write(name + ".in", deck)
        # Unbuffered stdout: error->one ends with MPI_Abort, which drops buffered output
        # (the ERROR line included).
        # prefix (valgrind, ...) wraps the executable itself.
        cmd = ["stdbuf", "-o0"] + list(prefix or []) + [
            exe or self.exe, "-in", inp, "-log", name + ".log", "-echo", "none"]
        if np > 1:
            cmd = [self.args.mpirun, "-np", str(np)] + cmd
        env = dict(os.environ)
        env.update(MPI_ENV)
        try:
            p = subprocess.run(cmd, cwd=self.dir, capture_output=True, text=True, errors="replace",
                               timeout=timeout, env=env)
        except subprocess.TimeoutExpired:
            if expect_ok:
                self.ck.check("run " + name, False, "timed out after %gs" % timeout)
                raise RunError(name)
            return None, "TIMEOUT"
        out = p.stdout + p.stderr
        if expect_ok and p.returncode != 0:
            tail = "\n".join(out.splitlines()[-15:])
            self.ck.check("run " + name, False, "exit %d\n%s" % (p.returncode, tail))
            raise RunError(name)
        return p.returncode, out

    def done(self):
        if self.args.keep or self.ck.failed:
            print("scratch directory kept: " + self.dir)
        else:
            shutil.rmtree(self.dir, ignore_errors=True)
        self.ck.finish()


class RunError(Exception):
    pass


def main_guard(session, body):
    """Runs body(session); a deck that failed to run counts as a failure, not a crash."""
    try:
        body(session)
    except RunError:
        pass
    except Exception:  # a check script bug or unreadable output is a failure too
        import traceback
        traceback.print_exc()
        session.ck.check("test script ran to the end", False)
    session.done()


DUMP_COLS = "id x y z vx vy vz omegax omegay omegaz"


def dump_lines(dump_id, every, fname, cols=DUMP_COLS, group="all"):
    """A 'dump custom' with full double precision, sorted by id."""
    ncol = len(cols.split())
    fmt = " ".join(["%d"] + ["%.17g"] * (ncol - 1))
    return ("dump %s %s custom %d %s %s\n"
            "dump_modify %s format \"%s\" sort id\n" % (dump_id, group, every, fname, cols,
                                                         dump_id, fmt))


def header(box, dt, young=(5.0e7, 2.0e8), poisson=(0.3, 0.25), e=0.7, mu=0.5,
           ntypes=2, boundary="f f f", extra_props="", newton="off", pre=""):
    """A granular deck head: SI units, particle type 1, wall type 2, Hertz pair style.

    Wall and particle materials differ on purpose so a mix-up of the two types in the
    property matrices shows. pre goes before create_box (processors, ...)."""
    def per_type(v):
        v = list(v) if isinstance(v, (list, tuple)) else [v] * ntypes
        return " ".join("%.17g" % x for x in v[:ntypes])

    def pair(v):
        return "%d %s" % (ntypes, " ".join(["%.17g" % v] * (ntypes * ntypes)))

    return f"""atom_style granular
atom_modify map array
boundary {boundary}
newton {newton}
communicate single vel yes
units si
{pre}region box block {box[0]} {box[1]} {box[2]} {box[3]} {box[4]} {box[5]} units box
create_box {ntypes} box
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype {per_type(young)}
fix m2 all property/global poissonsRatio peratomtype {per_type(poisson)}
fix m3 all property/global coefficientRestitution peratomtypepair {pair(e)}
fix m4 all property/global coefficientFriction peratomtypepair {pair(mu)}
{extra_props}pair_style gran model hertz tangential history
pair_coeff * *
timestep {dt!r}
"""


def sphere(atom_id, x, r, rho, v=(0, 0, 0), omega=(0, 0, 0), atype=1):
    """create_atoms + set lines for one sphere (ids are given in creation order)."""
    return ("create_atoms %d single %.17g %.17g %.17g units box\n"
            "set atom %d diameter %.17g density %.17g vx %.17g vy %.17g vz %.17g "
            "omegax %.17g omegay %.17g omegaz %.17g\n"
            % (atype, x[0], x[1], x[2], atom_id, 2 * r, rho, v[0], v[1], v[2],
               omega[0], omega[1], omega[2]))


# Surface files ---------------------------------------------------------------------

def plane_z(z0=0.0, half=1.0, name="floor"):
    """A plane z = z0 with n = +z: CYLINDER with a = (0,0,z0), local x = +x, generator
    along -y, so local y = generator x local x = +z; a LINE travelling +x has n = +y_local."""
    return (f"*SURFACE, TYPE=CYLINDER, NAME={name}\n"
            f"0, 0, {z0!r}, 1, 0, {z0!r}\n0, -1, {z0!r}\n"
            f"START, {-half!r}, 0\nLINE, {half!r}, 0\n")


def drum(radius, zlo, zhi, name="mantle", caps=False):
    """A drum about the z axis: REVOLUTION, profile (r, z) travelling +z at r = radius so
    n = (-t_z, t_r) = (-1, 0) points inward. With caps the profile closes over the two
    end discs (bottom cap travels +r at z = zlo: n = +z; top cap -r at z = zhi: n = -z)."""
    if caps:
        prof = (f"START, 0, {zlo!r}\nLINE, {radius!r}, {zlo!r}\n"
                f"LINE, {radius!r}, {zhi!r}\nLINE, 0, {zhi!r}\n")
    else:
        prof = f"START, {radius!r}, {zlo!r}\nLINE, {radius!r}, {zhi!r}\n"
    return f"*SURFACE, TYPE=REVOLUTION, NAME={name}\n0, 0, 0, 0, 0, 1\n" + prof


def disc_z(radius, z0=0.0, name="disc"):
    """An end disc z = z0 facing +z: REVOLUTION, profile travelling +r at z = z0, so
    n = (-t_z, t_r) = (0, 1) = +z."""
    return (f"*SURFACE, TYPE=REVOLUTION, NAME={name}\n0, 0, 0, 0, 0, 1\n"
            f"START, 0, {z0!r}\nLINE, {radius!r}, {z0!r}\n")


def stl_text(tris, name="part"):
    """An ASCII STL of triangles ((x, y, z) x 3 each), wound as given."""
    out = ["solid %s" % name]
    for t in tris:
        out.append(" facet normal 0 0 0\n  outer loop")
        out += ["   vertex %.17g %.17g %.17g" % tuple(p) for p in t]
        out.append("  endloop\n endfacet")
    out.append("endsolid %s" % name)
    return "\n".join(out) + "\n"


def cube_triangles(h, outward=True):
    """The cube [-h, h]^3 as 12 triangles whose right-hand normals point outward (or
    inward)."""
    tris = []
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for sgn in (-1.0, 1.0):
            quad = []
            for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = sgn * h, su * h, sv * h
                quad.append(tuple(p))
            a, b, c, d = quad
            for t in ((a, b, c), (a, c, d)):
                e1 = [t[1][k] - t[0][k] for k in range(3)]
                e2 = [t[2][k] - t[0][k] for k in range(3)]
                n_axis = e1[u] * e2[v] - e1[v] * e2[u]
                if n_axis * (sgn if outward else -sgn) < 0:
                    t = (t[0], t[2], t[1])
                tris.append(t)
    return tris


def rel_diff(a, b, scale):
    """|a - b| relative to max(|a|, |b|, scale): scale keeps values near zero honest."""
    if a == b:
        return 0.0
    return abs(a - b) / max(abs(a), abs(b), scale)


def compare_frames(fa, fb, fields_scales):
    """Largest relative difference per field over all common frames and atoms, and the
    (step, id) where it occurs. Frames must match one to one."""
    worst = {}
    if len(fa) != len(fb):
        return None
    for (sa, aa), (sb, ab) in zip(fa, fb):
        if sa != sb or set(aa) != set(ab):
            return None
        for i in aa:
            for fld, scale in fields_scales.items():
                d = rel_diff(aa[i][fld], ab[i][fld], scale)
                if d > worst.get(fld, (-1.0,))[0]:
                    worst[fld] = (d, sa, i)
    return worst


def sphere_wall_deck(wall, atoms, steps, gravity, integrator, box, tag, dt,
                     extra_props="", head=None):
    """One deck of a wall test: the header (head: more arguments of header()), the atoms,
    gravity -z if asked, the wall line(s), the integrator and a dump every 5 steps to
    TAG.dump."""
    d = header(box, dt, extra_props=extra_props, **(head or {}))
    d += atoms
    if gravity:
        d += "fix grav all gravity 9.81 vector 0 0 -1\n"
    d += wall + "\n"
    d += "fix integr all %s\n" % integrator
    d += dump_lines("d", 5, tag + ".dump")
    d += "run %d\n" % steps
    return d


def compare_walls(s, name, ours, ref, atoms, steps, gravity, integrator, box, touched,
                  dt, scales, tol, extra_props="", ref_tag="ref", head=None):
    """Runs the same deck with our wall and with LIGGGHTS's and checks that the reference
    touched (touched(frames)) and that every dumped field agrees to tol relative."""
    for wall, tag in ((ours, name + "_rigid"), (ref, name + "_" + ref_tag)):
        s.run(tag, sphere_wall_deck(wall, atoms, steps, gravity, integrator, box, tag, dt,
                                    extra_props, head))
    fa = read_dump(s.path(name + "_rigid.dump"))
    fb = read_dump(s.path(name + "_" + ref_tag + ".dump"))
    s.ck.check(name + ": the reference run made contact", touched(fb),
               why="LIGGGHTS's wall never touched the sphere: the deck tests nothing")
    check_trajectories(s, name, fa, fb, scales, tol)


def check_trajectories(s, name, fa, fb, scales, tol, ref="LIGGGHTS's"):
    """Checks that frames fa (ours) and fb (the reference's, ref) hold the same steps and
    atoms and that every field agrees to tol relative (scales as compare_frames). Returns
    the worst relative difference, or None when the frames differ."""
    worst = compare_frames(fa, fb, scales)
    if not s.ck.check(name + ": same frames and atoms", worst is not None,
                      "%d vs %d frames" % (len(fa), len(fb))):
        return None
    fld, (d, step, i) = max(worst.items(), key=lambda kv: kv[1][0])
    s.ck.check(name + ": trajectory equals %s to %g" % (ref, tol), d <= tol,
               "worst %s rel %.3g at step %d atom %d" % (fld, d, step, i))
    return d


def error_lines(out):
    return [l for l in out.splitlines() if l.startswith("ERROR")]


def one_sphere_deck(fix_line):
    """A deck with one sphere above plane.inp and fix_line, 10 steps: valid unless the
    fix line is not."""
    d = header((-0.1, 0.1, -0.1, 0.1, -0.05, 0.2), 1e-5)
    d += sphere(1, (0, 0, 0.02), 0.005, 2500.0)
    d += fix_line + "\n"
    d += "fix integr all nve/sphere\nrun 10\n"
    return d


def check_rejected(ck, name, line, want, rc, out):
    """The run of a bad line ended cleanly (exit 1: no signal, no abort, no uncaught
    exception) with one error message that holds every string of want. An error found
    on one rank (error->one) may print its message twice; it is one message."""
    errs = sorted(set(e.split(": ", 1)[-1] for e in error_lines(out)))
    crash = rc is None or rc < 0 or rc in (134, 136, 139) or "Segmentation" in out \
        or "MPI_ABORT" in out or "terminate called" in out or "signal" in out.lower()
    text = errs[0] if errs else ""
    missing = [w for w in want if w not in text]
    return ck.check(name, rc == 1 and not crash and len(errs) == 1 and not missing, text,
                    why="exit %s, %d error messages, missing %s\n  line: %s\n  tail: %s"
                    % (rc, len(errs), missing, line, " | ".join(out.splitlines()[-4:])))


def isfinite_all(vals):
    return all(math.isfinite(v) for v in vals)


# Stock tutorials run whole ---------------------------------------------------------------

TUTORIALS = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
STOCK_LIGGGHTS = "/usr/bin/liggghts"
# The bed at the end of a deck: count, centre of mass, kinetic energy, mass.
BED = ('variable cx equal xcm(all,x)\nvariable cy equal xcm(all,y)\n'
       'variable cz equal xcm(all,z)\nvariable n equal count(all)\nvariable m equal mass(all)\n'
       'variable ke equal ke\nprint "BED ${n} ${cx} ${cy} ${cz} ${ke} ${m}"\n')
# Every 1000 steps: count, kinetic energy and mean x velocity (`TUT` lines).
MONITOR = ('variable tn equal count(all)\nvariable tke equal ke\nvariable tvx equal vcm(all,x)\n'
           'fix tprint all print 1000 "TUT $(step) ${tn} ${tke} ${tvx}"\n')


def no_dumps(text):
    """A tutorial without its dumps, with MONITOR after create_box (or read_data)."""
    out = []
    for l in text.splitlines():
        if not l.strip().startswith("dump"):
            out.append(l)
        if l.strip().startswith(("create_box", "read_data")):
            out.append(MONITOR)
    return "\n".join(out) + "\n"


def run_tutorial(s, name, tag, exe, src_dir, deck, timeout=1200):
    """Runs deck as in.test in a copy of the tutorial's folder. Returns (output, the
    last BED values or None, {step: [count, KE, mean vx]} of the TUT lines, CPU s)."""
    import resource
    import time
    d = os.path.join(s.dir, name + "_" + tag)
    shutil.copytree(src_dir, d)
    with open(os.path.join(d, "in.test"), "w") as f:
        f.write(deck)
    t0, c0 = time.time(), resource.getrusage(resource.RUSAGE_CHILDREN)
    env = dict(os.environ)
    env.update(MPI_ENV)
    p = subprocess.run([exe, "-in", "in.test", "-log", "log." + tag], cwd=d, env=env,
                       capture_output=True, text=True, errors="replace", timeout=timeout)
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = c1.ru_utime + c1.ru_stime - c0.ru_utime - c0.ru_stime
    out = p.stdout + p.stderr
    s.ck.check("%s %s: the run ends without error" % (name, tag), p.returncode == 0,
               "exit %d, %.0f s, CPU %.0f s" % (p.returncode, time.time() - t0, cpu),
               "\n".join(out.splitlines()[-8:]))
    bed = [l.split()[1:] for l in out.splitlines() if l.startswith("BED ")]
    tut = {}
    for l in out.splitlines():
        t = l.split()
        if len(t) == 5 and t[0] == "TUT":
            tut[int(t[1])] = [float(v) for v in t[2:]]
    return out, ([float(v) for v in bed[-1]] if bed else None), tut, cpu


def window(tut, lo, hi, col):
    """The values of column col of the TUT lines of steps lo..hi, and their mean."""
    vals = [v[col] for st, v in tut.items() if lo <= st <= hi]
    return vals, (sum(vals) / len(vals) if vals else float("nan"))
