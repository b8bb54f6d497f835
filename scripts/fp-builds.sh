#!/usr/bin/env bash
# Issue 15 item 4: the energy balance must not depend on the build. Builds `ccm` at -O1, -O2 and
# -O3, each with floating-point contraction into FMA instructions (-ffp-contract=fast, GCC's
# default for C++ on this CPU) and without it (-ffp-contract=off), runs the same contact scenes
# with each, and prints every run's energy-balance error. Exits non-zero when a run does not
# complete, or when the errors of one scene differ by more than 0.1 % (absolute) between builds.
#
# Usage: scripts/fp-builds.sh [scene.toml ...]
#   default scenes: the steel Hertz impact on its coarse mesh (restitution 1), three blocks
#   resting under gravity with friction 0.5, and the rubber pad pressed on a limb (DCR).
# The six builds go to build-fp/ (about 2-3 minutes each on 2 cores); runs use 2 threads, whose
# result is bitwise that of one.
set -euo pipefail
cd "$(dirname "$0")/.."

scenes=("$@")
if [[ ${#scenes[@]} -eq 0 ]]; then
  scenes=(scenes/validation/hertz_steel_h320.toml scenes/hard/resting_blocks.toml
          scenes/examples/pad_on_limb_dcr.toml)
fi
for s in "${scenes[@]}"; do [[ -f "$s" ]] || { echo "fp-builds.sh: no scene $s" >&2; exit 2; }; done

out="${FP_OUT:-results/fp-builds}"
mkdir -p "$out"
rows=()
for opt in 1 2 3; do
  for contract in fast off; do
    name="O${opt}-${contract}"
    dir="build-fp/$name"
    echo "fp-builds: building $name" >&2
    cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_FLAGS_RELEASE="-O${opt} -DNDEBUG -ffp-contract=${contract}" \
      -DCCM_UNITY_BUILD=ON -DCCM_BUILD_TESTS=OFF -DCCM_BUILD_BENCH=OFF >/dev/null
    cmake --build "$dir" -j "$(nproc)" --target ccm >"$dir.log" 2>&1 ||
      { tail -30 "$dir.log" >&2; echo "fp-builds: the $name build failed ($dir.log)" >&2; exit 1; }
    for s in "${scenes[@]}"; do
      scene="$(basename "$s" .toml)"
      echo "fp-builds: $name $scene" >&2
      rm -rf "${out:?}/$name/$scene"
      set +e
      "$dir/ccm" run "$s" --out "$out/$name/$scene" --quiet --threads 2
      code=$?
      set -e
      rows+=("$name $scene $code")
    done
  done
done

python3 - "$out" "${rows[@]}" <<'PY'
import sys, tomllib, pathlib
out = pathlib.Path(sys.argv[1])
by_scene, failed = {}, False
print("| build | scene | verdict | steps | energy-balance error |")
print("|---|---|---|---|---|")
for row in sys.argv[2:]:
    build, scene, code = row.split()
    summary = out / build / scene / "summary.toml"
    if int(code) != 0 or not summary.exists():
        print(f"| {build} | {scene} | exit {code} | | |")
        failed = True
        continue
    s = tomllib.loads(summary.read_text())
    e = s["run"]["energy_balance_error"]
    by_scene.setdefault(scene, []).append((build, e))
    print(f"| {build} | {scene} | {s['verdict']} | {s['run']['steps']} | {e:.6%} |")
print()
for scene, runs in by_scene.items():
    errors = [e for _, e in runs]
    spread = max(errors) - min(errors)
    ok = spread <= 1e-3
    failed = failed or not ok
    print(f"{scene}: energy-balance error {min(errors):.6%} to {max(errors):.6%}, "
          f"spread {spread:.2e} (bound 1e-3): {'ok' if ok else 'FAIL'}")
sys.exit(1 if failed else 0)
PY
