"""What fix wall/rigid reads from a user routine's Fortran source before it runs it.

- A UINTER with the older argument list (no DVISCOUS, DSTRUCTURAL, FREQR), given as
  `law uinter FILE.f` with no further word: the sphere rests at the equilibrium
  overlap of its penalty law (the wall carries m g), and the routine ends the run
  (XIT) should it see KINC, NDIR or AREA out of place.
- Issue 32's UINTER, the current list less DVISCOUS and DSTRUCTURAL, which no adapter
  calls: an ERROR naming the file, the line of its SUBROUTINE statement, the count
  found (45) and the counts expected (47, 44); so is a VUINTER with an argument too
  many.
- A VUINTER on which gfortran warns (a REAL DO variable, a deleted feature, and a REAL
  array index), run on two ranks: one WARNING line with the count, the first warning
  with its file and line, and the compiler log's path; again when the library comes
  from the cache.
"""
import math
import os

import liglib

R, RHO, G, K = 0.005, 2500.0, 9.81, 2.0e4
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
H = MASS * G / K  # equilibrium overlap under the penalty law

UINTER_OLDER = """\
c     Penalty contact, STRESS(1) = K RDISP(1), written for the older UINTER list
      subroutine uinter(stress,ddsddr,flux,ddfddt,ddsddt,ddfddr,
     1 statev,sed,sfd,spd,svd,scd,pnewdt,rdisp,drdisp,
     2 temp,dtemp,predef,dpred,time,dtime,ciname,slname,msname,
     3 props,coords,alocaldir,drot,area,chrlngth,node,ndir,nstatv,
     4 npred,nprops,mcrd,kstep,kinc,kit,linper,lopenclose,lstate,
     5 lsdi,lprint)
      include 'aba_param.inc'
      character*80 ciname,slname,msname
      dimension stress(ndir),ddsddr(ndir,ndir),rdisp(ndir),props(nprops)
      if (kinc .lt. 1 .or. kinc .gt. 100000 .or. ndir .ne. 3 .or.
     1    area .ne. 1.d0 .or. nprops .ne. 1) call xit
      do i = 1, ndir
        stress(i) = 0.d0
      end do
      if (rdisp(1) .gt. 0.d0) then
        stress(1) = props(1) * rdisp(1)
        ddsddr(1,1) = props(1)
      end if
      return
      end
"""

# The current list less DVISCOUS and DSTRUCTURAL; the SUBROUTINE statement is on line 3.
UINTER_45 = """\
C     DVISCOUS and DSTRUCTURAL left out, FREQR kept
C
      SUBROUTINE UINTER(STRESS,DDSDDR,FLUX,DDFDDT,DDSDDT,DDFDDR,
     1 STATEV,SED,SFD,SPD,SVD,SCD,PNEWDT,RDISP,DRDISP,
     2 TEMP,DTEMP,PREDEF,DPRED,TIME,DTIME,FREQR,CINAME,SLNAME,MSNAME,
     3 PROPS,COORDS,ALOCALDIR,DROT,AREA,CHRLNGTH,NODE,NDIR,NSTATV,
     4 NPRED,NPROPS,MCRD,KSTEP,KINC,KIT,LINPER,LOPENCLOSE,LSTATE,
     5 LSDI,LPRINT)
      INCLUDE 'ABA_PARAM.INC'
      RETURN
      END
"""

VUINTER_HEAD = """\
      SUBROUTINE VUINTER(sfd, scd, spd, svd, stress, fluxSlv, fluxMst, sed,
     1 statev, kStep, kInc, nFacNod, nSlvNod, nMstNod, nSurfDir, nDir,
     2 nStateVar, nProps, nTemp, nPred, numDefTfv, jSlvUid, jMstUid,
     3 jConMstid, timStep, timGlb, dTimCur, surfInt, surfSlv, surfMst,
     4 rdisp, drdisp, drot, stiffDflt, condDflt, shape, coordSlv, coordMst,
     5 alocaldir, props, areaSlv, tempSlv, dtempSlv, preDefSlv, dpreDefSlv,
     6 tempMst, dtempMst, preDefMst, dpreDefMst{extra})
      INCLUDE 'VABA_PARAM.INC'
      CHARACTER*80 surfInt, surfSlv, surfMst
      DIMENSION stress(nDir,nSlvNod), rdisp(nDir,nSlvNod), props(nProps)
"""

