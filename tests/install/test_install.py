#!/usr/bin/python3
"""The installed package: `cmake --install` into a temporary prefix, then used from
outside the tree as a user would.

1. The install holds the public headers, the Fortran includes under their lower- and
   upper-case names, both libraries, the three programs (and lmp-rigidsurf and the LAMMPS
   plugin wallrigidplugin.so when built), the CMake package, rigidsurf.pc, the docs and
   the examples; the programs and the plugin find librigidsurf_abaqus in the prefix
   through their run path (no LD_LIBRARY_PATH anywhere in this test).
2. A C program built against the install, once through find_package(rigidsurf VERSION
   EXACT CONFIG) and once through pkg-config (with and without --static), reads a
   surface file and checks the closest point, normal and signed distance of a point on
   a plane and on a drum's mantle against their closed forms (its exit status).
3. A fixed-form VUINTER (INCLUDE 'VABA_PARAM.INC', linear penalty stress = k h) built
   with the installed rigidsurf-build-law, from the installed Fortran includes, holds a
   sphere on a plane in the installed liggghts-rigidsurf: the wall force is -m g and the
   sphere stays at its equilibrium overlap m g / k, to 1 %.

4. The coupling example (examples/coupling: drop.c and its CMakeLists.txt), as installed,
   is the program docs/coupling.md shows, and builds out of tree through
   find_package(rigidsurf): its three spheres, dropped on a floor built from arrays with
   law hertz, come to rest at Hertz's static overlap delta = (3 m g / (4 E* sqrt(R)))^(2/3)
   to 1e-6 of it (an equilibrium the law holds exactly once the bounces have died out),
   the one dropped straight stays still, and the two launched sideways at 0.05 m/s roll
   on at 5/7 of it (m rho^2 / (I + m rho^2), rho = R - delta/2) to 0.5 % (the bounces
   before they roll move them a little off it).

5. The walls example (examples/coupling/walls.c), built the same way, makes a rotating
   drum (a REVOLUTION) and a baffle (a MESH) from the words of the fix wall/rigid lines of
   a deck, and reads the particles of the deck's dump (moved by fix move: their states at
   each step are those the fix saw): every particle's force from each wall, at the setup
   call and every step, equals the force the fix stored (store_force), bit for bit, and
   contacts came, slid on the turning drum and pressed on the baffle.

`cmake --install` writes install_manifest.txt into the build directory; the test puts
back what was there before. Everything else lives in a temporary directory, removed at
the end (kept with --keep).
"""
import argparse
import math
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

SURFACES = """\
** The plane z = 0 facing +z: a CYLINDER whose generator is -y, so that a profile
** travelling along +x (local x) has its normal along local y = (-y) x (+x) = +z.
*SURFACE, TYPE=CYLINDER, NAME=floor
0, 0, 0, 1, 0, 0
0, -1, 0
START, -1, 0
LINE, 1, 0
** A drum's mantle of radius 0.15 about the z axis. The profile runs along +z in (r, z),
** so its normal, to the left of travel, is -e_r: particles live inside.
*SURFACE, TYPE=REVOLUTION, NAME=mantle
0, 0, 0, 0, 0, 1
START, 0.15, -1
LINE, 0.15, 1
"""

