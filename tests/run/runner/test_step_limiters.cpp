// What set each step of a run (RunSummary's limiter counts), and the claim of
// docs/contact-time-step.md that neither contact model limits the step before the sphere can
// reach the plate: before then both runs step at the structural rate.
#include <catch2/catch.hpp>
#include <cmath>
#include <string_view>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "run/scene/point_scene.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "study/grid/grid_file.hpp"
#include "study/grid/point_parameters.hpp"

using namespace ccm;
using namespace ccm::study;

namespace {

// A fast approach over a long gap: v_I = sqrt(2 KE / m_I) = 5.53 m/s (m_I = 65.4 kg), gap
// v_I t_c = 1.1 m, much more than the reach of a structural step. At this speed (1.5 x
// the plate's dilatational wave speed) the DCR limit 0.25 h_min / v_I is shorter than the
// structural step, so a DCR limit that ignored the distance would bind from t = 0. Coarse meshes (a
// few thousand tets); one output, at t_f.
constexpr std::string_view kApproachGrid = R"([axes]
ER = [1.0]
RLS = [0.5]
KE = [1000.0]

[time]
contact_time = 0.2
end = 0.21
output_interval = 0.21

[artifact]
length = 1.0
thickness = 0.25
E = 1.0e4
nu = 0.3
rho = 1000.0
mesh_size = 0.125

[impactor]
nu = 0.3
rho = 1000.0
mesh_size_ratio = 0.25
)";

GridPoint approach_point() {
  GridPoint p;
  p.modulus_ratio = 1.0;
  p.length_ratio = 0.5;
  p.kinetic_energy = 1000.0;
  return p;
}

struct Run {
  RunSummary summary;
  double dcr_min_edge = 0.0;  // the DCR model's shortest surface edge (ccm model only)
};

Run run_model(const GridSpec& spec, ImpactModel model) {
  const Scene scene = point_scene(spec, approach_point(), model);
  const Model built = build_model(scene);
  const ContactSetup contact = build_contact(scene, built);
  RunOptions options;
  options.time = time_control(scene.time);
  options.monitor = scene.monitor;
  options.contact = contact.model.get();
  Run r;
  r.summary = run_explicit(built, options);
  if (const auto* dcr = dynamic_cast<const dcr::DcrContact*>(contact.model.get()))
    r.dcr_min_edge = dcr->min_edge();
  return r;
}

void check_accounting(const RunSummary& s, double end_time) {
  INFO(s.instability.reason);
  REQUIRE(s.verdict == Verdict::completed);
  REQUIRE(s.steps > 0);
  // Each step is counted once, by what set it.
  CHECK(s.limiters.total() == s.steps);
  // The first step taken is within the recorded range; before contact it is the structural one.
  CHECK(s.dt_first >= s.dt_min);
  CHECK(s.dt_first <= s.dt_max);
  // steps x mean step = time reached = end time (1e-12: one division)
  CHECK(s.end_time == Approx(end_time).epsilon(1e-12));
  CHECK(static_cast<double>(s.steps) * s.dt_mean == Approx(end_time).epsilon(1e-12));
  // The loop's CPU time is measured and cannot exceed the run's wall time on one thread by more
  // than the clocks' granularity (1 ms allowed).
  CHECK(s.step_cpu_seconds > 0.0);
  CHECK(s.step_cpu_seconds <= s.step_wall_seconds + 1e-3);
  CHECK(s.step_wall_seconds <= s.wall_seconds);
  if (s.limiters.contact > 0) {
    CHECK(s.dt_contact_min >= s.dt_min);
    CHECK(s.first_contact_step_time >= 0.0);
  }
}

}  // namespace

TEST_CASE("rigid and DCR runs take no contact-limited step before the sphere can reach the plate",
          "[study][step_limit]") {
  const GridSpec spec = parse_grid(kApproachGrid, "approach.toml");
  const PointParameters p = point_parameters(spec, approach_point());
  const double v = p.impact_speed, gap = p.gap, R = 0.5 * p.impactor_diameter;
  REQUIRE(gap == Approx(0.2 * v));
  const double t_touch = gap / v;  // the sphere's lowest point reaches the plate's top face

  SECTION("rigid: structural steps until the sphere is within two steps' reach of the plate") {
    const Run run = run_model(spec, ImpactModel::rigid);
    const RunSummary& s = run.summary;
    check_accounting(s, 0.21);
    CHECK(s.dt_first == Approx(s.dt_initial).epsilon(1e-12));  // structural, not contact
    REQUIRE(s.limiters.contact > 0);
    // The plate's quadrature points lie in its top face, at least gap + R from the sphere's
    // centre, and the plate is at rest: the limit counts a point once twice the sphere's travel
    // in the step could bring it within 1e-6 R of the sphere (docs/contact-time-step.md), so the
    // first contact-limited step starts no earlier than 2 structural steps dt_s before
    // t_m = (gap - 1e-6 R) / v.
    const double t_m = (gap - 1e-6 * R) / v;
    INFO("first contact-limited step at " << s.first_contact_step_time << " s; t_m " << t_m
                                          << " s, structural step " << s.dt_initial << " s");
    CHECK(s.first_contact_step_time >= t_m - 2.0 * s.dt_initial * (1.0 + 1e-9));
    // ... and the limit is on before the sphere touches.
    CHECK(s.first_contact_step_time < t_touch);
    // Before it, every step was structural (no output time before t_f): at least t_m / dt_s - 2.
    CHECK(s.limiters.structure >= static_cast<long>(t_m / s.dt_initial) - 2);
  }

  SECTION("DCR: structural steps until the bodies are within 0.6 h_min of each other") {
    const Run run = run_model(spec, ImpactModel::ccm);
    const RunSummary& s = run.summary;
    check_accounting(s, 0.21);
    REQUIRE(run.dcr_min_edge > 0.0);
    // The limit DCR would impose at the approach speed is shorter than the structural step, so
    // this run shows the distance rule at work.
    const double dt_dcr = 0.5 * run.dcr_min_edge / (2.0 * v);
    REQUIRE(dt_dcr < s.dt_initial);
    CHECK(s.dt_first == Approx(s.dt_initial).epsilon(1e-12));
    REQUIRE(s.limiters.contact > 0);
    // The meshed sphere's nodes lie on or inside its analytic surface, so the gap between the
    // two bodies' boxes is at least `gap` at t = 0; it closes at v. The limit engages when
    // twice the step's reach covers the gap less p + 0.5 h_min = 0.6 h_min
    // (docs/contact-time-step.md, DCR "Only near contact"): not before 2 steps before t_m.
    const dcr::DcrSettings defaults;
    const double near = (defaults.proximity + defaults.step_fraction) * run.dcr_min_edge;
    const double t_m = (gap - near) / v;
    INFO("first contact-limited step at " << s.first_contact_step_time << " s; t_m " << t_m
                                          << " s, structural step " << s.dt_initial << " s");
    CHECK(s.first_contact_step_time >= t_m - 2.0 * s.dt_initial * (1.0 + 1e-9));
    CHECK(s.limiters.structure >= static_cast<long>(t_m / s.dt_initial) - 2);
  }
}