# A penalty VUINTER on which gfortran warns twice: line 12 (a REAL DO variable) and
# line 15 (a REAL array index; S / 6 = 1, so props(1)).
VUINTER_WARNS = VUINTER_HEAD.format(extra="") + """\
      S = 0.D0
      DO R = 1, 3
        S = S + R
      END DO
      AK = props(S / 6.D0)
      DO K = 1, nSlvNod
        stress(1, K) = AK * MAX(rdisp(1, K), 0.D0)
        DO I = 2, nDir
          stress(I, K) = 0.D0
        END DO
      END DO
      END
"""


def deck(s, law, routine, np=1, steps=200):
    surf = s.write("floor.inp", liglib.plane_z(0.0, half=1.0))
    text = liglib.header((-0.05, 0.05, -0.05, 0.05, -0.01, 0.05), 1e-5,
                         pre="processors %d 1 1\n" % np if np > 1 else "")
    for i, x in enumerate((-0.02, 0.02)):
        text += liglib.sphere(i + 1, (x, 0.0, R - H), R, RHO)
    text += ("fix grav all gravity %r vector 0 0 -1\n" % G
             + "fix w all wall/rigid surface %s law %s %s props %r\n" % (surf, law, routine, K)
             + "fix integr all nve/sphere\n"
             + "variable fz equal f_w[3]\n"
             + "fix out all print 50 \"${fz}\" file fz.txt screen no\n"
             + "run %d\n" % steps)
    return text


def carries_two_mg(s, name):
    fz = [r[0] for r in liglib.read_table(s.path("fz.txt"))]
    err = max(abs(f + 2 * MASS * G) / (2 * MASS * G) for f in fz) if fz else float("inf")
    s.ck.check(name, len(fz) >= 4 and err < 1e-6, "max relative error %.3g" % err)


def body(s):
    ck = s.ck
    os.environ["RIGIDSURF_CACHE"] = s.path("cache")

    older = s.write("uinter_older.f", UINTER_OLDER)
    rc, out = s.run("older", deck(s, "uinter", older))
    carries_two_mg(s, "the older UINTER list: the wall carries 2 m g")

    def refused(name, law, routine, expect):
        rc, out = s.run(name, deck(s, law, routine), expect_ok=False)
        lines = liglib.error_lines(out)
        ok = rc not in (0, None) and any(all(e in l for e in expect) for l in lines)
        ck.check(name, ok, "" if ok else "exit %s: %s" % (rc, lines[:2] or out[-300:]))

    bad = s.write("uinter45.f", UINTER_45)
    refused("issue 32's UINTER list is an error", "uinter", bad,
            ["uinter45.f:3: SUBROUTINE UINTER has 45 arguments", "with 47 (", " or 44 ("])
    extra = s.write("vuinter50.f", VUINTER_HEAD.format(extra=",\n     7 EXTRA") + "      END\n")
    refused("a VUINTER with an argument too many is an error", "vuinter", extra,
            ["vuinter50.f:1: SUBROUTINE VUINTER has 50 arguments", "with 49 ("])

    warns = s.write("warns.f", VUINTER_WARNS)
    for name in ("warns", "warns_cached"):
        rc, out = s.run(name, deck(s, "vuinter", warns, np=2), np=2)
        lines = [l for l in out.splitlines() if "WARNING" in l and "Fortran compiler" in l]
        ck.check(name + ": one WARNING line for two ranks", len(lines) == 1,
                 "%d lines" % len(lines))
        line = lines[0] if lines else ""
        ck.check(name + ": the count and the first warning with its file and line",
                 "gave 2 warnings" in line
                 and "warns.f:12:" in line and "Deleted feature: Loop variable" in line,
                 "" if lines else out[-300:], line)
        logs = [w for w in line.split() if w.endswith(".so.log)")]
        log = logs[0][:-1] if logs else ""
        ck.check(name + ": the compiler log's path", log.startswith(s.path("cache"))
                 and os.path.isfile(log), line)
        with open(s.path(name + ".log")) as f:
            ck.check(name + ": the line is in the log", "gave 2 warnings" in f.read())
        carries_two_mg(s, name + ": the routine runs")


liglib.main_guard(liglib.Session(__doc__), body)