PROBE_C = r"""/* One point against each surface of the file argv[1]: exactly one contact, whose
 * closest point, normal and signed distance match the closed forms to 1e-12. */
#include <rigidsurf/surface.h>

#include <math.h>
#include <stdio.h>

static int near(const double *a, const double *b, int n)
{
    for (int i = 0; i < n; ++i)
        if (!(fabs(a[i] - b[i]) <= 1e-12))
            return 0;
    return 1;
}

static int probe(const char *path, const char *name, const double p[3], const double xm[3],
                 const double n[3], double dist)
{
    rs_surface s;
    rs_error err;
    if (rs_surface_read(path, name, &s, &err) != RS_OK) {
        printf("%s: %s\n", name, err.msg);
        return 1;
    }
    rs_query q = {0};
    q.n = 1;
    q.slave.x = &p[0];
    q.slave.y = &p[1];
    q.slave.z = &p[2];
    q.gap_max = 1.0;
    q.dist_min = -INFINITY;
    rs_contacts c = {0};
    int ok = rs_surface_query(&s, &q, &c, &err) == RS_OK;
    if (!ok)
        printf("%s: %s\n", name, err.msg);
    if (ok && c.n != 1) {
        printf("%s: %d contacts, expected 1\n", name, c.n);
        ok = 0;
    }
    if (ok) {
        double gx[3] = {c.xm[0][0], c.xm[1][0], c.xm[2][0]};
        double gn[3] = {c.nrm[0][0], c.nrm[1][0], c.nrm[2][0]};
        ok = near(gx, xm, 3) && near(gn, n, 3) && near(&c.dist[0], &dist, 1);
        printf("%s: xm %.17g %.17g %.17g n %.17g %.17g %.17g dist %.17g%s\n", name, gx[0],
               gx[1], gx[2], gn[0], gn[1], gn[2], c.dist[0], ok ? "" : "  WRONG");
        if (!ok)
            printf("%s: expected xm %.17g %.17g %.17g n %.17g %.17g %.17g dist %.17g\n", name,
                   xm[0], xm[1], xm[2], n[0], n[1], n[2], dist);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
    return !ok;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: probe SURFACE_FILE\n");
        return 2;
    }
    int bad = 0;
    /* the plane z = 0: the foot of the point, n = +z, dist = z */
    const double p0[3] = {0.3, -0.2, 0.04}, x0[3] = {0.3, -0.2, 0.0}, n0[3] = {0, 0, 1};
    bad |= probe(argv[1], "floor", p0, x0, n0, 0.04);
    /* the mantle r = 0.15: xm = 0.15 e_r at the point's height, n = -e_r, dist = 0.15 - r */
    const double p1[3] = {0.05, 0.02, 0.3};
    double r = hypot(p1[0], p1[1]);
    const double e[3] = {p1[0] / r, p1[1] / r, 0.0};
    const double x1[3] = {0.15 * e[0], 0.15 * e[1], p1[2]}, n1[3] = {-e[0], -e[1], 0.0};
    bad |= probe(argv[1], "mantle", p1, x1, n1, 0.15 - r);
    printf("%s\n", bad ? "PROBE FAIL" : "PROBE PASS");
    return bad;
}
"""

PROBE_CMAKE = """\
cmake_minimum_required(VERSION 3.18)
project(rigidsurf_probe LANGUAGES C)
set(CMAKE_C_STANDARD 11)
find_package(rigidsurf ${RS_EXPECTED_VERSION} EXACT CONFIG REQUIRED)
# the package found must be the one just installed, with its variables
get_filename_component(found "${rigidsurf_DIR}" REALPATH)
get_filename_component(want "${RS_EXPECTED_DIR}" REALPATH)
if(NOT found STREQUAL want)
  message(FATAL_ERROR "rigidsurf found in ${found}, expected ${want}")
endif()
if(NOT EXISTS "${rigidsurf_FORTRAN_INCLUDE_DIR}/VABA_PARAM.INC"
   OR NOT EXISTS "${rigidsurf_BUILD_LAW}")
  message(FATAL_ERROR "rigidsurf_FORTRAN_INCLUDE_DIR or rigidsurf_BUILD_LAW wrong: "
    "${rigidsurf_FORTRAN_INCLUDE_DIR} ${rigidsurf_BUILD_LAW}")
endif()
add_executable(probe probe.c)
target_compile_options(probe PRIVATE -Wall -Wextra -Werror)
target_link_libraries(probe PRIVATE rigidsurf::rigidsurf)
"""

