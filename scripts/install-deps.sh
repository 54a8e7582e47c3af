#!/usr/bin/env bash
# Installs the Debian packages rangesim needs, only those missing. Idempotent; silent when all
# are present. Runs as root, or through sudo when it is available.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config ccache
  libsystemc-dev verilator iverilog
  libgtest-dev libfmt-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libpcg-cpp-dev
  gnuplot-nox gtkwave
  librapidcheck-dev clang libclang-rt-14-dev
  python3  # tests/cosim: checks the JSON and JUnit XML of `rangesim cosim`
  openmpi-bin libopenmpi-dev  # optional MPI build: mpirun -n N rangesim sweep / evaluate --trials
  pybind11-dev python3-numpy  # optional Python module rangesim (python/, docs/python.md)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq >/dev/null
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
