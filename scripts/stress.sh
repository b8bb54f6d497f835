#!/usr/bin/env bash
# Runs every scene in scenes/stress/ with `ccm run` and prints the "Stress cases" table of docs/evidence.md
# table: verdict, reason, steps, dt min/max, wall time, energy error, and whether history.csv
# holds a NaN. A run is killed after STRESS_TIMEOUT seconds (default 300) and reported as a
# hang; an exit code other than 0 (completed) or 3 (unstable) is reported as a crash.
# Usage: scripts/stress.sh [build-dir]   (default: build; it must contain ccm)
set -euo pipefail
cd "$(dirname "$0")/.."

build="${1:-build}"
ccm="$build/ccm"
[[ -x "$ccm" ]] || { echo "stress.sh: no $ccm (build first)" >&2; exit 1; }
out="${STRESS_OUT:-results/stress}"
timeout_s="${STRESS_TIMEOUT:-300}"
mkdir -p "$out"

rows=()
for scene in scenes/stress/*.toml; do
  name="$(basename "$scene" .toml)"
  rm -rf "${out:?}/$name"
  set +e
  timeout "$timeout_s" "$ccm" run "$scene" --out "$out/$name" --quiet >"$out/$name.stdout" 2>"$out/$name.stderr"
  code=$?
  set -e
  rows+=("$name $code")
done

python3 - "$out" "${rows[@]}" <<'PY'
import math, sys, tomllib, pathlib
out = pathlib.Path(sys.argv[1])
print("| scene | elements | verdict | reason | steps | dt min [s] | dt max [s] | wall [s] | energy error | NaN in history |")
print("|---|---|---|---|---|---|---|---|---|---|")
for row in sys.argv[2:]:
    name, code = row.split()
    code = int(code)
    d = out / name
    if code == 124:
        print(f"| {name} | | **HANG** (killed by timeout) | | | | | | | |")
        continue
    if code not in (0, 3) or not (d / "summary.toml").exists():
        err = (out / f"{name}.stderr").read_text().strip().splitlines()
        print(f"| {name} | | **CRASH** (exit {code}) | {err[-1] if err else ''} | | | | | | |")
        continue
    s = tomllib.loads((d / "summary.toml").read_text())
    r = s["run"]
    reason = s.get("instability", {}).get("reason", "")
    if reason:
        reason = f"{reason} (t = {s['instability']['time']:.4g} s)"
    nan = "no"
    with open(d / "history.csv") as f:
        next(f)
        for line in f:
            if any(not math.isfinite(float(v)) for v in line.split(",")):
                nan = "**yes**"
                break
    # The monitor checks the balance only on steps whose dt is within 1 % of the previous one;
    # an error of exactly 0 after the first step means no such check step occurred.
    err = r["energy_balance_error"]
    err = f"{err:.3g}" if err > 0 or r["steps"] == 0 else "0 (never checked)"
    print(f"| {name} | {s['model']['elements']} | {s['verdict']} | {reason} | {r['steps']} | "
          f"{r['dt_min']:.3g} | {r['dt_max']:.3g} | {r['wall_seconds']:.1f} | {err} | {nan} |")
PY