# A VUINTER as written for Abaqus: fixed form, upper-case include. props: k.
VUINTER_F = """\
C     Linear penalty: normal stress k h for the overclosure h = rdisp(1) > 0;
C     open contacts, and the call after a contact left, carry nothing.
      SUBROUTINE VUINTER(
     1 sfd, scd, spd, svd,
     2 stress, fluxSlv, fluxMst, sed, statev,
     3 kStep, kInc, nFacNod, nSlvNod, nMstNod, nSurfDir,
     4 nDir, nStateVar, nProps, nTemp, nPred, numDefTfv,
     5 jSlvUid, jMstUid, jConMstid, timStep, timGlb,
     6 dTimCur, surfInt, surfSlv, surfMst,
     7 rdisp, drdisp, drot, stiffDflt, condDflt,
     8 shape, coordSlv, coordMst, alocaldir, props,
     9 areaSlv, tempSlv, dtempSlv, preDefSlv, dpreDefSlv,
     1 tempMst, dtempMst, preDefMst, dpreDefMst)
C
      INCLUDE 'VABA_PARAM.INC'
C
      CHARACTER*80 surfInt, surfSlv, surfMst
      DIMENSION props(nProps), statev(nStateVar,nSlvNod),
     1 drot(2,2,nSlvNod), sed(nSlvNod), sfd(nSlvNod),
     2 scd(nSlvNod), spd(nSlvNod), svd(nSlvNod),
     3 rdisp(nDir,nSlvNod), drdisp(nDir,nSlvNod),
     4 stress(nDir,nSlvNod), fluxSlv(nSlvNod),
     5 fluxMst(nSlvNod), areaSlv(nSlvNod),
     6 stiffDflt(nSlvNod), condDflt(nSlvNod),
     7 alocaldir(nDir,nDir,nSlvNod), shape(nFacNod,nSlvNod),
     8 coordSlv(nDir,nSlvNod), coordMst(nDir,nMstNod),
     9 jSlvUid(nSlvNod), jMstUid(nMstNod),
     1 jConMstid(nFacNod,nSlvNod), tempSlv(nSlvNod),
     2 dtempSlv(nSlvNod), preDefSlv(nPred,nSlvNod),
     3 dpreDefSlv(nPred,nSlvNod), tempMst(numDefTfv),
     4 dtempMst(numDefTfv), preDefMst(nPred,numDefTfv),
     5 dpreDefMst(nPred,numDefTfv)
C
      ak = props(1)
      DO 100 k = 1, nSlvNod
        DO 10 i = 1, nDir
          stress(i,k) = 0.d0
   10   CONTINUE
        h = rdisp(1,k)
        IF (h .GT. 0.d0 .AND. h .LT. 0.5d0*r_MaxVal) THEN
          stress(1,k) = ak*h
          sed(k) = 0.5d0*ak*h*h
        ELSE
          sed(k) = 0.d0
        END IF
  100 CONTINUE
      RETURN
      END
"""

R, RHO, G, K = 0.005, 2500.0, 9.81, 1.0e4
NSTEP, NPRINT = 20000, 1000


def deck(z0):
    """One sphere at z0 on the plane z = 0 (type 2 wall), the VUINTER of props k."""
    return """\
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 -0.01 0.1 units box
create_box 2 box
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.0e6 2.0e8
fix m2 all property/global poissonsRatio peratomtype 0.3 0.25
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
create_atoms 1 single 0 0 %(z0).17g units box
set group all diameter %(d).17g density %(rho).17g
fix grav all gravity %(g).17g vector 0 0 -1
fix w all wall/rigid surface surfaces.inp name floor law vuinter ./libmylaw.so statev 0 &
    props %(k).17g type 2
fix integr all nve/sphere
variable st equal step
variable fz equal f_w[3]
variable nc equal f_w[7]
variable zs equal z[1]
fix rows all print %(nprint)d "ROW ${st} ${fz} ${nc} ${zs}" screen yes
run %(nstep)d
""" % dict(z0=z0, d=2 * R, rho=RHO, g=G, k=K, nprint=NPRINT, nstep=NSTEP)


class Checker:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, name, cond, detail=""):
        print(("ok   " if cond else "FAIL ") + name + (" (" + detail + ")" if detail else ""))
        sys.stdout.flush()
        if cond:
            self.passed += 1
        else:
            self.failed += 1
        return cond


class Failed(Exception):
    pass


