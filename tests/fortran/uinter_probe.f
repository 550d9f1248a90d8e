! Argument probe: a UINTER (current argument list) that records what it was
! handed, built against aba_param.inc. Its shear is an elastic spring on the
! slip increment, so it grows only if STRESS(2:NDIR) persists between increments:
!   STRESS(I) = STRESS(I) + props(1) DRDISP(I), I = 2..NDIR (STRESS(1) kept);
!   FLUX(1) = FLUX(1) + props(2), FLUX(2) = FLUX(2) - props(2);
!   PNEWDT = props(3) when props(3) > 0.
! statev(1:3) = STRESS, statev(4:5) = FLUX, statev(6) = KSTEP, statev(7) = KINC,
! statev(8:9) = TIME, statev(10) = NPRED, all as passed in; statev(11) counts
! the calls.
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
     2 RDISP(NDIR),DRDISP(NDIR),TEMP(2),DTEMP(2),PREDEF(2,*),
     3 DPRED(2,*),TIME(2),PROPS(NPROPS),COORDS(MCRD),
     4 ALOCALDIR(3,3),DROT(2,2),DVISCOUS(NDIR,NDIR),
     5 DSTRUCTURAL(NDIR,NDIR)
      PARAMETER (ZERO=0.D0)
      STATEV(3) = ZERO
      DO I = 1, NDIR
        STATEV(I) = STRESS(I)
      END DO
      STATEV(4) = FLUX(1)
      STATEV(5) = FLUX(2)
      STATEV(6) = KSTEP
      STATEV(7) = KINC
      STATEV(8) = TIME(1)
      STATEV(9) = TIME(2)
      STATEV(10) = NPRED
      STATEV(11) = STATEV(11) + 1.D0
      DO I = 2, NDIR
        STRESS(I) = STRESS(I) + PROPS(1) * DRDISP(I)
      END DO
      FLUX(1) = FLUX(1) + PROPS(2)
      FLUX(2) = FLUX(2) - PROPS(2)
      IF (PROPS(3) .GT. ZERO) PNEWDT = PROPS(3)
      RETURN
      END
