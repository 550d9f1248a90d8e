! Penalty hard contact as an Abaqus/Standard UINTER (current argument list, with
! DVISCOUS, DSTRUCTURAL and FREQR), built against aba_param.inc.
!   props(1) k: stress(1) = k h for the overclosure h = rdisp(1) > 0, 0 when open;
!               frictionless. k = 0 leaves stress(1) as passed in (the engine's
!               normal law decides).
!   props(2) hmax: PNEWDT = 0.5 when h > hmax (0: never).
!   props(3) hc: conductance per area, flux(1) = hc (T_mst - T_slv) at the end of
!               the increment, flux(2) = -flux(1).
! Status flags: LOPENCLOSE = 1 closed / 0 open; LSTATE counts open -> closed
! changes; LSDI = 1 when the status changes.
! statev(1) = LSTATE, statev(2) = LOPENCLOSE as passed in (if nstatv >= 2).
      SUBROUTINE UINTER(STRESS,DDSDDR,DVISCOUS,DSTRUCTURAL,FLUX,DDFDDT,
     1 DDSDDT,DDFDDR,STATEV,SED,SFD,SPD,SVD,SCD,PNEWDT,RDISP,
     2 DRDISP,
     3 TEMP,DTEMP,PREDEF,DPRED,TIME,DTIME,FREQR,CINAME,SLNAME,
     4 MSNAME,
     5 PROPS,COORDS,ALOCALDIR,DROT,AREA,CHRLNGTH,NODE,NDIR,NSTATV,
     6 NPRED,NPROPS,MCRD,KSTEP,KINC,KIT,LINPER,LOPENCLOSE,LSTATE,
     7 LSDI,LPRINT)
      INCLUDE 'aba_param.inc'
      CHARACTER*80 CINAME,SLNAME,MSNAME
      DIMENSION STRESS(NDIR),DDSDDR(NDIR,NDIR),FLUX(2),DDFDDT(2,2),
     1 DDSDDT(NDIR,2),DDFDDR(2,NDIR),STATEV(NSTATV),
     2 RDISP(NDIR),DRDISP(NDIR),TEMP(2),DTEMP(2),PREDEF(2,NPRED),
     3 DPRED(2,NPRED),TIME(2),PROPS(NPROPS),COORDS(MCRD),
     4 ALOCALDIR(3,3),DROT(2,2),DVISCOUS(NDIR,NDIR),
     5 DSTRUCTURAL(NDIR,NDIR)
      CALL PENALTY(STRESS,DDSDDR,FLUX,STATEV,SED,PNEWDT,RDISP,TEMP,
     1 DTEMP,PROPS,NDIR,NSTATV,NPROPS,LOPENCLOSE,LSTATE,LSDI)
      RETURN
      END
