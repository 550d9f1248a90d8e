#!/usr/bin/python3
"""fix wall/rigid warns once when the time step exceeds 0.2 of its law's critical step.

The critical steps are computed here from their closed forms, independently of the
code: the Rayleigh time pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = Y / (2 (1 + nu)),
for hertz (LIGGGHTS's material properties of the smallest sphere), and 2 sqrt(m / K)
for the spring laws (hooke: K = max(kn, 7 kt / 2); linear_softening with a projected
area: K = k pi R^2). Each deck has two spheres of different radii, so the check must
take the smallest step over the particles. A step 10 times over the limit warns, with
the critical step printed to 1e-5; a step under it does not.

A user routine's stiffness feeds the same check: a UINTER returning DDSDDR = K gives
the critical step 2 sqrt(m / (K A)) of the smallest sphere (both held on the plane),
warned once, after the run that met it. A routine returning PNEWDT < 1 gives one warning per run with the
smallest value, the step it suggests (dt PNEWDT) and the number of calls that asked
(two touching spheres, two increments a run: 4); `pnewdt stop` ends the run with an
ERROR. The routines' KSTEP counts the runs and KINC the increments of each run, and
TIME holds the step time and the total time at the end of the increment: a FRIC
writes them into its shear, read back from the fix's per-atom output.
"""
import math
import re

import liglib as L

RHO = 2500.0
RADII = (0.004, 0.002)
YOUNG, POISSON = 5.0e7, 0.3


def rayleigh(r):
    m = RHO * 4.0 / 3.0 * math.pi * r ** 3
    g = YOUNG / (2.0 * (1.0 + POISSON))
    rho = 3.0 * m / (4.0 * math.pi * r ** 3)
    return math.pi * r * math.sqrt(rho / g) / (0.1631 * POISSON + 0.8766)


def spring(r, k):
    return 2.0 * math.sqrt(RHO * 4.0 / 3.0 * math.pi * r ** 3 / k)


def deck(dt, law):
    d = L.header((-0.1, 0.1, -0.1, 0.1, -0.05, 0.2), dt, young=(YOUNG, 2.0e8),
                 poisson=(POISSON, 0.25))
    d += L.sphere(1, (0.0, 0.0, 0.02), RADII[0], RHO)
    d += L.sphere(2, (0.05, 0.0, 0.02), RADII[1], RHO)
    d += "fix w all wall/rigid surface plane.inp %s\n" % law
    d += "fix integr all nve/sphere\nrun 2\nrun 2\n"
    return d


# A UINTER: penalty STRESS(1) = K H with DDSDDR(1,1) = K, frictionless; PNEWDT =
# PROPS(2) when PROPS(2) > 0 and the contact is closed.
UINTER_K = """      SUBROUTINE UINTER(STRESS,DDSDDR,DVISCOUS,DSTRUCTURAL,FLUX,DDFDDT,
     1 DDSDDT,DDFDDR,STATEV,SED,SFD,SPD,SVD,SCD,PNEWDT,RDISP,DRDISP,
     2 TEMP,DTEMP,PREDEF,DPRED,TIME,DTIME,FREQR,CINAME,SLNAME,MSNAME,
     3 PROPS,COORDS,ALOCALDIR,DROT,AREA,CHRLNGTH,NODE,NDIR,NSTATV,
     4 NPRED,NPROPS,MCRD,KSTEP,KINC,KIT,LINPER,LOPENCLOSE,LSTATE,
     5 LSDI,LPRINT)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*80 CINAME,SLNAME,MSNAME
      DIMENSION STRESS(NDIR),DDSDDR(NDIR,NDIR),FLUX(2),RDISP(NDIR),
     1 PROPS(NPROPS)
      DO I = 1, NDIR
        STRESS(I) = 0.D0
      END DO
      IF (RDISP(1) .GT. 0.D0) THEN
        STRESS(1) = PROPS(1) * RDISP(1)
        DDSDDR(1,1) = PROPS(1)
        IF (PROPS(2) .GT. 0.D0) PNEWDT = PROPS(2)
      END IF
      RETURN
      END
"""

