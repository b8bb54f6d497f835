#!/usr/bin/env bash
# The README's main-job command: installs dependencies, builds ccm and runs the default
# example scene, printing its summary. Results go to results/default/.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
./build/ccm run scenes/examples/default.toml --out results/default
echo "results: $(pwd)/results/default"
