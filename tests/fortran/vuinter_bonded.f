! Bonded interface as an Abaqus/Explicit VUINTER, in the Abaqus calling form and built
! against vaba_param.inc. Same behaviour as the built-in law bonded_interface
! (src/laws/bonded_interface.c):
!   a slave whose initial gap -rdisp(1) is below the cutoff bonds on its first call;
!   normal: layer of thickness t, 1D modulus E, linear isotropic hardening H;
!   shear: elastic, G = E/(2(1+nu));  heat: conduction k (Tm - Ts)/t.
! props: gap cutoff, E, nu, yield stress, hardening, thickness, conductivity.
! statev: (1) 1 once initialised, (2) bonded flag, (3) current yield stress.
      subroutine vuinter(
! write only
     1 sfd, scd, spd, svd,
! read/write
     2 stress, fluxSlv, fluxMst, sed, statev,
! read only
     3 kStep, kInc, nFacNod, nSlvNod, nMstNod, nSurfDir,
     4 nDir, nStateVar, nProps, nTemp, nPred, numDefTfv,
     5 jSlvUid, jMstUid, jConMstid, timStep, timGlb,
     6 dTimCur, surfInt, surfSlv, surfMst,
     7 rdisp, drdisp, drot, stiffDflt, condDflt,
     8 shape, coordSlv, coordMst, alocaldir, props,
     9 areaSlv, tempSlv, dtempSlv, preDefSlv, dpreDefSlv,
     1 tempMst, dtempMst, preDefMst, dpreDefMst)
      include 'vaba_param.inc'
      character*80 surfInt, surfSlv, surfMst
      dimension props(nProps), statev(nStateVar,nSlvNod),
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
      parameter (zero = 0.d0, one = 1.d0, two = 2.d0, half = 0.5d0)
      dimension old(3)
      logical perContact
!
      cutoff = props(1)
      e = props(2)
      anu = props(3)
      sy0 = props(4)
      hard = props(5)
      thick = props(6)
      cond = props(7)
      g = e / (two * (one + anu))
      perContact = numDefTfv .gt. 1 .and. numDefTfv .eq. nSlvNod
!
      do 100 k = 1, nSlvNod
        h = rdisp(1,k)
        if (h .ge. half * r_MaxVal) then
! the contact left the tracking thickness: no stress, no flux
          do i = 1, nDir
            stress(i,k) = zero
          end do
          fluxSlv(k) = zero
          fluxMst(k) = zero
          sed(k) = zero
          goto 100
        end if
        ainit = statev(1,k)
        bonded = statev(2,k)
        sy = statev(3,k)
        if (ainit .lt. half) then
          ainit = one
          bonded = zero
          if (-h .lt. cutoff) bonded = one
          sy = sy0
        end if
        do i = 1, nDir
          old(i) = stress(i,k)
          stress(i,k) = zero
        end do
        fluxSlv(k) = zero
        fluxMst(k) = zero
        sed(k) = zero
        sfd(k) = zero
        scd(k) = zero
        spd(k) = zero
        svd(k) = zero
        if (bonded .gt. half) then
          trial = old(1) + e * drdisp(1,k) / thick
          f = abs(trial) - sy
          s = trial
          dep = zero
          synew = sy
          if (f .gt. zero) then
            dep = f / (e + hard)
            s = trial - sign(e * dep, trial)
            synew = sy + hard * dep
          end if
          stress(1,k) = s
          spd(k) = half * (sy + synew) * dep * thick
          tau2 = zero
          do i = 2, nDir
            tau = old(i) + g * drdisp(i,k) / thick
            stress(i,k) = tau
            tau2 = tau2 + tau * tau
          end do
          sed(k) = (s * s / (two * e) + tau2 / (two * g)) * thick
          if (nTemp .gt. 0) then
            if (perContact) then
              tm = tempMst(k)
            else
              tm = tempMst(1)
            end if
            q = cond * (tm - tempSlv(k)) / thick
            fluxSlv(k) = q
            fluxMst(k) = -q
          end if
          sy = synew
        end if
        statev(1,k) = ainit
        statev(2,k) = bonded
        statev(3,k) = sy
  100 continue
      return
      end
