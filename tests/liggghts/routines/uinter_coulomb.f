C Coulomb friction as an Abaqus/Standard UINTER, for use with a separate
C normal law: STRESS(1) on entry is the contact pressure, and only the shear
C STRESS(2:NDIR) is computed here (STRESS(1) is returned unchanged).
C   PROPS(1) friction coefficient MU
C   PROPS(2) stick stiffness AKS (shear stress per unit slip)
C   STATEV(1) 1 once the contact has been reported
C   STATEV(2) accumulated frictional slip (length of the slip path)
C Elastic stick: the trial shear STRESS(2:NDIR) + AKS DRDISP(2:NDIR) is
C capped at MU STRESS(1). An open contact (RDISP(1) <= 0) carries no shear.
C The first call of a closed contact writes an information line
C (XPLB_ABQERR, LOP = 1).
      SUBROUTINE UINTER(STRESS,DDSDDR,DVISCOUS,DSTRUCTURAL,FLUX,DDFDDT,
     1 DDSDDT,DDFDDR,STATEV,SED,SFD,SPD,SVD,SCD,PNEWDT,RDISP,DRDISP,
     2 TEMP,DTEMP,PREDEF,DPRED,TIME,DTIME,FREQR,CINAME,SLNAME,MSNAME,
     3 PROPS,COORDS,ALOCALDIR,DROT,AREA,CHRLNGTH,NODE,NDIR,NSTATV,
     4 NPRED,NPROPS,MCRD,KSTEP,KINC,KIT,LINPER,LOPENCLOSE,LSTATE,LSDI,
     5 LPRINT)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*80 CINAME,SLNAME,MSNAME
      DIMENSION STRESS(NDIR),DDSDDR(NDIR,NDIR),FLUX(2),DDFDDT(2,2),
     1 DDSDDT(NDIR,2),DDFDDR(2,NDIR),STATEV(NSTATV),
     2 RDISP(NDIR),DRDISP(NDIR),TEMP(2),DTEMP(2),PREDEF(2,*),
     3 DPRED(2,*),TIME(2),PROPS(NPROPS),COORDS(MCRD),
     4 ALOCALDIR(3,3),DROT(2,2),DVISCOUS(NDIR,NDIR),
     5 DSTRUCTURAL(NDIR,NDIR)
      DIMENSION TRIAL(3), INTV(2), REALV(3)
      CHARACTER*8 CHARV(1)
      PARAMETER (ZERO=0.D0, ONE=1.D0, TWO=2.D0)
	AMU = PROPS(1)
	AKS = PROPS(2)
	PRESS = STRESS(1)
	SFD = ZERO
	SED = ZERO
	DO I = 2, NDIR
	  DO J = 2, NDIR
	    DDSDDR(I,J) = ZERO
	  END DO
	END DO
	IF (RDISP(1) .LE. ZERO .OR. PRESS .LE. ZERO) THEN
	  DO I = 2, NDIR
	    STRESS(I) = ZERO
	  END DO
	  LOPENCLOSE = 0
	  RETURN
	END IF
	LOPENCLOSE = 1
	IF (STATEV(1) .EQ. ZERO) THEN
	  STATEV(1) = ONE
	  INTV(1) = NODE
	  INTV(2) = KINC
	  REALV(1) = PRESS
	  REALV(2) = AMU
	  REALV(3) = AKS
	  CHARV(1) = 'COULOMB'
	  CALL XPLB_ABQERR(1, '%S shear at node %I from increment %I: pressure %R, mu %R, stick stiffness %R', INTV, REALV, CHARV)
	END IF
	AMAG = ZERO
	DO I = 2, NDIR
	  TRIAL(I) = STRESS(I) + AKS * DRDISP(I)
	  AMAG = AMAG + TRIAL(I) * TRIAL(I)
	END DO
	AMAG = SQRT(AMAG)
	ALIM = AMU * PRESS
	IF (AMAG .GT. ALIM) THEN
	  LSTATE = 2
	  DO I = 2, NDIR
	    STRESS(I) = TRIAL(I) * (ALIM / AMAG)
	    DO J = 2, NDIR
	      DDSDDR(I,J) = -AKS * (ALIM / AMAG) * TRIAL(I) * TRIAL(J) / (AMAG * AMAG)
	    END DO
	    DDSDDR(I,I) = DDSDDR(I,I) + AKS * (ALIM / AMAG)
	  END DO
	  SFD = ALIM * (AMAG - ALIM) / AKS
	  STATEV(2) = STATEV(2) + (AMAG - ALIM) / AKS
	ELSE
	  LSTATE = 1
	  DO I = 2, NDIR
	    STRESS(I) = TRIAL(I)
	    DDSDDR(I,I) = AKS
	  END DO
	END IF
	DO I = 2, NDIR
	  SED = SED + STRESS(I) * STRESS(I)
	END DO
	SED = SED / (TWO * AKS)
      RETURN
      END
