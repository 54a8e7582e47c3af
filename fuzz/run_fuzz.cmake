# ctest `fuzz`: builds the libFuzzer targets with clang in a sub-build and runs each for a
# bounded time on a scratch copy of its seed corpus. Skips (prints FUZZ-SKIPPED, which the test's
# SKIP_REGULAR_EXPRESSION turns into "skipped") when clang or its libFuzzer runtime is absent.
#   cmake -DSOURCE_DIR=<repo> -DBINARY_DIR=<dir> [-DSECONDS=20] -P fuzz/run_fuzz.cmake
if(NOT SECONDS)
  set(SECONDS 20)
endif()
find_program(CLANGXX NAMES clang++ clang++-14 clang++-15 clang++-16)
if(NOT CLANGXX)
  message("FUZZ-SKIPPED: clang++ not found (scripts/install-deps.sh installs clang)")
  return()
endif()
# libFuzzer itself ships in libclang-rt-<v>-dev: try a one-line target first.
file(MAKE_DIRECTORY "${BINARY_DIR}/probe")
file(WRITE "${BINARY_DIR}/probe/p.cpp"
  "#include <cstdint>\n#include <cstddef>\nextern \"C\" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }\n")
execute_process(COMMAND "${CLANGXX}" -fsanitize=fuzzer,address,undefined "${BINARY_DIR}/probe/p.cpp"
                        -o "${BINARY_DIR}/probe/p" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(NOT rc EQUAL 0)
  message("FUZZ-SKIPPED: ${CLANGXX} cannot link -fsanitize=fuzzer (libclang-rt-dev missing)")
  return()
endif()

set(build "${BINARY_DIR}/build")
string(TIMESTAMP t0 "%s")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${build}" -G Ninja
                        -DCMAKE_CXX_COMPILER=${CLANGXX} -DCMAKE_BUILD_TYPE=RelWithDebInfo
                        -DRANGESIM_FUZZ=ON -DRANGESIM_BUILD_TESTS=OFF -DRANGESIM_WITH_RTL=OFF
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fuzz: configuring the clang sub-build failed")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${build}" --target preset_fuzz scene_fuzz cli_fuzz RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fuzz: building the fuzz targets failed")
endif()
string(TIMESTAMP t1 "%s")
math(EXPR build_s "${t1} - ${t0}")
message("fuzz: sub-build ready in ${build_s} s")

set(failed "")
foreach(target preset_fuzz scene_fuzz cli_fuzz)
  set(work "${BINARY_DIR}/corpus/${target}")
  file(REMOVE_RECURSE "${work}" "${BINARY_DIR}/artifacts/${target}")
  file(MAKE_DIRECTORY "${work}" "${BINARY_DIR}/artifacts/${target}")
  # New inputs go to the scratch corpus (first dir); the seeds in the repo are only read.
  execute_process(COMMAND "${build}/fuzz/${target}" -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048
                          -print_final_stats=1 -artifact_prefix=${BINARY_DIR}/artifacts/${target}/
                          "${work}" "${SOURCE_DIR}/fuzz/corpus/${target}"
                  WORKING_DIRECTORY "${BINARY_DIR}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REGEX MATCH "Done [0-9]+ runs in [0-9]+ second" done "${err}")
  string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" units "${err}")
  string(REGEX MATCH "cov: [0-9]+ ft: [0-9]+" cov "${err}")
  message("fuzz: ${target}: ${done} (${units}; ${cov}), exit code ${rc}")
  if(NOT rc EQUAL 0)
    string(LENGTH "${err}" n)
    if(n GREATER 6000)
      math(EXPR from "${n} - 6000")
      string(SUBSTRING "${err}" ${from} 6000 err)
    endif()
    message("${err}")
    list(APPEND failed ${target})
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "fuzz: findings in ${failed}; reproducers in ${BINARY_DIR}/artifacts/")
endif()
