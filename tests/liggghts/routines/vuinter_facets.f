C A linear penalty VUINTER on a faceted master that reports the facet under
C each contact (the facet arguments) in information lines, on increments 1
C and PROPS(2):
C   facet NODE K KINC NFACNOD NMSTNOD: the slave node, the increment, nFacNod
C     and nMstNod;
C   nodes NODE KINC: jMstUid(jConMstid(i,k)) and shape(i,k), i = 1..nFacNod;
C   coords NODE KINC I: coordMst(1:3, jConMstid(i,k)).
C PROPS(1) normal stiffness (stress per length). No shear.
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
      CHARACTER*80 SURFINT, SURFSLV, SURFMST
      CHARACTER*8 CHARV(1)
      DIMENSION PROPS(NPROPS), STRESS(NDIR,NSLVNOD), RDISP(NDIR,NSLVNOD),
     1 JSLVUID(NSLVNOD), JMSTUID(*), JCONMSTID(NFACNOD,NSLVNOD),
     2 SHAPE(NFACNOD,NSLVNOD), COORDMST(NDIR,*), INTV(12), REALV(4)
	DO K = 1, NSLVNOD
	  H = RDISP(1,K)
	  STRESS(1,K) = 0.0D0
	  IF (H .GT. 0.0D0 .AND. H .LT. 1.0D20) STRESS(1,K) = PROPS(1) * H
	  STRESS(2,K) = 0.0D0
	  STRESS(3,K) = 0.0D0
	  IF (KINC .EQ. 1 .OR. KINC .EQ. NINT(PROPS(2))) THEN
	    INTV(1) = JSLVUID(K)
	    INTV(2) = KINC
	    INTV(3) = NFACNOD
	    INTV(4) = NMSTNOD
	    CALL XPLB_ABQERR(1, 'facet %I %I %I %I', INTV, REALV, CHARV)
	    DO I = 1, NFACNOD
	      INTV(3) = I
	      INTV(4) = JMSTUID(JCONMSTID(I,K))
	      REALV(1) = SHAPE(I,K)
	      DO J = 1, 3
	        REALV(1 + J) = COORDMST(J, JCONMSTID(I,K))
	      END DO
	      CALL XPLB_ABQERR(1, 'node %I %I %I label %I shape %D at %D %D %D', INTV, REALV, CHARV)
	    END DO
	  END IF
	END DO
      RETURN
      END
