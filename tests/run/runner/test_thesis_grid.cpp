// The whole thesis grid (scenes/grids/thesis.toml, 36 points x 2 models) and its convergence
// runs, run in-process: a measurement, printed as a table (per-run wall time, steps, verdict,
// artifact kinetic energy at t_f for both models). It asserts only what must hold whatever the
// physics shows: every grid run completes (a convergence run may end unstable, with a reason),
// both models of a point share the sample times, and the artifact is at rest (to round-off)
// before the step in which the sphere reaches it at t_c.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "run/runner/point_runner.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"

using namespace ccm::study;

namespace {

// Largest |KE_c - KE_r| over the run, relative to the largest KE_r.
double largest_energy_difference(const ArtifactHistory& c, const ArtifactHistory& r) {
  double diff = 0.0;
  double peak = 0.0;
  for (size_t i = 0; i < c.kinetic_energy.size(); ++i) {
    diff = std::max(diff, std::abs(c.kinetic_energy[i] - r.kinetic_energy[i]));
    peak = std::max(peak, r.kinetic_energy[i]);
  }
  return peak > 0.0 ? diff / peak : 0.0;
}

void print_pair(const RunRecord& c, const RunRecord& r) {
  const GridPoint& p = c.point;
  std::string extra;
  for (const auto& [name, value] : p.other_axes) extra += fmt::format(" {}={}", name, value);
  const double nt_ratio =
      (c.average_iteration_seconds / c.initial_stable_dt) /
      (r.average_iteration_seconds / r.initial_stable_dt);  // RTR, eq. 2.40-2.42
  fmt::print(
      "{:3} {:7.0e} {:4} {:5}{} | ccm {:9} {:7} st {:7.2f} s {:6} el ISTS {:.2e} KE(tf) {:.4e} | "
      "rigid {:9} {:6} st {:6.2f} s {:5} el ISTS {:.2e} KE(tf) {:.4e} | KE c/r {:.3f} "
      "max|dKE|/KEr {:.3f} RTR {:.3g}\n",
      p.index, p.modulus_ratio, p.length_ratio, p.kinetic_energy, extra, c.verdict, c.steps,
      c.wall_seconds, c.n_elements, c.initial_stable_dt, c.artifact.kinetic_energy.back(),
      r.verdict, r.steps, r.wall_seconds, r.n_elements, r.initial_stable_dt,
      r.artifact.kinetic_energy.back(),
      c.artifact.kinetic_energy.back() / r.artifact.kinetic_energy.back(),
      largest_energy_difference(c.artifact, r.artifact), nt_ratio);
  if (!c.completed()) fmt::print("    ccm: {} at t = {}\n", c.reason, c.unstable_time);
  if (!r.completed()) fmt::print("    rigid: {} at t = {}\n", r.reason, r.unstable_time);
  std::fflush(stdout);
}

// require_completed: every run must complete; otherwise an unstable run must say why, and only
// completed pairs are compared.
void run_and_check(const GridSpec& g, const std::vector<GridPoint>& points,
                   bool require_completed) {
  double wall = 0.0;
  for (const GridPoint& p : points) {
    const RunRecord c = run_point(g, p, ImpactModel::ccm);
    const RunRecord r = run_point(g, p, ImpactModel::rigid);
    print_pair(c, r);
    wall += c.wall_seconds + r.wall_seconds;
    INFO("point " << p.index);
    for (const RunRecord* run : {&c, &r}) {
      if (require_completed) CHECK(run->completed());
      if (!run->completed()) CHECK(!run->reason.empty());
    }
    if (!c.completed() || !r.completed()) continue;
    CHECK(c.artifact.time == r.artifact.time);
    // At rest up to the round-off of the internal forces at F = I (~1e-27 J measured) before the
    // step in which the sphere reaches the plate. DCR exchanges momentum at the start of that
    // step (the velocity row lets a contact close only what is left of its gap, less the kept
    // separation, over the next step: docs/contact-method.md, "velocity row"), so with a 1 ms step
    // (ER = 1) the sample at t_c - 1 ms already holds that impulse (1.4e-8 J for ER 1, RLS 0.5, KE
    // 10). Every model's step before the touch is at most its initial stable step.
    for (const RunRecord* run : {&c, &r})
      for (size_t i = 0; i < run->artifact.time.size(); ++i)
        if (run->artifact.time[i] < g.time.contact_time - run->initial_stable_dt - 1e-9)
          CHECK(run->artifact.kinetic_energy[i] < 1e-12 * p.kinetic_energy);
  }
  fmt::print("total run wall time (set-up excluded): {:.1f} s\n", wall);
}

}  // namespace

TEST_CASE("thesis grid: all 72 runs", "[validation][grid-thesis]") {
  const GridSpec g = parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/thesis.toml");
  run_and_check(g, expand_grid(g), true);
}

TEST_CASE("thesis grid: convergence runs", "[validation][grid-convergence]") {
  const GridSpec g = parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/thesis.toml");
  // Measured: at mesh_scale 0.5, ER = 1 the DCR projection fails to converge at t = 0.131 s
  // (an engine limit, reported, not hidden): unstable runs are allowed here, with a reason.
  run_and_check(g, expand_convergence(g), false);
}
