"""A VUINTER written as for Abaqus (tests/abaqus/vuinter_util.f: upper-case include,
tabs, long lines, the utility routines) given to fix wall/rigid as its Fortran source.

- Two spheres at their equilibrium overlap on a plane, one per rank (-np 2): the routine
  is built once for both ranks (one library in the cache), the wall carries 2 m g, and
  each rank's information line (XPLB_ABQERR) gives the job name from -log, the rank
  count, the rank, the particle's group and tag (VGETPARTINFO) and its radius and mass
  (RS_GETDEM), as the deck set them; rank 0's line is in the log.
- Errors end the run with an ERROR line that carries the routine's text: LOP = -2
  (after the call), LOP = -3 and VGETVRM (at once), and a compile error names the file,
  the line and the compiler's message.
"""
import math
import os

import liglib

HERE = os.path.dirname(os.path.abspath(__file__))
ROUTINE = os.path.join(HERE, "..", "abaqus", "vuinter_util.f")

R, RHO, G, K = 0.005, 2500.0, 9.81, 2.0e4
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
H = MASS * G / K  # equilibrium overlap under the penalty law


def deck(s, props, np=2, steps=200, routine=ROUTINE):
    surf = s.write("floor.inp", liglib.plane_z(0.0, half=1.0))
    text = liglib.header((-0.05, 0.05, -0.05, 0.05, -0.01, 0.05), 1e-5,
                         pre="processors %d 1 1\n" % np if np > 1 else "")
    for i, x in enumerate((-0.02, 0.02)):
        text += liglib.sphere(i + 1, (x, 0.0, R - H), R, RHO)
    text += ("fix grav all gravity %r vector 0 0 -1\n" % G
             + "fix w all wall/rigid surface %s law vuinter %s statev 10 props %s\n"
             % (surf, routine, " ".join("%r" % p for p in props))
             + "fix integr all nve/sphere\n"
             + "variable fz equal f_w[3]\n"
             + "fix out all print 50 \"${fz}\" file fz.txt screen no\n"
             + "run %d\n" % steps)
    return text


def body(s):
    ck = s.ck
    cache = s.path("cache")
    os.environ["RIGIDSURF_CACHE"] = cache
    rc, out = s.run("rest", deck(s, (K, 0.0, 0.0, 0.0)), np=2)
    libs = [f for f in os.listdir(cache) if f.endswith(".so")]
    logs = [f for f in os.listdir(cache) if f.endswith(".so.log")]
    ck.check("built once for two ranks", len(libs) == 1 and len(logs) == 1,
             "libraries %s, compiler logs %s" % (libs, logs))
    fz = [r[0] for r in liglib.read_table(s.path("fz.txt"))]
    err = max(abs(f + 2 * MASS * G) / (2 * MASS * G) for f in fz) if fz else float("inf")
    ck.check("the wall carries 2 m g", err < 1e-6, "max relative error %.3g" % err)
    for rank, tag in ((0, 1), (1, 2)):
        want = ("rigidsurf INFO [rank %d] VUINTER (XPLB_ABQERR): job rest ranks 2 rank %d "
                "part all node %d dem 0 radius %g mass %g" % (rank, rank, tag, R, MASS))
        ck.check("rank %d's information line" % rank, out.count(want) == 1,
                 "" if want in out else "missing: " + want)
    with open(s.path("rest.log")) as f:
        log = f.read()
    ck.check("rank 0's line is in the log", "rigidsurf INFO [rank 0] VUINTER" in log)

    def fails(name, props, expect, np=1, routine=ROUTINE):
        rc, out = s.run(name, deck(s, props, np=np, routine=routine), np=np,
                        expect_ok=False)
        lines = [l for l in out.splitlines() if "ERROR" in l]
        ok = rc not in (0, None) and any(all(e in l for e in expect) for l in lines)
        ck.check(name, ok, "exit %s: %s" % (rc, lines[:2] if lines else out[-300:]))

    fails("error_after_call", (K, 0.5 * H, 0.0, 0.0),
          ["VUINTER raised an error", "exceeds the limit %g at node" % (0.5 * H)])
    fails("error_now", (K, 0.0, 0.0, 1.0), ["VUINTER raised an error", "stop now at node"])
    fails("vgetvrm", (K, 0.0, 1.0, 0.0), ["VGETVRM('SDV')", "DEM particle"])
    broken = s.write("broken.f", "      SUBROUTINE VUINTER(X)\n"
                     "      INCLUDE 'VABA_PARAM.INC'\n      X = = 1.0D0\n      END\n")
    fails("compile_error", (K, 0.0, 0.0, 0.0), ["broken.f:3:", "Error"], routine=broken)


liglib.main_guard(liglib.Session(__doc__), body)
