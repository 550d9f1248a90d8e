! Penalty hard contact shared by uinter_penalty.f and uinter_v6_penalty.f (see there).
      SUBROUTINE PENALTY(STRESS,DDSDDR,FLUX,STATEV,SED,PNEWDT,RDISP,
     1 TEMP,DTEMP,PROPS,NDIR,NSTATV,NPROPS,LOPENCLOSE,LSTATE,LSDI)
      INCLUDE 'aba_param.inc'
      DIMENSION STRESS(NDIR),DDSDDR(NDIR,NDIR),FLUX(2),STATEV(NSTATV),
     1 RDISP(NDIR),TEMP(2),DTEMP(2),PROPS(NPROPS)
      PARAMETER (ZERO=0.D0, HALF=0.5D0)
      AK = PROPS(1)
      HMAX = PROPS(2)
      HC = PROPS(3)
      H = RDISP(1)
      LIN = LOPENCLOSE
      IF (NSTATV .GE. 2) STATEV(2) = LIN
      IF (AK .GT. ZERO) THEN
        DO I = 1, NDIR
          STRESS(I) = ZERO
          DO J = 1, NDIR
            DDSDDR(I,J) = ZERO
          END DO
        END DO
        IF (H .GT. ZERO) THEN
          STRESS(1) = AK * H
          DDSDDR(1,1) = AK
          SED = HALF * AK * H * H
          LOPENCLOSE = 1
        ELSE
          SED = ZERO
          LOPENCLOSE = 0
        END IF
        IF (LOPENCLOSE .EQ. 1 .AND. LIN .NE. 1) LSTATE = LSTATE + 1
        IF (LIN .GE. 0 .AND. LOPENCLOSE .NE. LIN) LSDI = 1
      END IF
      IF (NSTATV .GE. 1) STATEV(1) = LSTATE
      IF (HMAX .GT. ZERO .AND. H .GT. HMAX) PNEWDT = HALF
      Q = HC * ((TEMP(2) + DTEMP(2)) - (TEMP(1) + DTEMP(1)))
      FLUX(1) = Q
      FLUX(2) = -Q
      RETURN
      END