# A FRIC that reports its KSTEP, KINC and TIME in its shear (LM = 0, no slip).
FRIC_STEPS = """      SUBROUTINE FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,
     1 DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,
     2 KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,
     3 NPATCH,COORDS,RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,
     4 NSTATV,CHRLNGTH,PROPS,NPROPS)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*80 CINAME,SLNAME,MSNAME
      DIMENSION TAU(NFDIR),DSLIP(NFDIR),TIME(2)
      LM = 0
      TAU(1) = 1000.D0 * KSTEP + KINC
      TAU(2) = 1000.D0 * TIME(2) / DTIME + TIME(1) / DTIME
      DSLIP(1) = 0.D0
      DSLIP(2) = 0.D0
      RETURN
      END
"""


def touching(dt, fix_line, runs, integrate=True):
    """The two spheres on the plane with a small overlap; without integration they stay
    there, so both touch it at every step."""
    d = L.header((-0.1, 0.1, -0.1, 0.1, -0.05, 0.2), dt, young=(YOUNG, 2.0e8),
                 poisson=(POISSON, 0.25))
    d += L.sphere(1, (0.0, 0.0, RADII[0] * (1 - 1e-5)), RADII[0], RHO)
    d += L.sphere(2, (0.05, 0.0, RADII[1] * (1 - 1e-5)), RADII[1], RHO)
    d += "fix w all wall/rigid surface plane.inp %s\n" % fix_line
    if integrate:
        d += "fix integr all nve/sphere\n"
    return d + runs


def routine_checks(s):
    s.write("uinter_k.f", UINTER_K)
    s.write("fric_steps.f", FRIC_STEPS)
    uk = s.path("uinter_k.f")
    k = 1.0e4
    tcrit = min(spring(r, k) for r in RADII)
    for factor, warn in ((10.0, True), (0.5, False)):
        dt = factor * 0.2 * tcrit
        tag = "uinter DDSDDR, dt = %g x 0.2 t_crit" % factor
        rc, out = s.run("uinter_%g" % factor,
                        touching(dt, "law uinter %s props %g 0 type 2" % (uk, k),
                                 "run 2\nrun 2\n", integrate=False))
        lines = [l for l in out.splitlines()
                 if l.startswith("WARNING") and "critical step" in l]
        if not warn:
            s.ck.check(tag + ": no warning", rc == 0 and not lines, "; ".join(lines),
                       why=out[-600:])
            continue
        if not s.ck.check(tag + ": one warning over two runs", len(lines) == 1,
                          "%d" % len(lines), why=out[-600:]):
            continue
        m = re.search(r"of the critical step ([0-9.eE+-]+) of law '[^']*' "
                      r"\(2 sqrt\(m/\(k A\)\) of the stiffness its routine returned, "
                      r"DDSDDR\)", lines[0])
        got = float(m.group(1)) if m else float("nan")
        s.ck.check(tag + ": the critical step is 2 sqrt(m/(K A)) of the smaller sphere",
                   m is not None and abs(got - tcrit) <= 1e-5 * tcrit,
                   "%.6g vs %.6g" % (got, tcrit), why=lines[0])

    dt = 0.05 * tcrit
    rc, out = s.run("pnewdt_warn", touching(dt, "law uinter %s props %g 0.25 type 2"
                                            % (uk, k), "run 2\nrun 2\n"))
    lines = [l for l in out.splitlines() if l.startswith("WARNING") and "PNEWDT" in l]
    s.ck.check("pnewdt warn: one warning per run", rc == 0 and len(lines) == 2,
               "%d" % len(lines), why=out[-800:])
    for l in lines:
        m = re.search(r"(\d+) call\(s\).*smallest PNEWDT = ([0-9.eE+-]+).*time step of "
                      r"([0-9.eE+-]+)", l)
        s.ck.check("pnewdt warn: 4 calls, PNEWDT 0.25, the step dt x 0.25",
                   m is not None and int(m.group(1)) == 4 and float(m.group(2)) == 0.25
                   and abs(float(m.group(3)) - 0.25 * dt) <= 1e-5 * dt, why=l)
    rc, out = s.run("pnewdt_stop", touching(dt, "law uinter %s props %g 0.25 type 2 "
                                            "pnewdt stop" % (uk, k), "run 2\n"),
                    expect_ok=False)
    err = L.error_lines(out)
    s.ck.check("pnewdt stop: the run ends with an ERROR naming PNEWDT",
               rc != 0 and any("PNEWDT = 0.25" in l for l in err), why=out[-800:])

    # KSTEP, KINC and TIME: spheres held in place (no integration), runs of 3 and 2
    dt = 1.0e-6
    deck = touching(dt, "law fric %s normal linear_softening props 1e5 type 2 peratom yes"
                    % s.path("fric_steps.f"), "", integrate=False)
    deck += L.dump_lines("d", 1, "steps.dump", cols="id f_w[5] f_w[6]")
    deck += "run 3\nrun 2\n"
    rc, out = s.run("steps", deck)
    frames = {}
    step, lines = None, open(s.path("steps.dump")).read().splitlines() if rc == 0 else []
    for i, l in enumerate(lines):
        if l.startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
        elif step is not None and l and l[0].isdigit() and len(l.split()) == 3:
            frames.setdefault(step, {}).setdefault(int(l.split()[0]),
                                                   tuple(map(float, l.split()[1:])))
    want = {1: (1001, 1001), 2: (1002, 2002), 3: (1003, 3003), 4: (2001, 4001),
            5: (2002, 5002)}
    for n, (kk, tt) in want.items():
        got = frames.get(n, {}).get(1)
        s.ck.check("step %d: KSTEP, KINC and TIME (step, total) at the end" % n,
                   got is not None and got[0] == kk and abs(got[1] - tt) < 1e-6,
                   "%s vs %s" % (got, (kk, tt)), why=out[-600:])


