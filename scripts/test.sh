#!/usr/bin/env bash
# The README's test command: installs dependencies, builds ccm twice (optimised with g++, and with
# clang under AddressSanitizer + UndefinedBehaviorSanitizer) and runs the unit test suite in both
# (under the sanitizers without its few long physics runs, tag [heavy], label unit-heavy:
# tests/CMakeLists.txt), then fuzzes each reader of outside input for a few seconds
# (docs/fuzzing.md). The suite runs in a few processes (scripts/unit-shards.sh), not one per
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

phase "sanitizer build (build-asan/: clang, AddressSanitizer + UBSan, and the fuzz targets)"
# clang-14 at -O1 -g1 (line tables only, for the sanitizers' stack traces), with the libFuzzer
# targets of fuzz/ (CCM_FUZZ: the readers' libraries instrumented for coverage; docs/fuzzing.md).
CC=clang-14 CXX=clang++-14 cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCCM_SANITIZE=ON -DCCM_FUZZ=ON \
  -DCCM_BUILD_BENCH=OFF -DCCM_UNITY_BUILD=ON >/dev/null
cmake --build build-asan -j "$jobs"
phase "sanitizer tests"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions="$(pwd)/tests/lsan.supp" CCM_MESH_CACHE="$cache_root/sanitizer" \
  scripts/unit-shards.sh build-asan "~[validation]~[heavy]" "$jobs"  # = ctest -L unit -LE heavy
phase "fuzz smoke (15 s per reader)"
CCM_FUZZ_BUILD=build-asan scripts/fuzz.sh 15
phase "done"
