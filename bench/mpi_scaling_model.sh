#!/usr/bin/env bash
# The 1 -> 64 rank model of docs/parallel.md ("Distributed memory (METIS + MPI)"), from the
# output of bench/mpi_scaling.sh: per scene, the measured 1-rank phase split and the METIS
# statistics (cut faces, halo sizes, neighbour counts) for 2 .. 64 ranks.
#   bench/mpi_scaling.sh > scaling.log ; bench/mpi_scaling_model.sh scaling.log
# Per step on P ranks (times in seconds):
#   T(P) = t_s (1 + imbalance_P) / P                       structure, METIS-balanced
#        + t_c                                             contact, replicated on every rank
#        + n_nb,max alpha + 24 pairs_max / beta            halo exchange (3 doubles per node)
#        + c alpha ceil(log2 P)                            reductions (dt, energies)
#        + g (alpha ceil(log2 P) + 72 R (P-1)/P / beta)    contact region gathers (x, v, a)
#   E(P) = (t_s + t_c) / (P T(P)).
# t_s = NS_PER_ELEMENT_STEP x elements (unloaded one-core step; default the 20 ns),
# t_c from the measured 1-rank contact share (thread CPU time, robust to machine load); c and g are the measured reductions and gathers
# per step; alpha, beta: a cluster interconnect's latency and bandwidth (defaults below).
# REGION=n replaces the contact region's node count (e.g. the surface layer of the same scene with
# restitution 1, which bench_partitioned_run SCENE --partitions 2 prints).
set -euo pipefail
log="${1:?usage: bench/mpi_scaling_model.sh SCALING_LOG}"
awk -v ns="${NS_PER_ELEMENT_STEP:-20e-9}" -v alpha="${ALPHA:-2e-6}" -v beta="${BETA:-5e9}" \
  -v region_override="${REGION:-}" '
function log2ceil(p,  k) { k = 0; while (2 ^ k < p) ++k; return k }
function field(name,  i, kv) {
  for (i = 1; i <= NF; ++i) { split($i, kv, "="); if (kv[1] == name) return kv[2] }
  return ""
}
/^== / { scene = $2; n1 = 0; s1 = 0; c1 = 0; coll = 0; gath = 0; found = 0 }
/^mode=partitioned ranks=1 / { s1 += field("structure_cpu_s"); c1 += field("contact_cpu_s"); ++n1 }
/^mode=partitioned ranks=2 / {
  coll = field("collectives_per_step"); region = field("contact_region")
  if (region > 0 && region_override != "") region = region_override
  gath = field("region_gathers_per_step")
  if (gath == "") gath = region > 0 ? 2 : 0  # logs from before the count: two per step
  coll -= gath
}
/^partitions=/ {
  P = field("partitions"); E = field("elements")
  if (P == 2) {
    share = (s1 + c1) > 0 ? c1 / (s1 + c1) : 0
    ts = ns * E; tc = share < 1 ? ts * share / (1 - share) : 0
    printf "%s: %d tets, contact share of the 1-rank step %.1f %%, contact region %d nodes\n", scene, E, 100 * share, region
    printf "  ranks  t_struct[us]  t_contact  t_halo  t_reduce  t_gather  T[us]   E\n"
    printf "  %5d  %12.1f  %9.1f  %6.1f  %8.1f  %8.1f  %6.1f  100.0 %%\n", 1, 1e6 * ts, 1e6 * tc, 0, 0, 0, 1e6 * (ts + tc)
    below = 0
  }
  l = log2ceil(P)
  t_s = ts * (1 + field("imbalance")) / P
  t_h = field("neighbours_max") * alpha + 24 * field("halo_pairs_max") / beta
  t_r = coll * alpha * l
  t_g = gath * (alpha * l + 72 * region * (P - 1) / P / beta)
  T = t_s + tc + t_h + t_r + t_g
  eff = (ts + tc) / (P * T)
  printf "  %5d  %12.1f  %9.1f  %6.1f  %8.1f  %8.1f  %6.1f  %5.1f %%\n", P, 1e6 * t_s, 1e6 * tc, 1e6 * t_h, 1e6 * t_r, 1e6 * t_g, 1e6 * T, 100 * eff
  if (eff < 0.8 && !below) { below = 1; printf "  -> efficiency below 80 %% from %d ranks on\n", P }
}
' "$log"
