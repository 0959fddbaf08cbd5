#!/usr/bin/env bash
# Installs the Debian packages hbtrack needs to build, test and plot. Idempotent; run as root
# (or with sudo). The README and .ci/run both call this one script.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  ccache                 # rebuilds (and CI runs on a machine that built before) reuse compiled objects
  clang-format           # scripts/check-format.sh: the tree's layout, checked by CI
  libeigen3-dev          # dense/sparse linear algebra
  libcli11-dev           # command line
  nlohmann-json3-dev     # summary.json
  libtoml11-dev          # case files
  libmatio-dev           # MATLAB .mat matrices
  libhdf5-dev            # `hbtrack export --format h5` (HDF5's C library; the tool only, not libhbtrack)
  zlib1g-dev             # inflates compressed .mat headers before libmatio sizes them
  calculix-ccx           # cross-checks the hex20 element against CalculiX (test skipped without it)
  libspectra-dev         # sparse/shift-invert eigensolvers (Hill, Craig-Bampton)
  libboost-dev           # Boost.odeint (header-only): the Dormand-Prince time integrator
  libopenblas-serial-dev # one-threaded optimized LAPACK for the continuation's dense LU (optional: Eigen's otherwise)
  libgtest-dev           # tests
  libbenchmark-dev       # bench/
  python3-numpy python3-matplotlib  # plots of the main job
  pybind11-dev python3-pybind11     # the Python module (python/)
  python3-pytest python3-scipy      # its tests (python/tests, run by ctest; scipy: sparse matrix input)
  libopenmpi-dev openmpi-bin        # `mpirun hbtrack sweep|study` (optional: without it tasks run locally)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi
sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo_cmd apt-get update -qq
$sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
