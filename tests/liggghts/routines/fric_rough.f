C A perfectly rough interface as an Abaqus/Standard FRIC: no relative
C tangential motion at any closed contact (LM = 1 on every call; the shear is
C the constraint stress TAULM that the solver computes). No properties, no
C state variables. On the first increment of a step the routine reports the
C number of processes (GETNUMCPUS) in an information line (XPLB_ABQERR).
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
      DIMENSION INTV(2), REALV(1)
      CHARACTER*8 CHARV(1)
	LM = 1
	IF (KINC .EQ. 1) THEN
	  CALL GETNUMCPUS(NCPUS)
	  INTV(1) = NODE
	  INTV(2) = NCPUS
	  CALL XPLB_ABQERR(1, 'perfectly rough friction at node %I, first increment, %I processes', INTV, REALV, CHARV)
	END IF
      RETURN
      END
