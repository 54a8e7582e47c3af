# Fuzzing (fuzz/): RANGESIM_FUZZ=ON turns this build into the clang libFuzzer build (every
# target instrumented with fuzzer-no-link + ASan + UBSan, fuzz/ added). A normal build with tests
# instead registers the ctest `fuzz` (label fuzz), which makes that build in a sub-directory at
# test time and runs each target for RANGESIM_FUZZ_SECONDS; it skips when clang is absent.
option(RANGESIM_FUZZ "Build the libFuzzer targets in fuzz/ (clang only)" OFF)
set(RANGESIM_FUZZ_SECONDS 20 CACHE STRING "Seconds each fuzz target runs in the fuzz ctest (three targets)")

if(RANGESIM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "RANGESIM_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=address,undefined)
endif()

# Called after the targets exist (top-level CMakeLists.txt).
function(rangesim_fuzz_targets)
  if(RANGESIM_FUZZ)
    add_subdirectory(${PROJECT_SOURCE_DIR}/fuzz ${PROJECT_BINARY_DIR}/fuzz)
  elseif(RANGESIM_BUILD_TESTS AND NOT RANGESIM_SANITIZE)
    add_test(NAME fuzz
             COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DBINARY_DIR=${PROJECT_BINARY_DIR}/fuzz-run
                     -DSECONDS=${RANGESIM_FUZZ_SECONDS} -P ${PROJECT_SOURCE_DIR}/fuzz/run_fuzz.cmake)
    set_tests_properties(fuzz PROPERTIES LABELS fuzz SKIP_REGULAR_EXPRESSION "FUZZ-SKIPPED" TIMEOUT 1500
                                         RUN_SERIAL FALSE)
  endif()
endfunction()
