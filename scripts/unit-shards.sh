#!/usr/bin/env bash
# Runs the Catch2 tests of BUILD_DIR/tests/ccm_tests that match SPEC in a few processes instead of
# one process per test case (ctest's way, tests/CMakeLists.txt):
#
#   scripts/unit-shards.sh BUILD_DIR SPEC [JOBS]
#
# Why: starting the test executable costs about 0.18 CPU-s optimised and 0.42 under the sanitizers
# (dynamic loading, the sanitizers' set-up and leak check), so 375 starts were a quarter of the
# test time of scripts/test.sh (docs/build.md, "Test shards"). Here the matching test cases, in
# name order, are dealt round-robin into 4 x JOBS shard files, and JOBS processes at a time run
# one shard each (`ccm_tests -f SHARD`, in BUILD_DIR/tests like ctest). Every test case runs
# exactly once; the script fails when any shard fails, when a shard runs fewer test cases than
# it was given, or when no test case matches. It ends with the slowest test cases of the pass.
set -euo pipefail

build=${1:?usage: unit-shards.sh BUILD_DIR SPEC [JOBS]}
spec=${2:?usage: unit-shards.sh BUILD_DIR SPEC [JOBS]}
jobs=${3:-$(nproc)}
binary="$(cd "$build" && pwd)/tests/ccm_tests"
[[ -x $binary ]] || { echo "unit-shards: no test executable $binary" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# (Catch2 v2's list options exit with the number of names listed, not 0.)
{ "$binary" --list-test-names-only "$spec" || true; } | sed '/^[[:space:]]*$/d' >"$work/names"
total=$(wc -l <"$work/names")
((total > 0)) || { echo "unit-shards: no test case matches $spec" >&2; exit 1; }
shards=$((4 * jobs))
# A test name in a shard file is a test spec: its commas and brackets are escaped (as
# catch_discover_tests does).
sed 's/[],[]/\\&/g' "$work/names" |
  awk -v n="$shards" -v dir="$work" '{ print > (dir "/shard." (NR - 1) % n) }'

run_shard() {  # one shard: its own log, and a line "STATUS SHARD: N test cases" (0: passed)
  local file=$1 binary=$2 given status=0
  given=$(wc -l <"$file")
  # A shard that hangs fails after SHARD_TIMEOUT seconds (default 1200; the slowest shard of a
  # pass takes about 90 s under the sanitizers) instead of holding CI to its 90-minute limit.
  (cd "$(dirname "$binary")" &&
    timeout --kill-after=10 "${SHARD_TIMEOUT:-1200}" "$binary" -f "$file" --reporter compact \
      --durations yes) >"$file.log" 2>&1 || status=$?
  if ((status == 124 || status == 137)); then
    echo "unit-shards: timed out after ${SHARD_TIMEOUT:-1200} s" >>"$file.log"
  fi
  # On success the compact reporter ends with "Passed all N test cases with M assertions."
  # ("Passed both 2 test cases ...", "Passed 1 test case ..."): a shard that ran fewer than it
  # was given fails.
  if ((status == 0)) && ! grep -Eq "^Passed (all |both )?$given test cases? with" "$file.log"; then
    status=99
  fi
  echo "$status $(basename "$file"): $given test cases"
  return 0
}
export -f run_shard

start=$SECONDS
shard_files=("$work"/shard.*)  # listed before any shard writes its log beside it
printf '%s\n' "${shard_files[@]}" | xargs -P "$jobs" -I{} bash -c 'run_shard "$@"' _ {} "$binary" |
  tee "$work/results"
failed=0
while read -r status name _; do
  if ((status != 0)); then
    failed=1
    echo "== ${name%:} failed; its output:"
    cat "$work/${name%:}.log"
  fi
done <"$work/results"
echo "unit-shards: the slowest test cases (and sections) of this pass:"
# (awk, not head: it reads all of sort's output, so sort never gets SIGPIPE under pipefail)
{ cat "$work"/shard.*.log | grep -E '^[0-9]+\.[0-9]+ s: ' || true; } | sort -rn |
  awk 'NR <= 8 { print "  " $0 }'
echo "unit-shards: $total test cases matching $spec in $shards shards, $((SECONDS - start)) s"
exit "$failed"
