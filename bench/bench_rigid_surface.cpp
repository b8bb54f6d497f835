// The cost of contact against a meshed rigid body against the analytic sphere's, per active
// contact point (issue 31's floor: a rigid box of 10k surface triangles resting on a deformable
// block adds at most 2x the contact cost the analytic sphere adds per active contact point).
//
//   ./build/bench_rigid_surface [--steps N] [--repeats R]
//
// Both cases press a rigid body onto the same soft block (200 x 200 x 50 mm, 12,000 tets, bottom
// fixed) under gravity with the per-point penalty (K_P 1e4 N/m): (a) the analytic sphere
// (R = 0.5 m, nearly flat over the block), (b) a free rigid box of 100 x 100 x 20 mm meshed
// 45 x 45 x 5 (9,900 surface triangles); both weigh 5 kg (so both rest on several hundred active
// points) and are released 0.1 mm above the block. Each run times, in thread CPU time, the
// contact model's calls (begin_step, add_forces, step_bound, end_step) over N steps after the
// contact has formed, and counts the active quadrature points each step; the cost per active
// point-step is formed within each run, and the ratio (b) / (a) of the medians over R repeats is
// printed with the range, and each phase's share of each model's time.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bench/bench_statistics.hpp"
#include "engine/bc/node_selection.hpp"
#include "engine/body/rigid_body_model.hpp"
#include "engine/contact/penalty/rigid_surface_penalty.hpp"
#include "engine/contact/rigid_sphere_penalty.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"

using namespace ccm;

namespace {

double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

const Vec3 kGravity(0.0, 0.0, -9.81);
constexpr double kTop = 0.05;  // the block's top face

// Times a contact model's calls and counts its active points after `skip` steps.
template <typename Model>
class Timed : public ContactModel {
 public:
  Timed(Model& inner, long skip)
      : ContactModel(inner.name(), inner.phases()), inner_(inner), skip_(skip) {}
  void begin_step(const State& s, double dt) override {
    timed(phase[0], [&] { inner_.begin_step(s, dt); });
  }
  void add_forces(State& s) override {
    timed(phase[1], [&] { inner_.add_forces(s); });
  }
  void correct(State& s, double dt) override { inner_.correct(s, dt); }
  void end_step(const State& s, double dt) override {
    timed(phase[3], [&] { inner_.end_step(s, dt); });
    ledger_ = inner_.ledger();
    if (++steps_ > skip_) point_steps += inner_.active_points();
  }
  ContactStepBound step_bound(const State& s, double ceiling) const override {
    ContactStepBound b;
    auto* self = const_cast<Timed*>(this);
    self->timed(self->phase[2], [&] { b = inner_.step_bound(s, ceiling); });
    return b;
  }
  double corrected_elements_stable_dt() const override {
    return inner_.corrected_elements_stable_dt();
  }
  double seconds = 0.0;
  double phase[4] = {0.0, 0.0, 0.0, 0.0};  // begin_step, add_forces, step_bound, end_step
  long point_steps = 0;

