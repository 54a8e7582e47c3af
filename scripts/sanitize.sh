#!/usr/bin/env bash
# Sanitizer run: configures a separate build with -fsanitize=address,undefined
# (-DRANGESIM_SANITIZE=ON, g++; cmake/Sanitize.cmake), builds the command and the golden, core,
# cli, badinput and stress tests, runs them, and exits non-zero on any failure or sanitizer
# report (halt_on_error; reports are also logged to files and any log fails the run, so a report
# in a process whose exit code nobody checks is not lost). The SystemC, Verilator and co-simulation
# parts are left out (-DRANGESIM_WITH_RTL=OFF, systemc tests not built): SystemC's own library is
# not instrumented and its coroutine stacks confuse ASan. The Python module is left out too: an
# instrumented module cannot load into the uninstrumented interpreter.
#   scripts/sanitize.sh [BUILD_DIR]        (default build-sanitize); extra ctest args via CTEST_ARGS
# Registered as the ctest `sanitize` (labels sanitize, heavy) of a normal build.
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$src/build-sanitize}
start=$(date +%s)

cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRANGESIM_SANITIZE=ON \
  -DRANGESIM_WITH_RTL=OFF -DRANGESIM_WITH_MPI=OFF -DRANGESIM_WITH_PYTHON=OFF -DRANGESIM_BUILD_TESTS=ON >/dev/null

# Test targets of the labels below that exist in this tree (other sensors' suites come and go).
targets=(rangesim test_golden test_core test_cli test_badinput test_stress)
# test_stress_kernels: the clock-level kernels without elaboration (no SystemC processes, so the
# uninstrumented libsystemc stays out of the way).
for t in test_golden_ls_demodulation test_golden_tof_lockin test_golden_tof_spad test_stress_kernels; do
  if ninja -C "$build" -t targets all 2>/dev/null | grep -q "^$t:"; then targets+=("$t"); fi
done

logs="$build/sanitizer-logs"
rm -rf "$logs"
mkdir -p "$logs"
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=0:log_path=$logs/asan"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$logs/ubsan"
export RC_PARAMS="${RC_PARAMS:-seed=1511224127 max_success=100}"

# gtest_discover_tests runs each test binary at build time, so the build already runs under the
# sanitizers' options.
cmake --build "$build" --target "${targets[@]}"
built=$(date +%s)

status=0
# shellcheck disable=SC2086
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -L 'golden|core|cli|badinput|stress' ${CTEST_ARGS:-} || status=$?
if compgen -G "$logs/*" >/dev/null; then
  echo "sanitize: sanitizer reports:" >&2
  for f in "$logs"/*; do
    echo "==== $f" >&2
    head -60 "$f" >&2
  done
  status=1
fi
end=$(date +%s)
echo "sanitize: build $((built - start)) s, tests $((end - built)) s, total $((end - start)) s, status $status"
exit $status
