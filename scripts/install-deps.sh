#!/usr/bin/env bash
# Installs every Debian package ccm needs to build, test and run. Idempotent: it
# installs only what is missing, and does nothing (not even apt-get update) when all is present.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config git
  libeigen3-dev libopenmpi-dev openmpi-bin libmetis-dev
  libsqlite3-dev sqlite3 libhdf5-dev hdf5-tools
  libfmt-dev catch2 libgmsh-dev
  libcli11-dev libtomlplusplus-dev libnlopt-dev gnuplot-nox nlohmann-json3-dev
  chromium
  libxml2-dev                  # tests: the field output's XDMF is parsed with libxml2
  python3-paraview xvfb        # tests: ParaView opens the field output, renders it headless
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