 private:
  template <typename F>
  void timed(double& in_phase, F f) {
    const double t0 = thread_seconds();
    f();
    if (steps_ < skip_) return;
    const double dt = thread_seconds() - t0;
    seconds += dt;
    in_phase += dt;
  }
  Model& inner_;
  long skip_, steps_ = 0;
};

ModelMesh block() {
  ModelMesh mesh;
  TetMesh b = structured_box(Vec3(0.2, 0.2, 0.05), 20, 20, 5);
  for (Vec3& x : b.nodes) x -= Vec3(0.1, 0.1, 0.0);
  add_body(mesh, "block", {MaterialModel::neo_hookean, 1e5, 0.3, 1000.0}, b);
  return mesh;
}

Model fixed_base(ModelMesh mesh) {
  Model m = make_model(std::move(mesh));
  m.bcs.fix(nodes_on_plane(m.mesh, 0, Vec3::Zero(), Vec3::UnitZ(), 1e-9));
  m.bcs.gravity = kGravity;
  return m;
}

struct Cost {
  double per_point_step = 0.0;  // [s]
  double points = 0.0;          // mean active points per timed step
  double share[4] = {};         // of the time: begin_step, add_forces, step_bound, end_step
};

template <typename Model>
Cost cost_of(const Timed<Model>& timed, long steps) {
  Cost c{timed.seconds / static_cast<double>(timed.point_steps),
         static_cast<double>(timed.point_steps) / static_cast<double>(steps)};
  for (int k = 0; k < 4; ++k) c.share[k] = timed.phase[k] / timed.seconds;
  return c;
}

void report(const RunSummary& s) {
  if (s.steps == 0 || (s.verdict == Verdict::unstable &&
                       s.instability.reason.find("step limit") == std::string::npos))
    std::fprintf(stderr, "run: %ld steps, %s\n", s.steps, s.instability.reason.c_str());
}

RunOptions timed_run(long skip, long steps) {
  RunOptions o;
  o.time.max_steps = skip + steps;
  o.time.end_time = 1.0;
  o.threads = 1;
  return o;
}

Cost sphere_cost(long skip, long steps) {
  Model m = fixed_base(block());
  RigidSpherePenaltyParams p;
  p.sphere = {0.5, 5.0, Vec3(0.0, 0.0, kTop + 0.5 + 1e-4), Vec3::Zero()};
  p.penalty = 1e4;
  p.damping = 1.0;
  p.gravity = kGravity;
  RigidSpherePenalty sphere(m.mesh.bodies[0].boundary, p);
  Timed<RigidSpherePenalty> timed(sphere, skip);
  RunOptions o = timed_run(skip, steps);
  o.contact = &timed;
  report(run_explicit(m, o));
  return cost_of(timed, steps);
}

Cost box_cost(long skip, long steps) {
  ModelMesh mesh = block();
  TetMesh box = structured_box(Vec3(0.1, 0.1, 0.02), 45, 45, 5);
  for (Vec3& x : box.nodes) x += Vec3(-0.05, -0.05, kTop + 1e-4);
  add_body(mesh, "box", {MaterialModel::neo_hookean, 1e9, 0.3, 25000.0}, box);  // 5 kg
  RigidBodyModel rigid = make_rigid(mesh, 1, RigidMotion::free);
  Model m = fixed_base(std::move(mesh));
  m.rigid_bodies.push_back(rigid);
  RigidSurfacePenaltyParams p;
  p.penalty = 1e4;
  p.damping = 1.0;
  RigidSurfacePenalty penalty(m.mesh, m.mesh.bodies[0].boundary, 1, p);
  Timed<RigidSurfacePenalty> timed(penalty, skip);
  RunOptions o = timed_run(skip, steps);
  o.contact = &timed;
  report(run_explicit(m, o));
  return cost_of(timed, steps);
}

}  // namespace

int main(int argc, char** argv) {
  long steps = 400, repeats = 5;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--steps")) steps = std::atol(argv[i + 1]);
    if (!std::strcmp(argv[i], "--repeats")) repeats = std::atol(argv[i + 1]);
  }
  const long skip = 200;  // the contact forms
  std::vector<double> ratios;
  for (long r = 0; r < repeats; ++r) {
    const Cost a = sphere_cost(skip, steps), b = box_cost(skip, steps);
    ratios.push_back(b.per_point_step / a.per_point_step);
    std::printf(
        "repeat=%ld sphere_ns_per_point_step=%.1f sphere_points=%.0f box_ns_per_point_step=%.1f "
        "box_points=%.0f ratio=%.2f\n",
        r + 1, 1e9 * a.per_point_step, a.points, 1e9 * b.per_point_step, b.points, ratios.back());
    for (const auto& [name, c] : {std::pair{"sphere", a}, std::pair{"box", b}})
      std::printf("  %s shares: begin_step %.2f add_forces %.2f step_bound %.2f end_step %.2f\n",
                  name, c.share[0], c.share[1], c.share[2], c.share[3]);
    std::fflush(stdout);
  }
  std::sort(ratios.begin(), ratios.end());
  const double lowest = ratios.empty() ? 0.0 : ratios[0];
  const double highest = ratios.empty() ? 0.0 : ratios[ratios.size() - 1];
  std::printf("median_ratio=%.2f lowest=%.2f highest=%.2f (floor: <= 2)\n", bench::median(ratios),
              lowest, highest);
  return 0;
}
