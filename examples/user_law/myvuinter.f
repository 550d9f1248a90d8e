C     A user VUINTER in Abaqus calling form, for `law vuinter myvuinter.f`:
C     Coulomb friction with a linear penalty in the normal direction, the same
C     model as the built-in law `coulomb` (and as mylaw.c), same operations in
C     the same order.
C       p   = kn h for the overclosure h = rdisp(1) > 0, open contacts carry
C             nothing
C       s_e <- drot s_e + drdisp(2:3), the elastic slip, in statev(1:2)
C       tau = k_stick s_e; if |tau| > mu p: tau <- mu p tau/|tau|,
C             s_e = tau / k_stick
C     stress(1) = p, stress(2:3) = tau (traction on the master).
C     props: mu, k_stick, kn.  NSTATEV = 2.
C     Build: the fix builds it when given the source; by hand:
C            rigidsurf-build-law myvuinter.f -o libmyvuinter.so
      subroutine vuinter(
C Write only
     1 sfd, scd, spd, svd,
C Read/Write
     2 stress, fluxSlv, fluxMst, sed, statev,
C Read only
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
      character*80 surfInt, surfSlv, surfMst
C
      dimension props(nProps), statev(nStateVar,nSlvNod),
     1 drot(2,2,nSlvNod), sed(nSlvNod), sfd(nSlvNod),
     2 scd(nSlvNod), spd(nSlvNod), svd(nSlvNod),
     3 rdisp(nDir,nSlvNod), drdisp(nDir,nSlvNod),
     4 stress(nDir,nSlvNod), fluxSlv(nSlvNod),
     5 fluxMst(nSlvNod), areaSlv(nSlvNod),
     6 stiffDflt(nSlvNod), condDflt(nSlvNod),
     7 alocaldir(nDir,nDir,nSlvNod), shape(nFacNod,nSlvNod),
     8 coordSlv(nDir,nSlvNod), coordMst(nDir,nFacNod,nSlvNod),
     9 jSlvUid(nSlvNod), jMstUid(nMstNod),
     1 jConMstid(nFacNod,nSlvNod), tempSlv(nSlvNod),
     2 dtempSlv(nSlvNod), preDefSlv(nPred,nSlvNod),
     3 dpreDefSlv(nPred,nSlvNod), tempMst(numDefTfv),
     4 dtempMst(numDefTfv), preDefMst(nPred,numDefTfv),
     5 dpreDefMst(nPred,numDefTfv)
C
      fmu = props(1)
      sk  = props(2)
      pk  = props(3)
      do 100 k = 1, nSlvNod
        do 10 i = 1, nDir
          stress(i,k) = 0.d0
   10   continue
        fluxSlv(k) = 0.d0
        fluxMst(k) = 0.d0
        sed(k) = 0.d0
        sfd(k) = 0.d0
        h = rdisp(1,k)
C       The call after the contact left the tracking thickness.
        if (h .ge. 0.5d0*r_MaxVal) goto 100
        if (.not. (h .gt. 0.d0)) then
          statev(1,k) = 0.d0
          if (nDir .eq. 3) statev(2,k) = 0.d0
          goto 100
        end if
        pn = pk*h
        s1 = statev(1,k)
        s2 = 0.d0
        if (nDir .eq. 3) then
          s2 = statev(2,k)
          r1 = drot(1,1,k)*s1 + drot(1,2,k)*s2
          r2 = drot(2,1,k)*s1 + drot(2,2,k)*s2
          s1 = r1 + drdisp(2,k)
          s2 = r2 + drdisp(3,k)
        else
          s1 = s1 + drdisp(2,k)
        end if
        t1 = sk*s1
        t2 = sk*s2
        tmag = sqrt(t1*t1 + t2*t2)
        tlim = fmu*pn
        if (tmag .gt. tlim) then
          ratio = tlim/tmag
          t1 = t1*ratio
          t2 = t2*ratio
          s1 = t1/sk
          s2 = t2/sk
          sfd(k) = tlim*(tmag - tlim)/sk
        end if
        stress(1,k) = pn
        stress(2,k) = t1
        if (nDir .eq. 3) stress(3,k) = t2
        sed(k) = 0.5d0*pk*h*h + (t1*t1 + t2*t2)/(2.d0*sk)
        statev(1,k) = s1
        if (nDir .eq. 3) statev(2,k) = s2
  100 continue
      return
      end
