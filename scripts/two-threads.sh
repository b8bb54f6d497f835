#!/usr/bin/env bash
# Two threads against one on a ~200k-tet scene (issue 35's measurement; docs/parallel.md):
# `ccm run --threads 1` and `--threads 2` alternating PAIRS times (default 10; the order within a
# pair alternates too), each run's ns per element-step from its summary.toml, and each pair's
# efficiency t1 / (2 t2). With --contact, the scene with DCR contact.
# The first run of each scene only fills the mesh cache and is not counted. Compare figures from
# one sitting on an otherwise idle machine. Before each pair, the round trip of a cache line
# between CPUs 0 and 1 (build/bench_core_latency, median of 3): 80-100 ns when the host has the
# two vCPUs near each other, 340-400 ns when it has them apart, the two-thread slow mode
# (docs/parallel.md, "The slow mode").
# Usage: scripts/two-threads.sh [--contact] [PAIRS] [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
contact=0
if [ "${1:-}" = --contact ]; then contact=1; shift; fi
pairs="${1:-10}"
build="${2:-build}"
ccm="$build/ccm"
[[ -x "$ccm" ]] || { echo "two-threads.sh: no $ccm (build first)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The scenes of the scaling bench (bench/scenes/): a clamped plate of about 200k tets, and the
# same with a soft ball striking it (DCR contact from about 1.7e-4 s of its 4e-4 s).
scene=bench/scenes/plate_200k.toml
[ "$contact" = 1 ] && scene=bench/scenes/ball_on_plate_dcr_200k.toml

ns_of() { awk -F' = ' '$1 == "ns_per_element_step" {print $2}' "$1/summary.toml"; }
run() {  # threads, out folder
  "$ccm" run "$scene" --out "$2" --threads "$1" --quiet > /dev/null
  ns_of "$2"
}
run 1 "$work/warm" > /dev/null  # meshes once into the mesh cache
probe="$build/bench_core_latency"
[[ -x "$probe" ]] || { echo "two-threads.sh: no $probe (build first)" >&2; exit 1; }
echo "pair  1 thread [ns/elem-step]  2 threads  efficiency  line round trip [ns]"
efficiencies=()
for ((i = 1; i <= pairs; i++)); do
  rt=$("$probe" --repeat 3 | awk '{print $10}')
  if ((i % 2)); then
    t1=$(run 1 "$work/a") t2=$(run 2 "$work/b")
  else
    t2=$(run 2 "$work/b") t1=$(run 1 "$work/a")
  fi
  e=$(python3 -c "print(f'{$t1 / (2 * $t2):.3f}')")
  efficiencies+=("$e")
  printf "%4d  %22.2f  %9.2f  %10s  %20s\n" "$i" "$t1" "$t2" "$e" "$rt"
done
python3 - "${efficiencies[@]}" <<'PY'
import statistics, sys
e = sorted(float(x) for x in sys.argv[1:])
print(f"efficiency: min {e[0]:.3f}, median {statistics.median(e):.3f}, max {e[-1]:.3f}; "
      f"{sum(x >= 0.85 for x in e)} of {len(e)} pairs at 85 % or more")
PY
