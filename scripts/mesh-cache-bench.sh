#!/usr/bin/env bash
# The mesh cache's set-up saving (docs/mesh-cache.md): `ccm run` twice on a block of about 200k
# tets with an empty mesh cache, then once with --no-mesh-cache; prints each run's set-up line and
# the second run's set-up over the first's.
#
#   scripts/mesh-cache-bench.sh [build/ccm]
set -euo pipefail
ccm=${1:-build/ccm}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat >"$work/block.toml" <<'TOML'
title = "a 10 cm block of about 200k tets, a few steps"
[time]
end = 2e-6
[[bodies]]
name = "block"
initial_velocity = [0.0, 0.0, -1.0]
[bodies.material]
E = 1e6
nu = 0.3
rho = 1000.0
[bodies.geometry]
shape = "box"
size = [0.1, 0.1, 0.1]
mesh_size = 0.003
TOML
setup() { grep -E "^  set-up" "$1" | sed 's/^  set-up *//'; }
export CCM_MESH_CACHE="$work/meshes"
"$ccm" run "$work/block.toml" --out "$work/first" >"$work/first.txt"
"$ccm" run "$work/block.toml" --out "$work/second" >"$work/second.txt"
"$ccm" run "$work/block.toml" --out "$work/off" --no-mesh-cache >"$work/off.txt"
echo "elements: $(grep -E '^  elements' "$work/first.txt" | awk '{print $2}')"
echo "first run (empty cache):  $(setup "$work/first.txt")"
echo "second run (from cache):  $(setup "$work/second.txt")"
echo "--no-mesh-cache:          $(setup "$work/off.txt")"
first=$(grep -E '^setup_seconds' "$work/first/summary.toml" | awk '{print $3}')
second=$(grep -E '^setup_seconds' "$work/second/summary.toml" | awk '{print $3}')
python3 -c "print(f'second / first set-up: {$second / $first:.3f}')"
