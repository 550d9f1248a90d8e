C A linear penalty VUINTER written as for Abaqus/Explicit: upper-case include,
C tab-indented statements, lines past column 72, and the utility routines.
C   PROPS(1) normal stiffness K (stress per length): STRESS(1) = K RDISP(1) when
C            RDISP(1) > 0, else 0
C   PROPS(2) penetration limit: above it an error (XPLB_ABQERR, LOP = -2); 0: none
C   PROPS(3) 1: call VGETVRM (an error that ends the run)
C   PROPS(4) 1: call XPLB_ABQERR with LOP = -3 on the first contact
C On each contact's first call (STATEV(1) = 0) an information line reports what the
C utility routines answered: job name, rank count, rank, the part and local number of
C the slave node, and the DEM radius and mass from RS_GETDEM. A warning (LOP = -1) is
C written when the penetration passes half the limit.
C STATEV(1) = 1 once seen, STATEV(2) = rank, STATEV(3) = rank count,
C STATEV(4) = local number of the node, STATEV(5) = JRCD of VGETPARTINFO,
C STATEV(6) = length of the part name, STATEV(7:8) = DEM radius and mass,
C STATEV(9) = length of the job name, STATEV(10) = length of the output folder.
      SUBROUTINE VUINTER(
     1 SFD, SCD, SPD, SVD,
     2 STRESS, FLUXSLV, FLUXMST, SED, STATEV,
     3 KSTEP, KINC, NFACNOD, NSLVNOD, NMSTNOD, NSURFDIR,
     4 NDIR, NSTATEVAR, NPROPS, NTEMP, NPRED, NUMDEFTFV,
     5 JSLVUID, JMSTUID, JCONMSTID, TIMSTEP, TIMGLB,
     6 DTIMCUR, SURFINT, SURFSLV, SURFMST,
     7 RDISP, DRDISP, DROT, STIFFDFLT, CONDDFLT,
     8 SHAPE, COORDSLV, COORDMST, ALOCALDIR, PROPS,
     9 AREASLV, TEMPSLV, DTEMPSLV, PREDEFSLV, DPREDEFSLV,
     1 TEMPMST, DTEMPMST, PREDEFMST, DPREDEFMST)
      INCLUDE 'VABA_PARAM.INC'
      CHARACTER*80 SURFINT, SURFSLV, SURFMST, PARTNAME
      CHARACTER*256 JOBNAME, OUTDIR
      CHARACTER*8 CHARV(2)
      DIMENSION PROPS(NPROPS), STATEV(NSTATEVAR,NSLVNOD),
     1 STRESS(NDIR,NSLVNOD), RDISP(NDIR,NSLVNOD), SED(NSLVNOD),
     2 JSLVUID(NSLVNOD), INTV(4), REALV(2), DEMV(8), RDATA(1), JDATA(1)
	STIFF = PROPS(1)
	ALIMIT = PROPS(2)
	DO K = 1, NSLVNOD
	  H = RDISP(1,K)
	  IF (H .GT. 0.0D0 .AND. H .LT. 1.0D20) THEN
	    STRESS(1,K) = STIFF * H
	    SED(K) = 0.5D0 * STIFF * H * H
	  ELSE
	    STRESS(1,K) = 0.0D0
	    SED(K) = 0.0D0
	  END IF
	  STRESS(2,K) = 0.0D0
	  IF (NDIR .EQ. 3) STRESS(3,K) = 0.0D0
	  IF (STATEV(1,K) .EQ. 0.0D0 .AND. H .LT. 1.0D20) THEN
	    CALL VGETJOBNAME(JOBNAME, LENJOB)
	    CALL VGETOUTDIR(OUTDIR, LENOUT)
	    CALL VGETNUMCPUS(NCPUS)
	    CALL VGETRANK(KRANK)
	    CALL VGETPARTINFO(JSLVUID(K), 1, PARTNAME, LOCNUM, JRCD)
	    CALL RS_GETDEM(K, DEMV, JRCDDEM)
	    STATEV(1,K) = 1.0D0
	    STATEV(2,K) = KRANK
	    STATEV(3,K) = NCPUS
	    STATEV(4,K) = LOCNUM
	    STATEV(5,K) = JRCD
	    STATEV(6,K) = LEN_TRIM(PARTNAME)
	    STATEV(7,K) = DEMV(I_DEM_RADIUS)
	    STATEV(8,K) = DEMV(I_DEM_MASS)
	    STATEV(9,K) = LENJOB
	    STATEV(10,K) = LENOUT
	    CHARV(1) = JOBNAME(1:8)
	    CHARV(2) = PARTNAME(1:8)
	    INTV(1) = NCPUS
	    INTV(2) = KRANK
	    INTV(3) = LOCNUM
	    INTV(4) = JRCDDEM
	    REALV(1) = DEMV(I_DEM_RADIUS)
	    REALV(2) = DEMV(I_DEM_MASS)
	    CALL XPLB_ABQERR(1, 'job %S ranks %I rank %I part %S node %I dem %I radius %R mass %R',
     1    INTV, REALV, CHARV)
	    IF (PROPS(4) .EQ. 1.0D0) CALL XPLB_ABQERR(-3, 'stop now at node %I', LOCNUM, REALV, CHARV)
	  END IF
	  IF (ALIMIT .GT. 0.0D0 .AND. H .GT. 0.5D0 * ALIMIT .AND. H .LT. 1.0D20) THEN
	    INTV(1) = JSLVUID(K)
	    REALV(1) = H
	    REALV(2) = ALIMIT
	    IF (H .GT. ALIMIT) THEN
	      CALL XPLB_ABQERR(-2, 'penetration %R exceeds the limit %R at node %I', INTV, REALV, CHARV)
	    ELSE
	      CALL XPLB_ABQERR(-1, 'penetration %R is past half the limit %R at node %I', INTV, REALV, CHARV)
	    END IF
	  END IF
	  IF (PROPS(3) .EQ. 1.0D0) CALL VGETVRM('SDV', RDATA, JDATA, CHARV, JSTATUS)
	END DO
      RETURN
      END
