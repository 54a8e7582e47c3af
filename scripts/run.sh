#!/usr/bin/env bash
# The main job: install missing Debian packages, configure, build, and run the thesis's
# evaluation of the default sensor (ls-conventional). Extra arguments go to `rangesim evaluate`.
# Outputs: out/ls-conventional/ (summary.json, CSV maps, PNG/SVG heat maps).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
build_dir=${RANGESIM_BUILD_DIR:-build}
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" --target rangesim
"$build_dir"/app/rangesim frame-rate ls-conventional
echo
"$build_dir"/app/rangesim evaluate ls-conventional --out out/ls-conventional "$@"
