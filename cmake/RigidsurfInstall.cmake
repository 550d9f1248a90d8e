# Installation, in one place (included once at the end of the top-level CMakeLists.txt):
#   bin/                     liggghts-rigidsurf, lmp-rigidsurf, rigidsurf-frames,
#                            rigidsurf-build-law, rigidsurf-migrate
#   share/rigidsurf/         rigidsurf_migrate_*.py (rigidsurf-migrate's modules)
#   lib/                     librigidsurf.a, librigidsurf_abaqus.so, wallrigidplugin.so
#                            (LAMMPS's plugin load),
#                            cmake/rigidsurf/ (find_package(rigidsurf CONFIG):
#                            rigidsurf::rigidsurf), pkgconfig/rigidsurf.pc
#   include/rigidsurf/       the public C headers and the Fortran includes of user
#                            routines, lower- and upper-case (VABA_PARAM.INC, ABA_PARAM.INC)
#   share/doc/rigidsurf/     README.md, docs/, examples/
# (lib/ and the others as GNUInstallDirs names them.) The programs find
# librigidsurf_abaqus through their run path $ORIGIN/../lib, and the user-routine build
# (rigidsurf-build-law, `law vuinter FILE.f` in the fix) links the librigidsurf_abaqus
# the process has loaded and takes the Fortran includes from <its prefix>/include/
# rigidsurf (src/law_build.c). So an install works in any prefix, and moved, as it is.
include(CMakePackageConfigHelpers)

set(RS_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/rigidsurf)
set(RS_INSTALL_INCDIR ${CMAKE_INSTALL_INCLUDEDIR}/rigidsurf)

set(RS_INSTALL_PROGRAMS rigidsurf-frames rigidsurf-build-law)
if(RS_WITH_LIGGGHTS)
  list(APPEND RS_INSTALL_PROGRAMS liggghts-rigidsurf)
endif()
if(RS_WITH_LAMMPS)
  list(APPEND RS_INSTALL_PROGRAMS lmp-rigidsurf)
  # the plugin finds librigidsurf_abaqus beside itself
  set_target_properties(wallrigidplugin PROPERTIES INSTALL_RPATH "$ORIGIN")
  install(TARGETS wallrigidplugin LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
set_target_properties(${RS_INSTALL_PROGRAMS} PROPERTIES
  INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")

# ---- Libraries and the CMake package ---------------------------------------------------
install(TARGETS rigidsurf rigidsurf_abaqus EXPORT rigidsurfTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT rigidsurfTargets NAMESPACE rigidsurf:: FILE rigidsurfTargets.cmake
  DESTINATION ${RS_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rigidsurfConfig.cmake.in
  ${PROJECT_BINARY_DIR}/rigidsurfConfig.cmake
  INSTALL_DESTINATION ${RS_INSTALL_CMAKEDIR}
  PATH_VARS RS_INSTALL_INCDIR CMAKE_INSTALL_BINDIR)
# 0.x: a minor release may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rigidsurfConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rigidsurfConfig.cmake
  ${PROJECT_BINARY_DIR}/rigidsurfConfigVersion.cmake DESTINATION ${RS_INSTALL_CMAKEDIR})

# ---- pkg-config ---------------------------------------------------------------------
# The file finds the prefix from where it lies (${pcfiledir}), so it stays right when the
# install is moved or made with `cmake --install --prefix`.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(RS_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH RS_PC_UP /rs/${CMAKE_INSTALL_LIBDIR}/pkgconfig /rs)
  string(REGEX REPLACE "/$" "" RS_PC_UP "${RS_PC_UP}")
  set(RS_PC_PREFIX "\${pcfiledir}/${RS_PC_UP}")
endif()
foreach(dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
    set(RS_PC_${dir} "${CMAKE_INSTALL_${dir}}")
  else()
    set(RS_PC_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
  endif()
endforeach()
set(RS_PC_DL "")
foreach(lib ${CMAKE_DL_LIBS})
  string(APPEND RS_PC_DL " -l${lib}")
endforeach()
configure_file(${CMAKE_CURRENT_LIST_DIR}/rigidsurf.pc.in ${PROJECT_BINARY_DIR}/rigidsurf.pc
  @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/rigidsurf.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# ---- Headers --------------------------------------------------------------------------
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/rigidsurf
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
# Abaqus routines write INCLUDE 'VABA_PARAM.INC' (or 'ABA_PARAM.INC'), older examples the
# lower-case names; a case-sensitive file system needs both.
foreach(inc vaba_param aba_param)
  string(TOUPPER ${inc} INC)
  install(FILES ${PROJECT_SOURCE_DIR}/src/${inc}.inc DESTINATION ${RS_INSTALL_INCDIR})
  install(FILES ${PROJECT_SOURCE_DIR}/src/${inc}.inc DESTINATION ${RS_INSTALL_INCDIR}
    RENAME ${INC}.INC)
endforeach()

# ---- Programs -------------------------------------------------------------------------
install(TARGETS ${RS_INSTALL_PROGRAMS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(PROGRAMS ${PROJECT_SOURCE_DIR}/src/cli/rigidsurf_migrate.py
  DESTINATION ${CMAKE_INSTALL_BINDIR} RENAME rigidsurf-migrate)
# its modules, where it looks for them: ../share/rigidsurf from bin/
install(FILES ${RS_MIGRATE_MODULES} DESTINATION share/rigidsurf)

# ---- Docs and examples ------------------------------------------------------------------
# README.md beside docs/ and examples/, so that its relative links hold.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
  FILES_MATCHING PATTERN "*.md")
# The examples' sources only: not their outputs (out/), nor the CTest file
# examples/CMakeLists.txt (examples/coupling/CMakeLists.txt builds that example against
# the installed package, and is installed with it).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
  USE_SOURCE_PERMISSIONS
  PATTERN out EXCLUDE
  PATTERN __pycache__ EXCLUDE
  PATTERN .gitignore EXCLUDE
  REGEX "/examples/CMakeLists\\.txt$" EXCLUDE
  REGEX "\\.(vtk|png|so|o)$" EXCLUDE
  PATTERN log.liggghts EXCLUDE)
