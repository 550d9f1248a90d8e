! Coulomb friction as an Abaqus/Standard FRIC, built against aba_param.inc.
!   props(1) mu, props(2) k_stick (elastic stick stiffness, stress per length),
!   props(3) mode: 0 Coulomb (LM = 0), 1 rigid stick (LM = 1),
!                  2 frictionless (LM = 2),
!   props(4) pmax: PNEWDT = 0.5 when PRESS > pmax (0: never).
! Coulomb: trial TAU + k_stick DGAM, capped at mu PRESS; the slip beyond the
! elastic limit is DSLIP; SFD = mu PRESS |DSLIP|; SED = |TAU|^2 / (2 k_stick).
! statev(1) = LM as passed in (if nstatv >= 1).
      SUBROUTINE FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,
     1 DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,
     2 KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,
     3 NPATCH,COORDS,RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,
     4 NSTATV,CHRLNGTH,PROPS,NPROPS)
      INCLUDE 'aba_param.inc'
      CHARACTER*80 CINAME,SLNAME,MSNAME
      DIMENSION TAU(NFDIR),DDTDDG(NFDIR,NFDIR),DDTDDP(NFDIR),
     1 DSLIP(NFDIR),DDTDDT(NFDIR,2),STATEV(*),DGAM(NFDIR),
     2 TAULM(NFDIR),SLIP(NFDIR),TIME(2),COORDS(MCRD),
     3 RCOORD(MCRD),DROT(2,2),TEMP(2),PREDEF(2,*),PROPS(NPROPS)
      DIMENSION TRIAL(2)
      PARAMETER (ZERO=0.D0, HALF=0.5D0, TWO=2.D0)
      AMU = PROPS(1)
      AKS = PROPS(2)
      MODE = NINT(PROPS(3))
      PMAX = PROPS(4)
      IF (NSTATV .GE. 1) STATEV(1) = LM
      IF (PMAX .GT. ZERO .AND. PRESS .GT. PMAX) PNEWDT = HALF
      IF (MODE .EQ. 1) THEN
        LM = 1
        RETURN
      ELSE IF (MODE .EQ. 2) THEN
        LM = 2
        RETURN
      END IF
      LM = 0
      AMAG = ZERO
      DO I = 1, NFDIR
        TRIAL(I) = TAU(I) + AKS * DGAM(I)
        AMAG = AMAG + TRIAL(I) * TRIAL(I)
        DO J = 1, NFDIR
          DDTDDG(I,J) = ZERO
        END DO
        DDTDDP(I) = ZERO
        DSLIP(I) = ZERO
      END DO
      AMAG = SQRT(AMAG)
      ALIM = AMU * PRESS
      SFD = ZERO
      IF (AMAG .GT. ALIM) THEN
        RATIO = ALIM / AMAG
        DO I = 1, NFDIR
          TAU(I) = TRIAL(I) * RATIO
          DSLIP(I) = TRIAL(I) / AMAG * (AMAG - ALIM) / AKS
          DDTDDP(I) = AMU * TRIAL(I) / AMAG
        END DO
        SFD = ALIM * (AMAG - ALIM) / AKS
      ELSE
        DO I = 1, NFDIR
          TAU(I) = TRIAL(I)
          DDTDDG(I,I) = AKS
        END DO
      END IF
      SED = ZERO
      DO I = 1, NFDIR
        SED = SED + TAU(I) * TAU(I)
      END DO
      SED = SED / (TWO * AKS)
      RETURN
      END
