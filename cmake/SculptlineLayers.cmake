# sculptline_forbid_includes(<target> <regex>): every build of <target> first scans its source
# directory and fails on an #include matching <regex>. System headers such as Coin's live on the
# default include path, so only a scan can make a wrong include fail to build.
# Optional EXCLUDE <subdir>..: subdirectories (relative to the source directory) that are their own
# target with their own check (solvers/volume may include OpenVDB, the rest of solvers may not).
function(sculptline_forbid_includes target regex)
  cmake_parse_arguments(ARG "" "" "EXCLUDE" ${ARGN})
  set(check ${target}_layer_check)
  string(REPLACE ";" "," excluded "${ARG_EXCLUDE}")
  add_custom_target(${check}
    COMMAND ${CMAKE_COMMAND} -DDIR=${CMAKE_CURRENT_SOURCE_DIR} -DFORBIDDEN=${regex} -DLAYER=${target}
            -DEXCLUDE=${excluded}
            -P ${PROJECT_SOURCE_DIR}/cmake/check_layer_includes.cmake
    COMMENT "Checking that ${target} includes only what its layer may use"
    VERBATIM)
  add_dependencies(${target} ${check})
endfunction()
