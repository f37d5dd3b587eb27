# OpenCASCADE (Debian 12: libocct-*-dev 7.6.3, scripts/debian-packages.txt), found in one place for
# every target that uses it: the imported target Sculptline::OpenCascade, with the headers as a
# system include directory and the toolkits linked by file. OCCT's own CMake targets are not used:
# their interface names /usr/lib/.../libtbb.so, the -dev symlink of a package OCCT's shared
# libraries do not need at link time (they carry their own dependencies).
#
# SCULPTLINE_OCCT_TOOLKITS lists the toolkits: geometry (TKernel..TKGeomAlgo), topology for the
# exchange's edges and faces (TKBRep, TKTopAlgo), and the STEP/IGES translators (TKXSBase..TKIGES).
set(SCULPTLINE_OCCT_TOOLKITS
  TKSTEP TKSTEPBase TKSTEPAttr TKSTEP209 TKIGES TKXSBase
  TKTopAlgo TKBRep TKGeomAlgo TKGeomBase TKG3d TKG2d TKMath TKernel)

find_path(SCULPTLINE_OCCT_INCLUDE_DIR Standard_Version.hxx PATH_SUFFIXES opencascade)
set(_sculptline_occt_libs)
set(_sculptline_occt_missing)
foreach(_tk ${SCULPTLINE_OCCT_TOOLKITS})
  find_library(SCULPTLINE_OCCT_${_tk} ${_tk})
  if(SCULPTLINE_OCCT_${_tk})
    list(APPEND _sculptline_occt_libs ${SCULPTLINE_OCCT_${_tk}})
  else()
    list(APPEND _sculptline_occt_missing ${_tk})
  endif()
endforeach()

if(SCULPTLINE_OCCT_INCLUDE_DIR AND NOT _sculptline_occt_missing)
  add_library(Sculptline::OpenCascade INTERFACE IMPORTED)
  target_include_directories(Sculptline::OpenCascade SYSTEM INTERFACE ${SCULPTLINE_OCCT_INCLUDE_DIR})
  target_link_libraries(Sculptline::OpenCascade INTERFACE ${_sculptline_occt_libs})
  set(SCULPTLINE_HAVE_OCCT TRUE)
else()
  set(SCULPTLINE_HAVE_OCCT FALSE)
  message(FATAL_ERROR "OpenCASCADE not found (headers: ${SCULPTLINE_OCCT_INCLUDE_DIR}; missing toolkits: "
                      "${_sculptline_occt_missing}). Install libocct-data-exchange-dev (scripts/debian-packages.txt).")
endif()
