#!/usr/bin/env bash
# The README's test command: installs dependencies, builds ccm twice (optimised, and with
# AddressSanitizer + UndefinedBehaviorSanitizer) and runs the unit test suite in both (under the
# sanitizers without its few long physics runs, tag [heavy], label unit-heavy:
# tests/CMakeLists.txt). The suite runs in a few processes (scripts/unit-shards.sh), not one per
# test case as `ctest -L unit` does: the same test cases, without 375 process starts.
# Validation tests (label `validation`) are slower and run with scripts/validate.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
jobs=$(nproc)
# Each pass meshes into its own empty mesh cache (docs/mesh-cache.md): the tests never read a mesh
# an earlier build made, and within a pass a body meshed once is read back.
cache_root=$(mktemp -d)
trap 'rm -rf "$cache_root"' EXIT

# Both builds are unity builds (CCM_UNITY_BUILD, cmake/BuildSpeed.cmake, docs/build.md).
phase() { echo "== $1 ($((SECONDS / 60)) min $((SECONDS % 60)) s since the start)"; }
phase "optimised build (build/)"
# CCM_BUILD_TESTS=ON explicitly: scripts/run.sh configures the same folder without the tests.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCCM_UNITY_BUILD=ON -DCCM_BUILD_TESTS=ON \
  -DCCM_BUILD_BENCH=ON >/dev/null
cmake --build build -j "$jobs"
phase "optimised tests"
CCM_MESH_CACHE="$cache_root/optimised" scripts/unit-shards.sh build "~[validation]" "$jobs"  # = ctest -L unit

phase "sanitizer build (build-asan/: AddressSanitizer + UBSan)"
# -O1 -g1: line tables only for the sanitizers' stack traces; -O1 compiles in 866 s against
# about 22 min at -O2. (The special flag -fexpensive-optimizations is gone: the coarse Hertz
# test's energy balance read 5.0 % at -O1 and 0.8 % at -O3 because the step alternated between
# a full and a short step at every output time, which the leapfrog energy measure does not
# follow; the landing steps are now equal, and the balance reads 2.6e-5 at -O1 and -O3.)
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCCM_SANITIZE=ON -DCCM_BUILD_BENCH=OFF -DCCM_UNITY_BUILD=ON >/dev/null
cmake --build build-asan -j "$jobs"
phase "sanitizer tests"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions="$(pwd)/tests/lsan.supp" CCM_MESH_CACHE="$cache_root/sanitizer" \
  scripts/unit-shards.sh build-asan "~[validation]~[heavy]" "$jobs"  # = ctest -L unit -LE heavy
phase "done"
