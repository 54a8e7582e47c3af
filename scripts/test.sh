#!/usr/bin/env bash
# The whole test suite: install missing Debian packages, configure, build everything, run
# ctest on both cores. Heavier runs carry the label `heavy` and are skipped here; run them
# with `ctest --test-dir build -L heavy`. Extra arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
build_dir=${RANGESIM_BUILD_DIR:-build}
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir"
# A test that hangs fails after 15 minutes with its name, not the whole run at the CI limit.
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" -LE heavy --timeout 900 "$@"
