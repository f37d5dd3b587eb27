# sculptline_forbid_includes(<target> <regex>): every build of <target> first scans its source
# directory and fails on an #include matching <regex>. System headers such as Coin's live on the
# default include path, so only a scan can make a wrong include fail to build.
function(sculptline_forbid_includes target regex)
  set(check ${target}_layer_check)
  add_custom_target(${check}
    COMMAND ${CMAKE_COMMAND} -DDIR=${CMAKE_CURRENT_SOURCE_DIR} -DFORBIDDEN=${regex} -DLAYER=${target}
            -P ${PROJECT_SOURCE_DIR}/cmake/check_layer_includes.cmake
    COMMENT "Checking that ${target} includes only what its layer may use"
    VERBATIM)
  add_dependencies(${target} ${check})
endfunction()
