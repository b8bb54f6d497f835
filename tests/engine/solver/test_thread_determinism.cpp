// Threads change the speed of a run, never its result (docs/parallel.md, "Threads (OpenMP)"):
// positions, velocities, energies and step statistics are compared bit for bit between 1, 2 and
// 3 threads, on a two-body model without contact (both material models, gravity, a fixed face)
// and on a rigid-sphere impact (the contact phases stay on one thread). The models are large
// enough that the element loop is cut into several slabs and the node loops run in parallel.
#include <catch2/catch.hpp>
#include <cstring>
#include <functional>
#include <vector>

#include "engine/contact/rigid_sphere_penalty.hpp"
#include "engine/element/internal_force.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/observe/history.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "tests/support/models.hpp"

using namespace ccm;

namespace {

// Everything a run leaves behind that a thread count could change.
struct RunResult {
  std::vector<Vec3> x, v;
  std::vector<std::vector<double>> history;  // per sample: kinetic and internal energy per body
  RunSummary summary;
};

bool same_bits(const void* a, const void* b, size_t bytes) { return std::memcmp(a, b, bytes) == 0; }

void require_identical(const RunResult& a, const RunResult& b) {
  REQUIRE(a.x.size() == b.x.size());
  CHECK(same_bits(a.x.data(), b.x.data(), a.x.size() * sizeof(Vec3)));
  CHECK(same_bits(a.v.data(), b.v.data(), a.v.size() * sizeof(Vec3)));
  REQUIRE(a.history.size() == b.history.size());
  for (size_t k = 0; k < a.history.size(); ++k) {
    REQUIRE(a.history[k].size() == b.history[k].size());
    CHECK(same_bits(a.history[k].data(), b.history[k].data(), a.history[k].size() * 8));
  }
  CHECK(a.summary.steps == b.summary.steps);
  CHECK(same_bits(&a.summary.dt_min, &b.summary.dt_min, 8));
  CHECK(same_bits(&a.summary.dt_max, &b.summary.dt_max, 8));
  CHECK(same_bits(&a.summary.energy_balance_error, &b.summary.energy_balance_error, 8));
}

// Two bodies side by side: a Neo-Hookean block (12,288 tets, 2,601 nodes) held at x = 0 and a
// linear-elastic block, both twisting under gravity.
Model two_blocks() {
  ModelMesh mesh;
  add_body(mesh, "soft", test::neo_hookean(1e6, 0.45, 1000.0),
           structured_box(Vec3(0.32, 0.16, 0.08), 32, 16, 8));
  TetMesh stiff = structured_box(Vec3(0.08, 0.08, 0.08), 8, 8, 8);
  for (Vec3& p : stiff.nodes) p.x() += 0.36;
  add_body(mesh, "stiff", {MaterialModel::linear_elastic, 5e6, 0.3, 2000.0}, stiff);
  Model model = make_model(std::move(mesh));
  std::vector<int> held;
  for (int n = 0; n < model.mesh.bodies[0].n_nodes; ++n)
    if (model.mesh.X[static_cast<size_t>(n)].x() == 0.0) held.push_back(n);
  model.bcs.fix(held);
  model.bcs.gravity = Vec3(0.0, 0.0, -9.81);
  for (size_t i = 0; i < model.initial_velocity.size(); ++i) {
    const Vec3& X = model.mesh.X[i];
    model.initial_velocity[i] = Vec3(-X.y(), X.x() - 0.1, 0.5 * X.z());
  }
  return model;
}

RunResult run(const Model& model, int threads, ContactModel* contact, double end_time) {
  OutputRequest request;
  request.kinetic_energy = true;
  request.internal_energy = true;
  HistoryRecorder history(model.mesh, request);
  RunOptions opt;
  opt.time.end_time = end_time;
  opt.time.output_interval = end_time / 4;
  opt.history = &history;
  opt.contact = contact;
  opt.monitor.check_interval = 5;  // the energy sums run often
  opt.threads = threads;
  RunResult r;
  opt.on_sample = [&](const State& s) {
    r.x = s.x;
    r.v = s.v;
  };
  r.summary = run_explicit(model, opt);
  r.history = history.rows();
  return r;
}

}  // namespace

