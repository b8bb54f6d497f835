#!/usr/bin/env bash
# The performance figures of the README.
#   scripts/bench.sh                   both benchmarks
#   scripts/bench.sh element [args]    single-thread ns per element-step on 201,600 tets
#   scripts/bench.sh contact [args]    DCR contact cost per step vs structure and surface size
#                                      (args: --levels N --repeats R --end T)
set -euo pipefail
cd "$(dirname "$0")/.."
which="${1:-all}"
[ $# -gt 0 ] && shift
case "$which" in
  element | contact | all) ;;
  *) echo "usage: scripts/bench.sh [element|contact|all] [args]" >&2; exit 2 ;;
esac
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCCM_BUILD_BENCH=ON >/dev/null
targets=()
[ "$which" != contact ] && targets+=(bench_element_step)
[ "$which" != element ] && targets+=(bench_contact)
cmake --build build -j "$(nproc)" --target "${targets[@]}"
case "$which" in
  element) ./build/bench_element_step "$@" ;;
  contact) ./build/bench_contact "$@" ;;
  all) ./build/bench_element_step && ./build/bench_contact ;;
esac