def clean_env(**extra):
    """The caller's environment without library search paths, plus extra."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("LD_LIBRARY_PATH", "PKG_CONFIG_PATH", "CMAKE_PREFIX_PATH")}
    env.update(extra)
    return env


def run(ck, name, cmd, cwd, env, timeout=240):
    """Runs cmd; a failure is reported with the tail of its output and ends the test."""
    try:
        p = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True,
                           errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        ck.check(name, False, "timed out after %d s" % timeout)
        raise Failed(name)
    out = p.stdout + p.stderr
    if p.returncode != 0:
        tail = "\n".join(out.splitlines()[-25:])
        ck.check(name, False, "exit %d: %s\n%s" % (p.returncode, " ".join(cmd), tail))
        raise Failed(name)
    ck.check(name, True)
    return out


def same_path(a, b):
    return os.path.realpath(a) == os.path.realpath(b)


def check_layout(ck, a, prefix):
    inc = os.path.join(prefix, a.includedir, "rigidsurf")
    lib = os.path.join(prefix, a.libdir)
    binp = os.path.join(prefix, a.bindir)
    doc = os.path.join(prefix, a.docdir)
    src = a.source_dir
    for h in sorted(os.listdir(os.path.join(src, "include", "rigidsurf"))):
        if h.endswith(".h"):
            ck.check("installed include/rigidsurf/" + h, os.path.isfile(os.path.join(inc, h)))
    for lower in ("vaba_param.inc", "aba_param.inc"):
        with open(os.path.join(src, "src", lower), "rb") as f:
            text = f.read()
        for name in (lower, lower.upper()):
            path = os.path.join(inc, name)
            same = os.path.isfile(path) and open(path, "rb").read() == text
            ck.check("installed include/rigidsurf/%s = src/%s" % (name, lower), same)
    for name in ("librigidsurf.a", "librigidsurf_abaqus.so", "pkgconfig/rigidsurf.pc",
                 "cmake/rigidsurf/rigidsurfConfig.cmake",
                 "cmake/rigidsurf/rigidsurfConfigVersion.cmake",
                 "cmake/rigidsurf/rigidsurfTargets.cmake"):
        ck.check("installed %s/%s" % (a.libdir, name), os.path.exists(os.path.join(lib, name)))
    for name in ("README.md", "docs/fix_wall_rigid.md", "docs/conventions.md",
                 "docs/architecture.md", "docs/coupling.md", "examples/README.md",
                 "examples/coupling/drop.c", "examples/user_law/myvuinter.f",
                 "examples/surfaces/drum.inp"):
        ck.check("installed %s/%s" % (a.docdir, name), os.path.isfile(os.path.join(doc, name)))
    path = os.path.join(binp, "rigidsurf-migrate")
    if ck.check("installed %s/rigidsurf-migrate" % a.bindir, os.access(path, os.X_OK)):
        p = subprocess.run([path, "--help"], capture_output=True, text=True, env=clean_env())
        ck.check("rigidsurf-migrate runs and prints its usage and exit codes",
                 p.returncode == 0 and "usage: rigidsurf-migrate" in p.stdout and
                 "Exit status" in p.stdout, p.stderr)
        # a motion, through the modules installed in share/rigidsurf
        deck = os.path.join(os.path.dirname(os.path.normpath(prefix)), "in.wiggle")
        with open(os.path.join(os.path.dirname(deck), "p.stl"), "w") as f:
            f.write("solid p\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
                    "   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid p\n")
        with open(deck, "w") as f:
            f.write("fix p all mesh/surface file p.stl type 1\n"
                    "fix w all wall/gran model hertz tangential history mesh n_meshes 1 "
                    "meshes p\n"
                    "fix s all move/mesh mesh p wiggle amplitude 0 0 1e-3 period 0.1\n")
        p = subprocess.run([path, deck], capture_output=True, text=True, env=clean_env())
        ck.check("rigidsurf-migrate translates a move/mesh wiggle (its module installed)",
                 p.returncode == 0 and "variable rs_s_t0 equal $(time)" in p.stdout,
                 p.stderr)
    progs = ["liggghts-rigidsurf", "rigidsurf-frames", "rigidsurf-build-law"]
    if a.with_lammps == "ON":
        progs += ["lmp-rigidsurf", os.path.join("..", a.libdir, "wallrigidplugin.so")]
    for prog in progs:
        path = os.path.join(binp, prog)
        usable = os.R_OK if prog.endswith(".so") else os.X_OK
        if not ck.check("installed %s/%s" % (a.bindir, prog), os.access(path, usable)):
            continue
        # every library resolves without LD_LIBRARY_PATH, the utility library to the
        # prefix's copy through the run path; the LIGGGHTS host always loads it (user
        # routines share its instance)
        p = subprocess.run(["ldd", path], capture_output=True, text=True, env=clean_env())
        missing = [l.split()[0] for l in p.stdout.splitlines() if "not found" in l]
        ck.check(prog + ": every shared library found", p.returncode == 0 and not missing,
                 " ".join(missing))
        where = [l.split("=>")[1].split("(")[0].strip() for l in p.stdout.splitlines()
                 if "librigidsurf_abaqus" in l and "=>" in l]
        if where or prog in ("liggghts-rigidsurf", "lmp-rigidsurf") or prog.endswith(".so"):
            ok = len(where) == 1 and os.path.isfile(where[0]) and same_path(
                os.path.dirname(where[0]), lib)
            ck.check(prog + " loads librigidsurf_abaqus from the prefix", ok,
                     where[0] if where else "not linked")


def check_probe_cmake(ck, a, prefix, tmp):
    srcdir = os.path.join(tmp, "probe")
    bdir = os.path.join(tmp, "probe-cmake")
    cmdir = os.path.join(prefix, a.libdir, "cmake", "rigidsurf")
    env = clean_env()
    run(ck, "probe: configure with find_package(rigidsurf CONFIG)",
        [a.cmake, "-S", srcdir, "-B", bdir, "-DCMAKE_BUILD_TYPE=Release",
         "-DCMAKE_C_COMPILER=" + a.cc, "-DCMAKE_PREFIX_PATH=" + prefix,
         "-DRS_EXPECTED_DIR=" + cmdir, "-DRS_EXPECTED_VERSION=" + a.version], tmp, env)
    run(ck, "probe: build through CMake", [a.cmake, "--build", bdir], tmp, env)
    out = run(ck, "probe (CMake build): normals and distances against closed forms",
              [os.path.join(bdir, "probe"), os.path.join(srcdir, "surfaces.inp")], tmp, env)
    print(out.rstrip())


def check_probe_pkgconfig(ck, a, prefix, tmp):
    srcdir = os.path.join(tmp, "probe")
    env = clean_env(PKG_CONFIG_PATH=os.path.join(prefix, a.libdir, "pkgconfig"))
    for static in (False, True):
        tag = "pkg-config%s" % (" --static" if static else "")
        cmd = [a.pkg_config, "--cflags", "--libs"] + (["--static"] if static else []) + [
            "rigidsurf"]
        flags = shlex.split(run(ck, tag + " --cflags --libs rigidsurf", cmd, tmp, env))
        incs = [f[2:] for f in flags if f.startswith("-I")]
        ck.check(tag + ": -I is the prefix's include folder",
                 len(incs) == 1 and same_path(incs[0], os.path.join(prefix, a.includedir)),
                 " ".join(flags))
        exe = os.path.join(tmp, "probe-pc%s" % ("-static" if static else ""))
        run(ck, "probe: cc with " + tag,
            [a.cc, "-std=c11", "-Wall", "-Wextra", "-Werror", os.path.join(srcdir, "probe.c"),
             "-o", exe] + flags, tmp, env)
        out = run(ck, "probe (%s build): normals and distances against closed forms" % tag,
                  [exe, os.path.join(srcdir, "surfaces.inp")], tmp, env)
        print(out.rstrip())


def check_vuinter(ck, a, prefix, tmp):
    work = os.path.join(tmp, "deck")
    os.makedirs(work)
    with open(os.path.join(work, "mylaw.f"), "w") as f:
        f.write(VUINTER_F)
    with open(os.path.join(work, "surfaces.inp"), "w") as f:
        f.write(SURFACES)
    env = clean_env(RIGIDSURF_CACHE=os.path.join(tmp, "cache"))
    binp = os.path.join(prefix, a.bindir)
    out = run(ck, "rigidsurf-build-law mylaw.f -o libmylaw.so",
              [os.path.join(binp, "rigidsurf-build-law"), "mylaw.f", "-o", "libmylaw.so",
               "-v"], work, env)
    words = out.split()
    inc = [words[i + 1] for i in range(len(words) - 1) if words[i] == "-I"]
    libs = [words[i + 1] for i in range(len(words) - 1) if words[i] == "-L"]
    ck.check("rigidsurf-build-law uses the installed Fortran includes",
             len(inc) >= 1 and same_path(inc[0], os.path.join(prefix, a.includedir,
                                                              "rigidsurf")), " ".join(inc))
    ck.check("rigidsurf-build-law links the installed utility library",
             len(libs) == 1 and same_path(libs[0], os.path.join(prefix, a.libdir)),
             " ".join(libs))
    ck.check("libmylaw.so built", os.path.isfile(os.path.join(work, "libmylaw.so")))

    m = RHO * 4.0 / 3.0 * math.pi * R ** 3
    mg = m * G
    h0 = mg / K  # the equilibrium overlap
    z0 = R - h0
    with open(os.path.join(work, "in.rest"), "w") as f:
        f.write(deck(z0))
    out = run(ck, "installed liggghts-rigidsurf runs the deck with law vuinter",
              [os.path.join(binp, "liggghts-rigidsurf"), "-in", "in.rest", "-log", "none",
               "-echo", "none"], work, env)
    rows = []
    for line in out.splitlines():
        w = line.split()
        if len(w) == 5 and w[0] == "ROW":
            rows.append((int(float(w[1])), float(w[2]), float(w[3]), float(w[4])))
    ck.check("deck printed every %d steps" % NPRINT, len(rows) == NSTEP // NPRINT,
             "%d rows" % len(rows))
    if not rows:
        return
    ferr = max(abs(fz + mg) / mg for _, fz, _, _ in rows)
    zerr = max(abs(z - z0) / h0 for _, _, _, z in rows)
    ck.check("one contact at every row", all(nc == 1 for _, _, nc, _ in rows))
    ck.check("wall force -m g to 1%", ferr <= 0.01,
             "m g %.6g N, largest relative error %.3g, last Fz %.9g N" % (mg, ferr, rows[-1][1]))
    ck.check("sphere at its equilibrium overlap m g / k to 1%", zerr <= 0.01,
             "overlap %.6g m, largest error %.3g of it" % (h0, zerr))


# The coupling example's inputs (examples/coupling/drop.c, docs/coupling.md): sphere i
# (0, 1, 2) of radius 4 + i mm, density 2500, launched at 0.05 (i - 1) m/s along x;
# hertz with Y 1e7 and nu 0.3 for sphere and wall; gravity 9.81.
DROP_RHO, DROP_G, DROP_Y, DROP_NU, DROP_V0 = 2500.0, 9.81, 1.0e7, 0.3, 0.05


def code_block(page, heading):
    """The first ```c block after the heading line of a Markdown page."""
    after = page.split("\n" + heading + "\n", 1)
    if len(after) != 2 or "```c\n" not in after[1]:
        return None
    return after[1].split("```c\n", 1)[1].split("\n```", 1)[0] + "\n"


