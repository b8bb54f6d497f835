#!/usr/bin/env bash
# Fuzzes every reader of outside input (docs/fuzzing.md): scripts/fuzz.sh [SECONDS] [TARGET...]
# (as many targets at once as there are cores)
# Builds build-fuzz/ (clang-14, libFuzzer, AddressSanitizer + UBSan) when needed, seeds each
# target's corpus from the repository's own files, runs each target SECONDS (default 60) and
# prints its executions and coverage. A crash, a hang (> 10 s on one input) or a sanitizer report
# stops that target; its input is kept in build-fuzz/artifacts/<target>/ and the script exits 1.
# Fixed crashes are kept as regression inputs in tests/data/fuzz/<target>/ and every run replays
# them first.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_scene_file fuzz_grid_file fuzz_unv_mesh fuzz_inp_mesh
  fuzz_msh_mesh fuzz_trial_csv fuzz_store_file)
build=${CCM_FUZZ_BUILD:-build-fuzz}  # CI fuzzes in its sanitizer build (scripts/test.sh)
command -v clang++-14 >/dev/null || { echo "fuzz: clang++-14 is missing (scripts/install-deps.sh)" >&2; exit 1; }

if [ ! -f "$build/build.ninja" ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCCM_SANITIZE=ON -DCCM_FUZZ=ON \
    -DCCM_BUILD_TESTS=OFF -DCCM_BUILD_BENCH=OFF -DCCM_UNITY_BUILD=ON >/dev/null
fi
# One executable holds every target; each target is a link to it by its name (fuzz/CMakeLists.txt).
cmake --build "$build" -j "$(nproc)" --target ccm_fuzz

# The seed corpus of a target: the repository's files of its kind.
seeds() {
  case "$1" in
    fuzz_scene_file) find scenes -name '*.toml' -not -path 'scenes/grids/*' ;;
    fuzz_grid_file) find scenes/grids -name '*.toml' ;;
    fuzz_unv_mesh) find tests/data/meshes -name '*.unv' -size -64k ;;
    fuzz_inp_mesh) find tests/data/meshes -name '*.inp' ;;
    fuzz_msh_mesh) ;;         # made below (the repository holds no .msh file)
    fuzz_trial_csv) find tests/data/rig-dev -name '*_t1.csv' ;;
    fuzz_store_file) ;;  # made below
  esac
}

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Gmsh leaks on the error paths of its own reader (not ccm's allocations): suppressed as in the
# sanitizer tests, and the .msh target fuzzes in child processes that restart (-fork) so that the
# leaked memory does not add up to the RSS limit.
export LSAN_OPTIONS=suppressions=$(pwd)/tests/lsan.supp

# Replays the target's kept inputs, then fuzzes it; the summary goes to $build/<target>.summary.
fuzz_one() {
  local t=$1 corpus="$build/corpus/$1" artifacts="$build/artifacts/$1/" regressions="tests/data/fuzz/$1"
  local summary="$build/$t.summary"
  mkdir -p "$corpus" "$artifacts"
  while IFS= read -r f; do [ -n "$f" ] && cp "$f" "$corpus/"; done < <(seeds "$t")
  if [ "$t" = fuzz_store_file ] && [ ! -f "$corpus/seed.sqlite" ]; then
    CCM_FUZZ_MAKE_SEED="$corpus/seed.sqlite" "$build/fuzz/$t"
    rm -f "$corpus"/seed.sqlite-*
  fi
  if [ "$t" = fuzz_msh_mesh ] && [ ! -f "$corpus/box41.msh" ]; then
    CCM_FUZZ_MAKE_SEED="$corpus" "$build/fuzz/$t"
  fi
  if [ -d "$regressions" ] &&
    ! "$build/fuzz/$t" "$regressions"/* > "$build/$t.regressions.log" 2>&1; then
    echo "fuzz: $t FAILS a kept input (log: $build/$t.regressions.log)" > "$summary"
    return 1
  fi
  local extra=()
  [ "$t" = fuzz_msh_mesh ] && extra=(-fork=1 -ignore_ooms=1)
  if "$build/fuzz/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$artifacts" "${extra[@]}" "$corpus" > "$build/$t.log" 2>&1; then
    {
      echo "== $t: $seconds s"
      grep -E '^#[0-9]+(:|[[:space:]]+DONE)' "$build/$t.log" | tail -1 || true
      grep -E 'stat::number_of_executed_units|stat::peak_rss_mb' "$build/$t.log" || true
    } > "$summary"
  else
    {
      echo "fuzz: $t FAILED; the input is in $artifacts (log: $build/$t.log)"
      grep -E 'ERROR|ccm fuzz|SUMMARY' "$build/$t.log" | head -5
    } > "$summary"
    return 1
  fi
}

# The targets, as many at once as there are cores (each is one process).
jobs=$(nproc)
for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  (if fuzz_one "$t"; then echo 0; else echo 1; fi) > "$build/$t.status" &
done
wait
status=0
for t in "${targets[@]}"; do
  cat "$build/$t.summary"
  [ "$(cat "$build/$t.status")" = 0 ] || status=1
done
exit $status