def body(s):
    s.write("plane.inp", L.plane_z(0.0, 1.0))
    kn, kt, k_area = 2.0e4, 1.0e4, 3.0e8
    cases = [
        ("hertz", "law hertz type 2", min(rayleigh(r) for r in RADII)),
        ("hooke", "law hooke props %g %g 0 0 0.5 type 2" % (kn, kt),
         min(spring(r, max(kn, 3.5 * kt)) for r in RADII)),
        ("linear_softening", "law linear_softening props %g area projected type 2" % k_area,
         min(spring(r, k_area * math.pi * r * r) for r in RADII)),
    ]
    for name, law, tcrit in cases:
        for factor, warn in ((10.0, True), (0.5, False)):
            dt = factor * 0.2 * tcrit
            rc, out = s.run("%s_%g" % (name, factor), deck(dt, law))
            lines = [l for l in out.splitlines()
                     if l.startswith("WARNING") and "critical step" in l]
            tag = "%s, dt = %g x 0.2 t_crit" % (name, factor)
            if not warn:
                s.ck.check(tag + ": no warning", not lines, "; ".join(lines))
                continue
            if not s.ck.check(tag + ": one warning over two runs", len(lines) == 1,
                              "%d" % len(lines), why=out[-600:]):
                continue
            m = re.search(r"of the critical step ([0-9.eE+-]+) of law '(\w+)'", lines[0])
            got = float(m.group(1)) if m else float("nan")
            s.ck.check(tag + ": the critical step is the closed form",
                       m is not None and m.group(2) == name
                       and abs(got - tcrit) <= 1e-5 * tcrit,
                       "%.6g vs %.6g" % (got, tcrit), why=lines[0])
    routine_checks(s)


if __name__ == "__main__":
    L.main_guard(L.Session(__doc__), body)
