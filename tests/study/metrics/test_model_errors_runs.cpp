// The cumulative errors (eqs. 2.34-2.36, time averages: docs/metrics.md) of real runs of a small
// point, CCM and rigid, each run twice: at an output interval of 0.5 ms and of 0.25 ms (30 and 60
// samples over the 15 ms after contact). The error must not follow the sampling: the two
// readings agree within 1 % (the issue's criterion), while the sum over samples as printed in
// the thesis doubles.
//
// What is left is the trapezoidal rule's resolution of the histories, O(dt^2), not a dependence
// on the rate. Measured (u_max; u_mean alike): 3.4796e-3, 3.3028e-3, 3.2543e-3, 3.2386e-3,
// 3.2346e-3 at 2, 1, 0.5, 0.25, 0.125 ms, successive changes shrinking 3.6, 3.1 and 3.9 times per
// halving; the runs themselves agree (u_max on a common 2 ms grid within 0.3 % across all five).
// Between 1 and 0.5 ms (15 samples over the contact) the change is 1.5 %, between 0.5 and 0.25
// ms 0.49 % (u_max), 0.56 % (u_mean), 0.02 % (KE): hence the pair used here.
#include <catch2/catch.hpp>
#include <string>

#include "run/runner/point_runner.hpp"
#include "study/grid/grid_file.hpp"
#include "study/metrics/model_errors.hpp"
#include "tests/support/tolerance.hpp"

using ccm::test::relative_error;
using namespace ccm::study;

namespace {

// The point runner's test point (a few hundred tets): contact from t_c = 5 ms to t_f = 20 ms.
std::string tiny_grid(const char* output_interval) {
  return std::string(R"([axes]
ER = [1.0]
RLS = [0.5]
KE = [10.0]

[time]
contact_time = 0.005
end = 0.02
output_interval = )") +
         output_interval + R"(

[artifact]
length = 1.0
thickness = 0.25
E = 1000.0
nu = 0.49
rho = 1000.0
mesh_size = 0.25

[impactor]
nu = 0.49
rho = 1000.0
mesh_size_ratio = 0.4
)";
}

struct Errors {
  double u_mean = 0.0, u_max = 0.0, kinetic_energy = 0.0;
  double printed_u_max = 0.0;  // sum over samples of (c - r)^2, the thesis's numerator
  size_t samples = 0;
};

Errors errors_at(const char* output_interval) {
  const GridSpec g = parse_grid(tiny_grid(output_interval), "tiny.toml");
  GridPoint p;
  p.index = 0;
  p.modulus_ratio = 1.0;
  p.length_ratio = 0.5;
  p.kinetic_energy = 10.0;
  const RunRecord c = run_point(g, p, ImpactModel::ccm);
  const RunRecord r = run_point(g, p, ImpactModel::rigid);
  REQUIRE(c.completed());
  REQUIRE(r.completed());
  REQUIRE(c.artifact.time == r.artifact.time);
  const ArtifactHistory &hc = c.artifact, &hr = r.artifact;
  Errors e;
  e.u_mean = cumulative_error(hc.time, hc.u_mean, hr.u_mean);
  e.u_max = cumulative_error(hc.time, hc.u_max, hr.u_max);
  e.kinetic_energy = cumulative_error(hc.time, hc.kinetic_energy, hr.kinetic_energy);
  for (size_t i = 0; i < hc.time.size(); ++i)
    e.printed_u_max += (hc.u_max[i] - hr.u_max[i]) * (hc.u_max[i] - hr.u_max[i]);
  e.samples = hc.time.size();
  // Uniform samples: the form without times gives the same.
  CHECK(relative_error(cumulative_error(hc.u_max, hr.u_max), e.u_max) < 1e-12);
  return e;
}

}  // namespace

TEST_CASE("cumulative errors of real runs do not follow the output interval", "[metrics][heavy]") {
  const Errors coarse = errors_at("5e-4");
  const Errors fine = errors_at("2.5e-4");
  INFO("0.5 ms: u_mean " << coarse.u_mean << ", u_max " << coarse.u_max << ", KE "
                         << coarse.kinetic_energy << "; 0.25 ms: u_mean " << fine.u_mean
                         << ", u_max " << fine.u_max << ", KE " << fine.kinetic_energy);
  CHECK(coarse.samples == 41);
  CHECK(fine.samples == 81);
  CHECK(coarse.u_max > 0.0);
  CHECK(relative_error(fine.u_mean, coarse.u_mean) < 0.01);
  CHECK(relative_error(fine.u_max, coarse.u_max) < 0.01);
  CHECK(relative_error(fine.kinetic_energy, coarse.kinetic_energy) < 0.01);
  // The printed sum over samples about doubles with the samples (what the time average fixes):
  // measured 1.86, not 2, because the sum weighs its end samples fully, and the last is the
  // largest difference.
  INFO("printed sums " << coarse.printed_u_max << ", " << fine.printed_u_max);
  CHECK(fine.printed_u_max / coarse.printed_u_max > 1.8);
}
