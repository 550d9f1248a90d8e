C Coulomb friction as an Abaqus/Standard FRIC with an elastic stick.
C   PROPS(1) friction coefficient MU
C   PROPS(2) stick stiffness AKS (shear stress per unit slip)
C   STATEV(1) 1 once the contact has been reported
C The trial shear TAU + AKS DGAM is capped at MU PRESS; the slip beyond the
C elastic limit is DSLIP. An open contact (LM = 2 on entry) carries no shear:
C the routine returns at once, as the FRIC manual advises. The first call of
C a closed contact writes an information line (XPLB_ABQERR, LOP = 1).
      SUBROUTINE FRIC(LM,TAU,DDTDDG,DDTDDP,DSLIP,SED,SFD,
     1 DDTDDT,PNEWDT,STATEV,DGAM,TAULM,PRESS,DPRESS,DDPDDH,SLIP,
     2 KSTEP,KINC,TIME,DTIME,NOEL,CINAME,SLNAME,MSNAME,NPT,NODE,
     3 NPATCH,COORDS,RCOORD,DROT,TEMP,PREDEF,NFDIR,MCRD,NPRED,
     4 NSTATV,CHRLNGTH,PROPS,NPROPS)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*80 CINAME,SLNAME,MSNAME
      DIMENSION TAU(NFDIR),DDTDDG(NFDIR,NFDIR),DDTDDP(NFDIR),
     1 DSLIP(NFDIR),DDTDDT(NFDIR,2),STATEV(*),DGAM(NFDIR),
     2 TAULM(NFDIR),SLIP(NFDIR),TIME(2),COORDS(MCRD),
     3 RCOORD(MCRD),DROT(2,2),TEMP(2),PREDEF(2,*),PROPS(NPROPS)
      DIMENSION TRIAL(2), INTV(1), REALV(3)
      CHARACTER*8 CHARV(1)
      PARAMETER (ZERO=0.D0, ONE=1.D0, TWO=2.D0)
	IF (LM .EQ. 2) RETURN
	AMU = PROPS(1)
	AKS = PROPS(2)
	LM = 0
	IF (STATEV(1) .EQ. ZERO) THEN
	  STATEV(1) = ONE
	  INTV(1) = NODE
	  REALV(1) = PRESS
	  REALV(2) = AMU
	  REALV(3) = AKS
	  CHARV(1) = 'COULOMB'
	  CALL XPLB_ABQERR(1, '%S friction at node %I: pressure %R, mu %R, stick stiffness %R', INTV, REALV, CHARV)
	END IF
	AMAG = ZERO
	DO I = 1, NFDIR
	  TRIAL(I) = TAU(I) + AKS * DGAM(I)
	  AMAG = AMAG + TRIAL(I) * TRIAL(I)
	  DDTDDP(I) = ZERO
	  DSLIP(I) = ZERO
	  DO J = 1, NFDIR
	    DDTDDG(I,J) = ZERO
	  END DO
	END DO
	AMAG = SQRT(AMAG)
	ALIM = AMU * PRESS
	SFD = ZERO
	IF (AMAG .GT. ALIM) THEN
	  DO I = 1, NFDIR
	    TAU(I) = TRIAL(I) * (ALIM / AMAG)
	    DSLIP(I) = TRIAL(I) / AMAG * (AMAG - ALIM) / AKS
	    DDTDDP(I) = AMU * TRIAL(I) / AMAG
	    DO J = 1, NFDIR
	      DDTDDG(I,J) = -AKS * (ALIM / AMAG) * TRIAL(I) * TRIAL(J) / (AMAG * AMAG)
	    END DO
	    DDTDDG(I,I) = DDTDDG(I,I) + AKS * (ALIM / AMAG)
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
