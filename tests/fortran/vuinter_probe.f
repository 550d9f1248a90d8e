! ABI probe: a VUINTER that records what it was handed, to pin the argument order,
! the hidden CHARACTER*80 lengths, the Abaqus integers and the DEM data that the
! utility routine RS_GETDEM returns.
!   statev(1:8,k)  = RS_GETDEM(k) (i_dem_radius .. i_dem_curv2)
!   statev(9,k)    = len_trim(surfInt), statev(10,k) = len(surfMst)
!   statev(11,k)   = nPred, statev(12,k) = dTimCur, statev(13,k) = stiffDflt(k)
!   statev(14,k)   = tempMst(1), statev(15,k) = jSlvUid(k)
!   statev(16,k)   = nFacNod, statev(17,k) = nMstNod, statev(18,k) = numDefTfv
!   statev(19,k)   = fluxSlv(k), statev(20,k) = fluxMst(k), statev(21,k) = sed(k)
!                    on entry
!   statev(22,k)   = kStep, statev(23,k) = kInc, statev(24,k) = timStep,
!   statev(25,k)   = timGlb, statev(26,k) = preDefSlv(1,k) (0 when nPred = 0),
!   statev(27,k)   = jrcd of RS_GETDEM
!   stress(:,k)    = rdisp(:,k); sfd(k) = areaSlv(k); svd(k) = props(nProps)
!   fluxSlv(k) = fluxSlv(k) + props(1), fluxMst(k) = fluxMst(k) - props(1),
!   sed(k) = sed(k) + props(2): each increment adds to what it was handed
      subroutine vuinter(
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
      dimension demv(n_dem_pred)
      do k = 1, nSlvNod
        call rs_getdem(k, demv, jrcd)
        do i = 1, n_dem_pred
          statev(i,k) = demv(i)
        end do
        statev(9,k) = len_trim(surfInt)
        statev(10,k) = len(surfMst)
        statev(11,k) = nPred
        statev(12,k) = dTimCur
        statev(13,k) = stiffDflt(k)
        statev(14,k) = tempMst(1)
        statev(15,k) = jSlvUid(k)
        statev(16,k) = nFacNod
        statev(17,k) = nMstNod
        statev(18,k) = numDefTfv
        statev(19,k) = fluxSlv(k)
        statev(20,k) = fluxMst(k)
        statev(21,k) = sed(k)
        statev(22,k) = kStep
        statev(23,k) = kInc
        statev(24,k) = timStep
        statev(25,k) = timGlb
        statev(26,k) = 0.d0
        if (nPred .ge. 1) statev(26,k) = preDefSlv(1,k)
        statev(27,k) = jrcd
        do i = 1, nDir
          stress(i,k) = rdisp(i,k)
        end do
        sfd(k) = areaSlv(k)
        svd(k) = props(nProps)
        fluxSlv(k) = fluxSlv(k) + props(1)
        fluxMst(k) = fluxMst(k) - props(1)
        sed(k) = sed(k) + props(2)
      end do
      return
      end
