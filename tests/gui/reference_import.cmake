# Reference geometry (File > Import Reference, --import-reference; ui/reference_set.h), included by
# tests/gui/CMakeLists.txt.
#
# The real program under Xvfb: the default scene without a reference, with the box imported by the
# flag, the same with a replayed Ctrl+Z, and the saved document reopened; then a checker compares the
# pictures and reads the documents. The runs work on a copy of the box in their own folder (removed
# first, so a stale file never passes).
set(reference_dir ${CMAKE_CURRENT_BINARY_DIR}/references)
set(reference_box ${reference_dir}/orig/box.iv)
add_test(NAME gui_reference_setup
  COMMAND sh -c "rm -rf '${reference_dir}' && mkdir -p '${reference_dir}/orig' && cp '${PROJECT_SOURCE_DIR}/data/references/box.iv' '${reference_box}'")
set_tests_properties(gui_reference_setup PROPERTIES FIXTURES_SETUP gui_reference_setup)
function(sculptline_reference_run name)
  add_test(NAME gui_reference_${name} COMMAND ${xvfb} $<TARGET_FILE:sculptline> --size 800x600 ${ARGN} --quit)
  set_tests_properties(gui_reference_${name} PROPERTIES
    FIXTURES_REQUIRED gui_reference_setup FIXTURES_SETUP gui_reference_runs TIMEOUT 180)
endfunction()
sculptline_reference_run(none --screenshot ${reference_dir}/none.png)
sculptline_reference_run(flag --import-reference ${reference_box} --screenshot ${reference_dir}/with.png
                         --save ${reference_dir}/orig/with.json)
sculptline_reference_run(ctrlz --import-reference ${reference_box} --replay ${sessions}/reference_undo.json
                         --screenshot ${reference_dir}/undone.png --save ${reference_dir}/undone.json)
sculptline_reference_run(reopen ${reference_dir}/orig/with.json --screenshot ${reference_dir}/reopened.png
                         --save ${reference_dir}/reopened.json)
set_tests_properties(gui_reference_reopen PROPERTIES DEPENDS gui_reference_flag)

add_executable(reference_runs_test reference_runs_test.cpp)
target_link_libraries(reference_runs_test PRIVATE Qt5::Gui nlohmann_json::nlohmann_json GTest::gtest GTest::gtest_main sculptline_warnings)
add_test(NAME gui_reference_check COMMAND reference_runs_test)
set_tests_properties(gui_reference_check PROPERTIES
  FIXTURES_REQUIRED gui_reference_runs
  ENVIRONMENT "SCULPTLINE_REFERENCE_DIR=${reference_dir}"
  TIMEOUT 60)

# A file the importer refuses stops the program before Qt starts: status 2 and the reason.
add_test(NAME gui_reference_refused
  COMMAND $<TARGET_FILE:sculptline> --import-reference ${PROJECT_SOURCE_DIR}/tests/fuzz/corpus/iv-import/bad_file.iv --quit)
set_tests_properties(gui_reference_refused PROPERTIES
  PASS_REGULAR_EXPRESSION "sculptline: --import-reference: .*bad_file.iv: line 3: node File is not accepted: it reads files"
  TIMEOUT 60)
add_test(NAME gui_reference_refused_status
  COMMAND sh -c "$<TARGET_FILE:sculptline> --import-reference '${PROJECT_SOURCE_DIR}/tests/fuzz/corpus/iv-import/bad_cycle.iv' --quit; test $? -eq 2")
set_tests_properties(gui_reference_refused_status PROPERTIES TIMEOUT 60)

# In the real window: drawn greyed, unpickable, strokes go through it onto the plane; View >
# References, Edit > Remove References and undo; saved, reopened, moved with its folder, missing.
add_executable(reference_window_test reference_window_test.cpp)
target_link_libraries(reference_window_test PRIVATE sculptline::ui GTest::gtest GTest::gtest_main sculptline_warnings)
target_compile_definitions(reference_window_test PRIVATE SCULPTLINE_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
add_test(NAME gui_reference_window COMMAND ${xvfb} $<TARGET_FILE:reference_window_test>)
set_tests_properties(gui_reference_window PROPERTIES
  ENVIRONMENT "SCULPTLINE_REFERENCE_SHOT=${CMAKE_CURRENT_BINARY_DIR}/reference_window.png" TIMEOUT 180)
