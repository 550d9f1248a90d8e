! Argument probe: a FRIC that records what it was handed and returns what its
! properties ask, built against aba_param.inc.
!   props(1) MODE: -1 exits at once when LM = 2 (as the FRIC manual advises),
!                  else returns LM = 0 with the shear props(2) along t1;
!                  0, 1, 2 returns that LM (0: shear props(2) along t1).
!   With LM = 0 returned: DSLIP = DGAM; SFD = props(3); DDTDDG(1,1) = props(5).
!   props(4): PNEWDT returned when > 0.
! statev(1) = LM, statev(2:3) = DGAM, statev(4:5) = TAULM, statev(6) = PRESS,
! statev(7) = DPRESS, statev(8) = DDPDDH, statev(9:10) = SLIP, statev(11) = KSTEP,
! statev(12) = KINC, statev(13:14) = TIME, statev(15) = NPRED,
! statev(16:17) = TAU, statev(18) = DTIME, all as passed in; statev(19) counts
! the calls.
      SUBROUTINE FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,
     1 DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,
     2 KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,
     3 NPATCH,COORDS,RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,
     4 NSTATV,CHRLNGTH,PROPS,NPROPS)
      INCLUDE 'aba_param.inc'
      CHARACTER*80 CINAME,SLNAME,MSNAME
      DIMENSION TAU(NFDIR),DDTDDG(NFDIR,NFDIR),DDTDDP(NFDIR),
     1 DSLIP(NFDIR),DDTDDT(NFDIR,2),STATEV(NSTATV),DGAM(NFDIR),
     2 TAULM(NFDIR),SLIP(NFDIR),TIME(2),COORDS(MCRD),
     3 RCOORD(MCRD),DROT(2,2),TEMP(2),PREDEF(2,*),PROPS(NPROPS)
      PARAMETER (ZERO=0.D0)
      STATEV(1) = LM
      DO I = 1, 2
        STATEV(1+I) = ZERO
        STATEV(3+I) = ZERO
        STATEV(8+I) = ZERO
        STATEV(15+I) = ZERO
      END DO
      DO I = 1, NFDIR
        STATEV(1+I) = DGAM(I)
        STATEV(3+I) = TAULM(I)
        STATEV(8+I) = SLIP(I)
        STATEV(15+I) = TAU(I)
      END DO
      STATEV(6) = PRESS
      STATEV(7) = DPRESS
      STATEV(8) = DDPDDH
      STATEV(11) = KSTEP
      STATEV(12) = KINC
      STATEV(13) = TIME(1)
      STATEV(14) = TIME(2)
      STATEV(15) = NPRED
      STATEV(18) = DTIME
      STATEV(19) = STATEV(19) + 1.D0
      IF (PROPS(4) .GT. ZERO) PNEWDT = PROPS(4)
      MODE = NINT(PROPS(1))
      IF (MODE .EQ. -1) THEN
        IF (LM .EQ. 2) RETURN
        MODE = 0
      END IF
      LM = MODE
      IF (MODE .NE. 0) RETURN
      DO I = 1, NFDIR
        TAU(I) = ZERO
        DSLIP(I) = DGAM(I)
      END DO
      TAU(1) = PROPS(2)
      SFD = PROPS(3)
      DDTDDG(1,1) = PROPS(5)
      RETURN
      END
