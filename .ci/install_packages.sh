#!/usr/bin/env bash
# Installs Debian packages for .ci/run and fuzz/run_campaign.sh:
#   bash .ci/install_packages.sh PACKAGE...
# Skipped when SEPAX_SKIP_INSTALL=1 (the packages, or their equivalents on a
# system that is not Debian, are installed already).  Runs apt-get as root,
# or through sudo; with neither it stops and says what to do.
set -euo pipefail

if [ "${SEPAX_SKIP_INSTALL:-0}" = 1 ]; then
  echo "SEPAX_SKIP_INSTALL=1: not installing packages (expected present: $*)"
  exit 0
fi

skip_hint="install them (or your system's equivalents) yourself, then run again with SEPAX_SKIP_INSTALL=1"
if ! command -v apt-get >/dev/null 2>&1; then
  echo "error: apt-get not found (not Debian?).  sepax needs these Debian packages or their equivalents:" >&2
  echo "  $*" >&2
  echo "$skip_hint" >&2
  exit 1
fi

sudo=""
if [ "$(id -u)" != 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo="sudo"
  else
    echo "error: installing packages needs root, and sudo is not available (running as $(id -un))." >&2
    echo "Run as root, or $skip_hint:" >&2
    echo "  apt-get install $*" >&2
    exit 1
  fi
fi

export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "$@" >/dev/null
echo "packages installed: $*"
