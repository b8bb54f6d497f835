#!/usr/bin/env bash
# Installs the Debian packages ccm needs. Idempotent: it installs only what is missing, and does
# nothing (not even apt-get update) when all is present.
#   scripts/install-deps.sh         to build, run and test (scripts/test.sh, validate.sh, bench.sh)
#   scripts/install-deps.sh --run   to build and run only (scripts/run.sh): no test tools
set -euo pipefail

# Building ccm and running it (gnuplot-nox: `ccm report` draws its figures with it).
packages=(
  g++ cmake ninja-build pkg-config git
  libeigen3-dev libopenmpi-dev openmpi-bin libmetis-dev
  libsqlite3-dev sqlite3 libhdf5-dev hdf5-tools
  libfmt-dev libgmsh-dev
  libcli11-dev libtomlplusplus-dev libnlopt-dev gnuplot-nox nlohmann-json3-dev
)
# The tests alone: Catch2; Chromium renders the report page (tests/reports/test_report_page.cpp);
# pandas and h5py run docs/store.md's Python recipes (tests/app/test_store_recipes.cpp); libxml2
# parses the field output's XDMF, ParaView (with Xvfb) opens and renders it headless
# (tests/io/fields/); mpiexec (openmpi-bin, above) runs the partitioned-run tests; clang-14 (with
# its OpenMP runtime) builds the sanitizer pass and the libFuzzer targets (docs/fuzzing.md).
test_packages=(catch2 chromium python3 python3-pandas python3-h5py libxml2-dev python3-paraview
  xvfb clang-14 libomp-14-dev)

case "${1:-}" in
  --run) ;;
  "") packages+=("${test_packages[@]}") ;;
  *) echo "usage: $0 [--run]" >&2; exit 2 ;;
esac

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
