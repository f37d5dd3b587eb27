# Sanitizer and fuzzing instrumentation, attached to sculptline_warnings (which every Sculptline
# target links), so it reaches every translation unit and every link of an executable.
#
# SCULPTLINE_SANITIZE (scripts/sanitize.sh, CI): AddressSanitizer and UndefinedBehaviorSanitizer, with
# -fno-sanitize-recover=all so that the first report aborts the program and fails its test, and
# _GLIBCXX_ASSERTIONS (bounds-checked operator[] and friends in libstdc++).
# SCULPTLINE_FUZZ (clang only): coverage instrumentation for libFuzzer in every library; the fuzz/
# programs then link libFuzzer's main (fuzz/CMakeLists.txt). Without it they are corpus-replay programs.
if(SCULPTLINE_SANITIZE)
  target_compile_options(sculptline_warnings INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
    # The ASan documentation recommends -O1 for "reasonable performance"; at -O0 Eigen's expression
    # templates are not inlined and the numeric tests run tens of times slower.
    $<$<CONFIG:Debug>:-O1>
    # Line tables are all a sanitizer report or a debugger backtrace needs (file:line per frame); full
    # -g made every fuzz program, a whole CLI linked statically, 282 MB, and the build 11 GB, enough to
    # fill the disk of a CI machine (stop 25's CI run). With clang the last -g option wins.
    $<$<AND:$<CONFIG:Debug>,$<CXX_COMPILER_ID:Clang>>:-gline-tables-only>)
  target_compile_definitions(sculptline_warnings INTERFACE _GLIBCXX_ASSERTIONS)
  target_link_options(sculptline_warnings INTERFACE -fsanitize=address,undefined)
endif()

if(SCULPTLINE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "SCULPTLINE_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  target_compile_options(sculptline_warnings INTERFACE -fsanitize=fuzzer-no-link)
endif()
