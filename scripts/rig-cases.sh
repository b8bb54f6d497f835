#!/usr/bin/env bash
# Runs the 12 benchtop cases of thesis Table 3.2 one after the other (low priority, one at a
# time) on the measured trials of DATA, into OUT/rig.sqlite and OUT/<CASE>/, then prints the
# the rig performance table of docs/benchtop-rig.md from the store. Extra arguments go to every `ccm rig run`.
#   scripts/rig-cases.sh [build-dir] [data-dir] [out-dir] [-- ccm rig run options]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
data=${2:-tests/data/rig-dev}
out=${3:-results/rig-cases}
shift $(( $# < 3 ? $# : 3 ))
[ "${1:-}" = "--" ] && shift
mkdir -p "$out"
for c in RX025 RX050 RX100 FX025 FX050 FX100 RF025 RF050 RF100 FF025 FF050 FF100; do
  echo "rig-cases: $c" >&2
  nice -n 15 "$build/ccm" rig run "$c" --data "$data" --out "$out/$c" --db "$out/rig.sqlite" \
    --quiet "$@" || echo "rig-cases: $c exited $?" >&2
done
sqlite3 -separator ' | ' "$out/rig.sqlite" "
  SELECT '| ' || case_code, n_elements, steps,
         printf('%.3g .. %.3g', dt_min, dt_max), printf('%.1f', wall_seconds),
         printf('%.3g %%', 100 * max_energy_error), status || ' |'
  FROM rig_runs WHERE id IN (SELECT max(id) FROM rig_runs WHERE purpose = 'run' GROUP BY case_code)
  ORDER BY CASE substr(case_code, 1, 2) WHEN 'RX' THEN 1 WHEN 'FX' THEN 2 WHEN 'RF' THEN 3 ELSE 4 END,
           case_code;"
