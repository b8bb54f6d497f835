#!/usr/bin/env bash
# The performance figures of the README: single-thread ns per element-step on 201,600 tets.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target bench_element_step
./build/bench_element_step "$@"
