#!/usr/bin/env bash
# Strong scaling of a partitioned run, 1 -> 2 ranks, on the two 200k-tet scenes of bench/scenes
# (no contact; DCR ball on a plate), and the partition statistics for 2 .. 64 ranks that the
# scaling model of docs/parallel.md ("Distributed memory (METIS + MPI)") takes as input.
#   bench/mpi_scaling.sh [REPEATS]      (default 3; the machine load is printed before each set)
# Per scene and repeat: the serial integrator, the partitioned run on 1 rank (its phase split)
# and on 2 ranks; then the efficiencies of the repeat: whole step T_serial / (2 T_2) and, per
# phase, T_1,phase / (2 T_2,phase), in wall time (slowest rank) and in thread CPU time (which
# leaves out the time a rank waits, descheduled, for its peer on a shared machine).
# Then, per scene, REPEATS alternating rounds in one mpirun job (bench_partitioned_run
# --alternate): the serial run on rank 0 while rank 1 sleeps, then the 2-rank run, seconds apart,
# each round's efficiency and their median (the machine's speed drifts between minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
repeats="${1:-3}"
cmake --build build -j 2 --target bench_partitioned_run >/dev/null
mpi=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
value() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$2"; }
# SCENES="a.toml b.toml" replaces the two scenes.
for scene in ${SCENES:-bench/scenes/plate_200k.toml bench/scenes/ball_on_plate_dcr_200k.toml}; do
  echo "== $scene"
  for r in $(seq "$repeats"); do
    echo "# repeat $r, $(date -u +%H:%M:%S) UTC, load average $(uptime | sed 's/.*load average: //')"
    serial=$(./build/bench_partitioned_run "$scene" --serial) && echo "$serial"
    one=$("${mpi[@]}" -np 1 ./build/bench_partitioned_run "$scene") && echo "$one"
    two=$("${mpi[@]}" -np 2 ./build/bench_partitioned_run "$scene") && echo "$two"
    awk -v ts="$(value step_s "$serial")" -v t2="$(value step_s "$two")" \
      -v s1="$(value structure_s "$one")" -v s2="$(value structure_s "$two")" \
      -v c1="$(value contact_s "$one")" -v c2="$(value contact_s "$two")" \
      -v m2="$(value communication_s "$two")" \
      -v s1c="$(value structure_cpu_s "$one")" -v s2c="$(value structure_cpu_s "$two")" \
      -v c1c="$(value contact_cpu_s "$one")" -v c2c="$(value contact_cpu_s "$two")" 'BEGIN {
        printf "efficiency (wall): whole step %.1f %%, structure %.1f %%, contact %s, communication %.1f %% of the 2-rank step\n",
          100 * ts / (2 * t2), 100 * s1 / (2 * s2),
          (c2 > 0 ? sprintf("%.1f %%", 100 * c1 / (2 * c2)) : "none"), 100 * m2 / t2
        printf "efficiency (thread CPU): structure %.1f %%, contact %s, structure + contact %.1f %%\n",
          100 * s1c / (2 * s2c), (c2c > 0 ? sprintf("%.1f %%", 100 * c1c / (2 * c2c)) : "none"),
          100 * (s1c + c1c) / (2 * (s2c + c2c)) }'
  done
  "${mpi[@]}" -np 2 ./build/bench_partitioned_run "$scene" --alternate "$repeats"
  ./build/bench_partitioned_run "$scene" --partitions 2,4,8,16,32,64
done
