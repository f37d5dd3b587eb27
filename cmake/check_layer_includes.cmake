# Fails the build when a layer includes headers of a layer it must not depend on
# (../shared/STYLE.md: solvers -> scene -> manipulators -> ui -> app).
# Usage: cmake -DDIR=<source dir> -DFORBIDDEN=<regex> -DLAYER=<name> [-DEXCLUDE=<subdir>,..]
#        -P check_layer_includes.cmake
file(GLOB_RECURSE sources "${DIR}/*.h" "${DIR}/*.hpp" "${DIR}/*.cpp")
if(EXCLUDE)
  string(REPLACE "," ";" excluded "${EXCLUDE}")
  foreach(sub IN LISTS excluded)
    list(FILTER sources EXCLUDE REGEX "^${DIR}/${sub}/")
  endforeach()
endif()
set(violations "")
foreach(src IN LISTS sources)
  file(STRINGS "${src}" hits REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](${FORBIDDEN})")
  foreach(hit IN LISTS hits)
    string(APPEND violations "\n  ${src}: ${hit}")
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "The ${LAYER} layer must not include these headers:${violations}")
endif()
