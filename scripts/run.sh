#!/usr/bin/env bash
# The README's main-job command: installs dependencies, builds ccm, runs the default trade study
# (thesis Table 2.2 at the default resolution, scenes/grids/default.toml) on an embedded SQLite
# store, prints its recommendation table, adds one benchtop rig case (RX025 on the synthetic dev
# trials, so that the report's rig section is not empty) and writes its HTML report. A second
# call resumes / reuses the study's runs already in the store (the rig case runs again).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh --run   # what building and running needs; no test tools (Chromium, Catch2)
# The same build folder and flags as scripts/test.sh's optimised build, without the tests and the
# benchmarks: only the executable is built (and the libraries it links).
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCCM_UNITY_BUILD=ON \
  -DCCM_BUILD_TESTS=OFF -DCCM_BUILD_BENCH=OFF >/dev/null
cmake --build build -j "$(nproc)" --target ccm
mkdir -p results
./build/ccm study run scenes/grids/default.toml --db results/default-study.sqlite --jobs "$(nproc)"
./build/ccm rig run RX025 --data tests/data/rig-dev --db results/default-study.sqlite \
  --out results/rig-RX025 || [ $? -eq 3 ]   # 3: unstable, stored as such and reported
./build/ccm report --db results/default-study.sqlite --out results/default-report
echo "report: $(pwd)/results/default-report/index.html"
