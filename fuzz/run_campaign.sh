#!/usr/bin/env bash
# sepax's main job, for a fresh Debian 12 machine: install the Debian packages
# the sepax program needs, build it, and run the differential fuzz campaign on
# the built-in generators (default budget about 30 s; it prints its report and
# exits non-zero on any unexplained disagreement, writing reproducers to
# ./fuzz-reproducers/).  Extra arguments go to `sepax fuzz` (e.g. --seconds 600,
# --seed 7, --json, --families boxes,flat).
#
# Usage: bash fuzz/run_campaign.sh [sepax fuzz options]   (as root, or with sudo)
# Env:   SEPAX_SKIP_INSTALL=1 skips the package installation (packages already
#        there, or a system that is not Debian: install the equivalents).
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install_packages.sh \
  cmake ninja-build g++ libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev \
  libcli11-dev nlohmann-json3-dev
cmake -S . -B build-main -G Ninja -DSEPAX_BUILD_TESTS=OFF >/dev/null
cmake --build build-main --target sepax_cli -j"$(nproc)"
exec ./build-main/src/sepax fuzz "$@"