def check_coupling_example(ck, a, prefix, tmp):
    doc = os.path.join(prefix, a.docdir)
    exdir = os.path.join(doc, "examples", "coupling")
    with open(os.path.join(doc, "docs", "coupling.md")) as f:
        page = f.read()
    with open(os.path.join(exdir, "drop.c")) as f:
        source = f.read()
    ck.check("docs/coupling.md shows examples/coupling/drop.c as installed",
             code_block(page, "## The example") == source)
    ck.check("installed examples/coupling/CMakeLists.txt",
             os.path.isfile(os.path.join(exdir, "CMakeLists.txt")))
    srcdir = os.path.join(tmp, "coupling")
    shutil.copytree(exdir, srcdir)
    bdir = os.path.join(tmp, "coupling-build")
    env = clean_env()
    run(ck, "coupling example: configure out of tree with find_package(rigidsurf)",
        [a.cmake, "-S", srcdir, "-B", bdir, "-DCMAKE_BUILD_TYPE=Release",
         "-DCMAKE_C_COMPILER=" + a.cc, "-DCMAKE_PREFIX_PATH=" + prefix,
         "-DCMAKE_C_FLAGS=-Werror"], tmp, env)
    run(ck, "coupling example: build", [a.cmake, "--build", bdir], tmp, env)
    out = run(ck, "coupling example: runs", [os.path.join(bdir, "drop")], tmp, env)
    print(out.rstrip())
    rows = [l.split() for l in out.splitlines() if l.startswith("sphere ")]
    ck.check("coupling example: three spheres reported", len(rows) == 3, "%d" % len(rows))
    estar = 1.0 / (2.0 * (1.0 - DROP_NU ** 2) / DROP_Y)
    for i, w in enumerate(rows[:3]):
        R = 0.004 + 0.001 * i
        m = DROP_RHO * 4.0 / 3.0 * math.pi * R ** 3
        delta = (3.0 * m * DROP_G / (4.0 * estar * math.sqrt(R))) ** (2.0 / 3.0)
        got_r, overlap, speed = float(w[3]), float(w[7]), float(w[9])
        ck.check("sphere %d: radius %g as launched" % (i + 1, R), abs(got_r - R) <= 1e-12)
        ck.check("sphere %d rests at the Hertz static overlap to 1e-6" % (i + 1),
                 abs(overlap - delta) <= 1e-6 * delta,
                 "overlap %.6e m, closed form %.6e m, error %.2e" % (
                     overlap, delta, abs(overlap / delta - 1.0)))
        v0 = DROP_V0 * abs(i - 1)
        rho = R - delta / 2.0
        roll = v0 * m * rho ** 2 / (0.4 * m * R ** 2 + m * rho ** 2)
        if v0 == 0.0:
            ck.check("sphere %d, dropped straight, is still" % (i + 1), speed <= 1e-9,
                     "speed %.3g m/s" % speed)
        else:
            ck.check("sphere %d rolls at 5/7 of its launch speed to 0.5%%" % (i + 1),
                     abs(speed - roll) <= 5e-3 * roll,
                     "speed %.6g m/s, closed form %.6g m/s" % (speed, roll))


