#!/usr/bin/env bash
# sepax's main job, for a fresh Debian 12 machine: install the Debian packages
# the sepax program needs, build it, and run the differential fuzz campaign on
# the built-in generators (default budget about 30 s; it prints its report and
# exits non-zero on any unexplained disagreement, writing reproducers to
# ./fuzz-reproducers/).  Extra arguments go to `sepax fuzz` (e.g. --seconds 600,
# --seed 7, --json, --families boxes,flat).
#
# Usage: bash fuzz/run_campaign.sh [sepax fuzz options]   (as root, or with sudo)
set -euo pipefail
cd "$(dirname "$0")/.."
sudo=""
if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends \
  cmake ninja-build g++ libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev libcli11-dev nlohmann-json3-dev >/dev/null
cmake -S . -B build-main -G Ninja -DSEPAX_BUILD_TESTS=OFF >/dev/null
cmake --build build-main --target sepax_cli -j"$(nproc)"
exec ./build-main/src/sepax fuzz "$@"
