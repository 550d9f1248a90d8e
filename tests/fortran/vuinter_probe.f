! ABI probe: a VUINTER that records what it was handed, to pin the argument order,
! the hidden CHARACTER*80 lengths and the DEM fields passed as predefined fields.
!   statev(1:8,k)  = preDefSlv(1:8,k)  (i_dem_radius .. i_dem_curv2)
!   statev(9,k)    = len_trim(surfInt), statev(10,k) = len(surfMst)
!   statev(11,k)   = nPred, statev(12,k) = dTimCur, statev(13,k) = stiffDflt(k)
!   statev(14,k)   = tempMst(1), statev(15,k) = jSlvUid(k)
!   stress(:,k)    = rdisp(:,k); sfd(k) = areaSlv(k); svd(k) = props(nProps)
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
      do k = 1, nSlvNod
        do i = 1, min(nPred, n_dem_pred)
          statev(i,k) = preDefSlv(i,k)
        end do
        statev(9,k) = len_trim(surfInt)
        statev(10,k) = len(surfMst)
        statev(11,k) = nPred
        statev(12,k) = dTimCur
        statev(13,k) = stiffDflt(k)
        statev(14,k) = tempMst(1)
        statev(15,k) = jSlvUid(k)
        do i = 1, nDir
          stress(i,k) = rdisp(i,k)
        end do
        sfd(k) = areaSlv(k)
        svd(k) = props(nProps)
      end do
      return
      end