# The walls example's deck: spheres moved by fix move (no integrator: the states the fix
# sees are those dumped) into a drum's mantle that turns, and onto a baffle plate; each
# wall stores its force on every particle. The walls' words are the deck's.
WALLS_DRUM = ("surface inline revolution origin 0 0 0 axis 0 0 1 profile START 0.1 -0.05 "
              "LINE 0.1 0.05 end law hertz props 5e6 0.3 5e7 0.25 0.5 0.3 0 type 2 "
              "rotate origin 0 0 0 axis 0 0 1 period 0.5 store_force into drum")
WALLS_BAFFLE = ("surface inline mesh baffle.stl law hertz props 5e6 0.3 5e7 0.25 0.6 0.4 0 "
                "type 2 store_force into baffle")
WALLS_STEPS = 400
BAFFLE_STL = """solid baffle
facet normal 0 -1 0
outer loop
vertex -0.09 0.06 -0.05
vertex 0.09 0.06 -0.05
vertex 0.09 0.06 0.05
endloop
endfacet
facet normal 0 -1 0
outer loop
vertex -0.09 0.06 -0.05
vertex 0.09 0.06 0.05
vertex -0.09 0.06 0.05
endloop
endfacet
endsolid baffle
"""


def walls_deck():
    atoms = []
    k = 0
    for i in range(6):  # near the mantle at +x, near the baffle at +y, in between
        th = -0.3 + 0.12 * i
        for j, (x, y) in enumerate(((0.0972 * math.cos(th), 0.0972 * math.sin(th)),
                                    (-0.05 + 0.02 * i, 0.0574 - 0.0001 * i),
                                    (0.02 * i - 0.06, -0.02))):
            k += 1
            atoms.append("create_atoms 1 single %.6f %.6f %.6f units box" % (x, y, 0.01 * (j - 1)))
    lines = [
        "units si", "atom_style granular", "atom_modify map array", "boundary f f f",
        "newton off", "communicate single vel yes",
        "region box block -0.12 0.12 -0.12 0.12 -0.06 0.06 units box", "create_box 2 box",
        "neighbor 0.002 bin", "neigh_modify delay 0",
        "fix m1 all property/global youngsModulus peratomtype 5e6 5e7",
        "fix m2 all property/global poissonsRatio peratomtype 0.3 0.25",
        "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5",
        "fix m4 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3",
        "pair_style gran model hertz tangential history", "pair_coeff * *",
        "timestep 1e-5"] + atoms + [
        "set group all diameter 0.004 density 2500",
        "set group all omegax 40 omegay -25 omegaz 60",
        "fix drum all wall/rigid " + WALLS_DRUM,
        "fix baffle all wall/rigid " + WALLS_BAFFLE,
        "fix push all move linear 0.3 0.25 0.02",
        "dump d all custom 1 replay.dump id x y z vx vy vz omegax omegay omegaz radius mass "
        "f_force_drum[1] f_force_drum[2] f_force_drum[3] f_force_baffle[1] f_force_baffle[2] "
        "f_force_baffle[3]",
        'dump_modify d sort id format "%d' + " %.17g" * 17 + '"',
        "run %d" % WALLS_STEPS]
    return "\n".join(lines) + "\n"


