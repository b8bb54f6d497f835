#!/usr/bin/env bash
# The cost of resting contact against the structure alone (issue 15 item 6: at most 5x per
# element-step). Runs scenes/hard/resting_blocks.toml to END seconds (default 0.3, the issue's
# run) and the same scene without its [contact] table, one thread each, alternating RUNS times
# (default 3), and prints each run's ns per element-step (summary.toml) and the ratio of the
# medians. Exits 1 when that ratio exceeds the floor (RESTING_FLOOR, default 5). Machines differ
# and drift: compare ratios from one sitting, on an otherwise idle machine.
# Usage: scripts/resting-cost.sh [build-dir] [END] [RUNS]   (build-dir default: build)
set -euo pipefail
cd "$(dirname "$0")/.."

build="${1:-build}"
end="${2:-0.3}"
runs="${3:-3}"
floor="${RESTING_FLOOR:-5}"
ccm="$build/ccm"
[[ -x "$ccm" ]] || { echo "resting-cost.sh: no $ccm (build first)" >&2; exit 1; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
python3 - scenes/hard/resting_blocks.toml "$end" "$work" <<'PY'
import re, sys, pathlib
scene, end, work = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
lines = scene.read_text().splitlines()
timed = [re.sub(r"^end = .*", f"end = {end}", l) for l in lines]
if timed == lines:
    sys.exit(f"resting-cost.sh: no 'end = ' line in {scene}")
structure, skip = [], False
for line in timed:
    if re.match(r"^\[+\s*contact", line):
        skip = True
        continue
    if line.startswith("["):
        skip = False
    if not skip:
        structure.append(line)
(work / "contact.toml").write_text("\n".join(timed) + "\n")
(work / "structure.toml").write_text("\n".join(structure) + "\n")
PY

ns_per_element_step() {  # scene -> ns per element-step of one run
  rm -rf "$work/out"
  "$ccm" run "$1" --threads 1 --quiet --out "$work/out" >/dev/null
  python3 -c 'import sys, tomllib; print(tomllib.load(open(sys.argv[1], "rb"))["run"]["ns_per_element_step"])' \
    "$work/out/summary.toml"
}

contact=() structure=()
for i in $(seq "$runs"); do
  contact+=("$(ns_per_element_step "$work/contact.toml")")
  structure+=("$(ns_per_element_step "$work/structure.toml")")
  echo "run $i: resting contact ${contact[-1]} ns, structure alone ${structure[-1]} ns per element-step"
done
python3 - "$floor" "${contact[*]}" "${structure[*]}" <<'PY'
import statistics, sys
floor = float(sys.argv[1])
contact = statistics.median(float(x) for x in sys.argv[2].split())
structure = statistics.median(float(x) for x in sys.argv[3].split())
ratio = contact / structure
print(f"medians: resting contact {contact:.1f} ns, structure {structure:.2f} ns per element-step: "
      f"{ratio:.2f}x the structure (floor {floor:g}x)")
sys.exit(0 if ratio <= floor else 1)
PY
