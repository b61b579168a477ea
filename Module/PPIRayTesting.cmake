# ppiray_add_cxx_tests(<driver>
#   TESTS <name>...            one <name>.cxx each, int <name>(int, char*[])
#   LIBRARIES <target>...
#   [BASELINE_DIR <dir>]       baselines: <dir>/<name>.png (passed with -V)
#   [SOURCES <file>...])       helpers compiled into the driver
#
# One executable per module (create_test_sourcelist), one ctest test per
# function, run with VTK's regression-test arguments: -D <data root>
# -T <temporary dir> -V <baseline>. Tests name what they check in the code.
function (ppiray_add_cxx_tests driver)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "BASELINE_DIR" "TESTS;LIBRARIES;SOURCES")
  set(sources)
  foreach (test IN LISTS arg_TESTS)
    list(APPEND sources "${test}.cxx")
  endforeach ()
  create_test_sourcelist(driver_sources "${driver}.cxx" ${sources})
  add_executable("${driver}" ${driver_sources} ${arg_SOURCES})
  target_link_libraries("${driver}" PRIVATE ${arg_LIBRARIES})
  set_property(TARGET "${driver}" PROPERTY PPIRAY_BASELINE_DIR "${arg_BASELINE_DIR}")
  foreach (test IN LISTS arg_TESTS)
    _ppiray_add_cxx_test("${driver}" "${test}" "${driver}.${test}")
  endforeach ()
endfunction ()

# ppiray_add_cxx_test_variants(<driver> <suffix> ARGS <arg>... TESTS <name>...):
# tests of <driver> run again with more arguments, as "<driver>.<name>.<suffix>"
# (same baselines).
function (ppiray_add_cxx_test_variants driver suffix)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "ARGS;TESTS")
  foreach (test IN LISTS arg_TESTS)
    _ppiray_add_cxx_test("${driver}" "${test}" "${driver}.${test}.${suffix}" ${arg_ARGS})
  endforeach ()
endfunction ()

function (_ppiray_add_cxx_test driver test name)
  set(temporary "${CMAKE_BINARY_DIR}/Testing/Temporary")
  file(MAKE_DIRECTORY "${temporary}")
  get_property(baseline_dir TARGET "${driver}" PROPERTY PPIRAY_BASELINE_DIR)
  set(baseline_args)
  if (baseline_dir)
    set(baseline_args -V "${baseline_dir}/${test}.png")
  endif ()
  add_test(NAME "${name}"
    COMMAND "${driver}" "${test}" -D "${PPIRAY_DATA_ROOT}" -T "${temporary}" ${baseline_args}
      ${ARGN})
  # A hang fails in 10 minutes (the slowest test takes about 80 s here).
  set(environment "OMP_NUM_THREADS=2" ${PPIRAY_SANITIZER_ENVIRONMENT})
  set_tests_properties("${name}" PROPERTIES
    SKIP_RETURN_CODE 125
    TIMEOUT 600
    ENVIRONMENT "${environment}")
endfunction ()

# Under PPIRAY_SANITIZE: leaks are reported (suppressed only in the driver
# libraries listed in Module/sanitizer-suppressions.txt, each with a reason),
# any undefined behaviour fails the test.
set(PPIRAY_SANITIZER_ENVIRONMENT "")
if (PPIRAY_SANITIZE)
  set(PPIRAY_SANITIZER_ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/Module/sanitizer-suppressions.txt:print_suppressions=0"
    "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
endif ()

# ppiray_add_python_test(<name> <script> [ARGS...]): runs VTK's Python with the
# build's ppiray package importable.
function (ppiray_add_python_test name script)
  if (NOT PPIRAY_PYTHON_DESTINATION)
    return ()
  endif ()
  add_test(NAME "${name}"
    COMMAND "${PPIRAY_PYTHON_EXECUTABLE}" "${script}" ${ARGN})
  set(ppiray_vtk_pythonpath "")
  if (PPIRAY_VTK_PYTHONPATH)
    set(ppiray_vtk_pythonpath ":${PPIRAY_VTK_PYTHONPATH}")
  endif ()
  set(environment
    "PYTHONPATH=${CMAKE_BINARY_DIR}/${PPIRAY_PYTHON_DESTINATION}${ppiray_vtk_pythonpath}"
    "LD_LIBRARY_PATH=${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
  if (PPIRAY_SANITIZE)
    # The interpreter is not instrumented: the ASan runtime must come first.
    # Python keeps its objects at exit by design, so leaks are not checked
    # in Python processes (the C++ tests check them).
    list(APPEND environment "LD_PRELOAD=${PPIRAY_ASAN_RUNTIME}" "ASAN_OPTIONS=detect_leaks=0"
      "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  endif ()
  set_tests_properties("${name}" PROPERTIES
    SKIP_RETURN_CODE 125
    ENVIRONMENT "${environment}")
endfunction ()

# ppiray_add_test_display(<target>): the rendering test helpers' one X
# connection per process, opened with retries (PPIRayTestDisplay.cxx), and
# VTK's rendering factories.
function (ppiray_add_test_display target)
  target_sources("${target}" PRIVATE
    "${PROJECT_SOURCE_DIR}/Rendering/Testing/Cxx/PPIRayTestDisplay.cxx")
  target_include_directories("${target}" PRIVATE "${PROJECT_SOURCE_DIR}/Rendering/Testing/Cxx")
  find_package(X11 QUIET)
  if (TARGET X11::X11)
    target_link_libraries("${target}" PRIVATE X11::X11)
    target_compile_definitions("${target}" PRIVATE PPIRAY_TEST_HAS_X11=1)
  else ()
    target_compile_definitions("${target}" PRIVATE PPIRAY_TEST_HAS_X11=0)
  endif ()
  vtk_module_autoinit(TARGETS "${target}"
    MODULES VTK::RenderingOpenGL2 VTK::InteractionStyle VTK::RenderingVolumeOpenGL2)
endfunction ()