def check_walls_example(ck, a, prefix, tmp):
    bdir = os.path.join(tmp, "coupling-build")
    exe = os.path.join(bdir, "walls")
    if not ck.check("walls example: built with the coupling examples", os.access(exe, os.X_OK)):
        return
    work = os.path.join(tmp, "walls")
    os.makedirs(work)
    with open(os.path.join(work, "baffle.stl"), "w") as f:
        f.write(BAFFLE_STL)
    with open(os.path.join(work, "in.walls"), "w") as f:
        f.write(walls_deck())
    with open(os.path.join(work, "scene"), "w") as f:
        f.write("dt 1e-5\nskin 0.002\nbox -0.12 0.12 -0.12 0.12 -0.06 0.06\n"
                "wall drum %s\nwall baffle %s\n" % (WALLS_DRUM, WALLS_BAFFLE))
    env = clean_env()
    run(ck, "walls example: the deck runs in the installed liggghts-rigidsurf",
        [os.path.join(prefix, a.bindir, "liggghts-rigidsurf"), "-in", "in.walls", "-log",
         "none", "-echo", "none"], work, env)
    out = run(ck, "walls example: runs on the deck's dump",
              [exe, "scene", "replay.dump"], work, env)
    ours = {}
    for line in out.splitlines():
        w = line.split()
        if len(w) == 9 and w[0] == "step":
            ours[(int(w[1]), w[3], int(w[5]))] = tuple(float(v) for v in w[6:9])
    fix, step = {}, None
    with open(os.path.join(work, "replay.dump")) as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        if line.startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
        elif step is not None and line and line[0].isdigit() and len(line.split()) == 18:
            w = line.split()
            fix[(step, "drum", int(w[0]))] = tuple(float(v) for v in w[12:15])
            fix[(step, "baffle", int(w[0]))] = tuple(float(v) for v in w[15:18])
    ck.check("walls example: a force for every particle, wall and step",
             len(fix) == 2 * 18 * (WALLS_STEPS + 1) and set(fix) == set(ours),
             "%d of the fix's, %d of the example's" % (len(fix), len(ours)))
    differ = [k for k in fix if ours.get(k) != fix[k]]
    ck.check("walls example: every force equals the fix's, bit for bit", not differ,
             "%d differ, the first %s: %s against %s" % (
                 len(differ), differ[0], ours.get(differ[0]), fix[differ[0]])
             if differ else "%d forces" % len(fix))
    touched = {w: sum(1 for k, f in fix.items() if k[1] == w and any(f)) for w in
               ("drum", "baffle")}
    ck.check("walls example: both walls pressed particles",
             touched["drum"] > 100 and touched["baffle"] > 100, str(touched))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", required=True)
    ap.add_argument("--source-dir", default=os.path.join(os.path.dirname(
        os.path.abspath(__file__)), "..", ".."))
    ap.add_argument("--version", required=True, help="the project's version")
    ap.add_argument("--cmake", default="cmake")
    ap.add_argument("--cc", default="cc")
    ap.add_argument("--pkg-config", dest="pkg_config", default="pkg-config")
    ap.add_argument("--bindir", default="bin")
    ap.add_argument("--libdir", default="lib")
    ap.add_argument("--includedir", default="include")
    ap.add_argument("--docdir", default="share/doc/rigidsurf")
    ap.add_argument("--keep", action="store_true", help="keep the temporary directory")
    ap.add_argument("--with-lammps", dest="with_lammps", default="OFF",
                    help="ON: lmp-rigidsurf and wallrigidplugin.so are installed too")
    a = ap.parse_args()

    ck = Checker()
    tmp = tempfile.mkdtemp(prefix="rs_install_")
    prefix = os.path.join(tmp, "prefix")
    probe = os.path.join(tmp, "probe")
    os.makedirs(probe)
    for name, text in (("probe.c", PROBE_C), ("CMakeLists.txt", PROBE_CMAKE),
                       ("surfaces.inp", SURFACES)):
        with open(os.path.join(probe, name), "w") as f:
            f.write(text)

    manifest = os.path.join(a.build_dir, "install_manifest.txt")
    saved = os.path.join(tmp, "install_manifest.txt")
    had_manifest = os.path.exists(manifest)
    if had_manifest:
        shutil.copy2(manifest, saved)
    try:
        try:
            run(ck, "cmake --install into a temporary prefix",
                [a.cmake, "--install", a.build_dir, "--prefix", prefix], tmp, clean_env())
        finally:
            if had_manifest:
                shutil.copy2(saved, manifest)
            elif os.path.exists(manifest):
                os.remove(manifest)
        check_layout(ck, a, prefix)
        for step in (check_probe_cmake, check_probe_pkgconfig, check_vuinter,
                     check_coupling_example, check_walls_example):
            try:
                step(ck, a, prefix, tmp)
            except Failed:
                pass
    except Failed:
        pass
    finally:
        if a.keep:
            print("temporary directory kept: " + tmp)
        else:
            shutil.rmtree(tmp, ignore_errors=True)
    print("%d passed, %d failed" % (ck.passed, ck.failed))
    return 1 if ck.failed or not ck.passed else 0


if __name__ == "__main__":
    sys.exit(main())
