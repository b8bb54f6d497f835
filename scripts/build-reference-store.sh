#!/usr/bin/env bash
# Builds ccm's reference store: the whole-impact grid over the users' regime
# (scenes/grids/whole-impacts.toml, 96 points) run both ways at every point, then refined along ER
# where the answer changes (`ccm study refine`, twice the grid's runs in all), and its report.
#
#   scripts/build-reference-store.sh [STORE]     default: data/reference/whole-impacts.sqlite, the
#                                                one `ccm recommend` reads without --db
#
# Resumable: after a stop, the same command picks up where it was (no run is done twice).
# JOBS local worker processes (default: the cores). With CCM_MPI_RANKS=N the grid is spread over
# N MPI ranks (mpirun -np N, on one machine or, with your own hostfile in MPIRUN_FLAGS, across
# several); the refinement then runs on this machine (each round depends on the last).
# Provenance (ccm version, git hash, host, ranks, jobs) is stored with every run.
set -euo pipefail
cd "$(dirname "$0")/.."

store="${1:-data/reference/whole-impacts.sqlite}"
grid=scenes/grids/whole-impacts.toml
ccm="${CCM:-build/ccm}"
jobs="${JOBS:-$(nproc)}"
if [ ! -x "$ccm" ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCCM_UNITY_BUILD=ON \
    -DCCM_BUILD_TESTS=OFF -DCCM_BUILD_BENCH=OFF >/dev/null
  cmake --build build -j "$(nproc)" --target ccm
fi
mkdir -p "$(dirname "$store")"
if [ -n "${CCM_MPI_RANKS:-}" ]; then
  # shellcheck disable=SC2086  # MPIRUN_FLAGS is a list of flags
  mpirun ${MPIRUN_FLAGS:-} -np "$CCM_MPI_RANKS" "$ccm" study run "$grid" --db "$store"
else
  "$ccm" study run "$grid" --db "$store" --jobs "$jobs"
fi
"$ccm" study refine --db "$store" --jobs "$jobs"
# Shipped in rollback-journal mode: reading it then writes no -wal or -shm file beside it.
python3 -c "import sqlite3, sys; sqlite3.connect(sys.argv[1]).execute('PRAGMA journal_mode=DELETE')" \
  "$store"
"$ccm" report --db "$store" --out "${store%.sqlite}-report"
echo "reference store: $store (report: ${store%.sqlite}-report/index.html)"
