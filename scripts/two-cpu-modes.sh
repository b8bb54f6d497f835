#!/usr/bin/env bash
# The two-thread step against the host's placement of the two vCPUs (docs/parallel.md, "The slow
# mode"; bench/results/two-cpu-modes-2026-12-07.md). ROUNDS times (default 10), on the 32^3-cell
# structured box, kernel / whole-step medians in ns per element-step:
#   (default)        the cache line's round trip between CPUs 0 and 1 (bench_core_latency), the
#                    2-thread bench_element_step, the round trip again;
#   --pairs          one 1-thread bench alone, two at once pinned to CPUs 0 and 1, one 2-thread;
#   --vs OTHER       the round trip, OTHER's 2-thread bench_element_step (another build's binary),
#                    this build's, the round trip again.
# Usage: scripts/two-cpu-modes.sh [--pairs | --vs OTHER_BENCH_ELEMENT_STEP] [ROUNDS] [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
mode=probe other=""
if [ "${1:-}" = --pairs ]; then mode=pairs; shift; fi
if [ "${1:-}" = --vs ]; then mode=vs; other="$2"; shift 2; fi
rounds="${1:-10}"
build="${2:-build}"
bench="$build/bench_element_step" probe="$build/bench_core_latency"
for b in "$bench" "$probe" ${other:+"$other"}; do
  [[ -x "$b" ]] || { echo "two-cpu-modes.sh: no $b (build first)" >&2; exit 1; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
step() {  # binary, threads: "kernel/whole" medians
  "$1" --cells 32 32 32 --threads "$2" --repeat 5 | awk -v n="$2" '$1 == n {print $4 "/" $9}'
}
round_trip() { "$probe" --repeat 3 | awk '{print $10}'; }
for ((i = 1; i <= rounds; i++)); do
  case "$mode" in
    probe) echo "$i round_trip_ns $(round_trip) two_threads $(step "$bench" 2) round_trip_ns $(round_trip)" ;;
    vs) echo "$i round_trip_ns $(round_trip) other $(step "$other" 2) this $(step "$bench" 2) round_trip_ns $(round_trip)" ;;
    pairs)
      alone=$(step "$bench" 1)
      taskset -c 0 "$bench" --cells 32 32 32 --threads 1 --repeat 5 > "$work/0" &
      taskset -c 1 "$bench" --cells 32 32 32 --threads 1 --repeat 5 > "$work/1" &
      wait
      p0=$(awk '$1 == 1 {print $4 "/" $9}' "$work/0") p1=$(awk '$1 == 1 {print $4 "/" $9}' "$work/1")
      echo "$i alone $alone pair $p0 $p1 two_threads $(step "$bench" 2)" ;;
  esac
done