TEST_CASE("The element loop is cut into slabs whose phases share no node", "[threads]") {
  const Model model = two_blocks();
  const ElementSchedule& schedule = model.elements.schedule;
  REQUIRE(schedule.phases.size() == 2);
  CHECK(schedule.phases[0].size() >= 4);  // enough slabs that 3 threads all have work
  std::vector<int> owner(static_cast<size_t>(model.mesh.n_nodes()));
  int covered = 0;
  for (const std::vector<int>& phase : schedule.phases) {
    std::fill(owner.begin(), owner.end(), -1);
    for (int s : phase) {
      const Slab& slab = schedule.slabs[static_cast<size_t>(s)];
      const ElementBlock& b = model.elements.blocks[static_cast<size_t>(slab.block)];
      for (int i = slab.first_pack * kLanes;
           i < (slab.first_pack + slab.n_packs - 1) * kLanes + slab.last_lanes; ++i) {
        ++covered;
        for (int n :
             model.elements.tets[static_cast<size_t>(b.lane_element[static_cast<size_t>(i)])]) {
          int& o = owner[static_cast<size_t>(n)];
          CHECK((o < 0 || o == s));
          o = s;
        }
      }
    }
  }
  CHECK(covered == model.elements.n_elements());  // every element exactly once
}

TEST_CASE("Internal forces, stable step and energies are bitwise the same on 1, 2 and 3 threads",
          "[threads]") {
  const Model model = two_blocks();
  std::vector<Vec3> x = model.mesh.X;
  for (size_t i = 0; i < x.size(); ++i)
    x[i] += 1e-3 * Vec3(std::sin(40 * x[i].y()), x[i].x() * x[i].z() * 50, -x[i].x());
  auto evaluate = [&](int threads, std::vector<Vec3>& f, std::vector<double>& energy) {
    f.assign(x.size(), Vec3::Constant(0.125));  // the forces are added to what is there
    energy.assign(model.elements.blocks.size(), 0.0);
    return add_internal_forces(model.elements, x, f, energy, threads);
  };
  std::vector<Vec3> f1;
  std::vector<double> e1;
  const InternalForceResult r1 = evaluate(1, f1, e1);
  CHECK(e1[0] > 0.0);
  for (int threads : {2, 3}) {
    std::vector<Vec3> f;
    std::vector<double> e;
    const InternalForceResult r = evaluate(threads, f, e);
    INFO(threads << " threads");
    CHECK(same_bits(f.data(), f1.data(), f.size() * sizeof(Vec3)));
    CHECK(same_bits(e.data(), e1.data(), e.size() * sizeof(double)));
    CHECK(same_bits(&r.stable_dt, &r1.stable_dt, 8));
    CHECK(same_bits(&r.min_J, &r1.min_J, 8));
  }
}

TEST_CASE("A run is bitwise the same on 1, 2 and 3 threads", "[threads]") {
  const Model model = two_blocks();
  const RunResult one = run(model, 1, nullptr, 2e-3);
  REQUIRE(one.summary.verdict == Verdict::completed);
  REQUIRE(one.summary.steps > 20);
  for (int threads : {2, 3}) {
    INFO(threads << " threads");
    const RunResult r = run(model, threads, nullptr, 2e-3);
    CHECK(r.summary.threads == threads);
    require_identical(one, r);
  }
}

TEST_CASE("A contact run is bitwise the same on 1, 2 and 3 threads", "[threads]") {
  // A rigid sphere (R 10 mm, 2 g) strikes a free soft box 20 x 20 x 10 mm (12,288 tets) from a
  // 0.5 mm gap at 0.5 m/s: in contact from 1 ms.
  Model model =
      test::box_model(Vec3(0.02, 0.02, 0.01), 16, 16, 8, test::neo_hookean(1e5, 0.3, 1000.0));
  RigidSpherePenaltyParams p;
  p.sphere.radius = 0.01;
  p.sphere.mass = 2e-3;
  p.sphere.center = Vec3(0.009, 0.011, 0.01 + 0.01 + 5e-4);
  p.sphere.velocity = Vec3(0.05, -0.02, -0.5);
  p.penalty = 1e3;
  const auto& surface = model.mesh.surfaces.at("box/boundary").triangles;
  auto contact_run = [&](int threads) {
    RigidSpherePenalty contact(surface, p);
    RunResult r = run(model, threads, &contact, 2e-3);
    REQUIRE(contact.work() != 0.0);  // the sphere did touch
    return r;
  };
  const RunResult one = contact_run(1);
  REQUIRE(one.summary.verdict == Verdict::completed);
  for (int threads : {2, 3}) {
    INFO(threads << " threads");
    require_identical(one, contact_run(threads));
  }
}
