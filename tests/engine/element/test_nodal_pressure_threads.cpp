// The nodal-pressure element keeps results bitwise the same for any thread count (docs/parallel.md
// "Threads"): its nodal volumes are summed in the force loop's slab/phase order, its pressures
// in a node loop, its volumetric energy in node order. A partitioned (MPI) run refuses it.
#include <catch2/catch.hpp>
#include <cstring>
#include <vector>

#include "engine/distributed/distributed_run.hpp"
#include "engine/element/internal_force.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/observe/history.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "tests/support/models.hpp"

using namespace ccm;

namespace {

bool bits_equal(const void* a, const void* b, size_t bytes) {
  return std::memcmp(a, b, bytes) == 0;
}

// A nearly incompressible nodal-pressure block (12,288 tets: several slabs, parallel node loops)
// held at x = 0 beside a plain linear-elastic block, both twisting under gravity.
Model mixed_blocks() {
  ModelMesh mesh;
  add_body(mesh, "soft", test::neo_hookean(1e6, 0.499, 1000.0),
           structured_box(Vec3(0.16, 0.16, 0.08), 16, 16, 8));
  mesh.bodies.back().element = ElementKind::nodal_pressure;
  TetMesh stiff = structured_box(Vec3(0.08, 0.08, 0.08), 8, 8, 8);
  for (Vec3& p : stiff.nodes) p.x() += 0.2;
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

struct Outcome {
  std::vector<Vec3> x, v;
  std::vector<std::vector<double>> history;
  RunSummary summary;
};

Outcome run_with(const Model& model, int threads) {
  HistoryRecorder history(model.mesh, {true, true, false, {}});
  RunOptions opt;
  opt.time.end_time = 5e-4;
  opt.time.output_interval = opt.time.end_time / 4;
  opt.history = &history;
  opt.monitor.check_interval = 5;
  opt.threads = threads;
  Outcome o;
  opt.on_sample = [&](const State& s) {
    o.x = s.x;
    o.v = s.v;
  };
  o.summary = run_explicit(model, opt);
  o.history = history.rows();
  return o;
}

}  // namespace

TEST_CASE("Nodal-pressure forces, step and energies are bitwise the same on 1, 2 and 3 threads",
          "[nodal_pressure][threads]") {
  const Model model = mixed_blocks();
  REQUIRE(model.elements.schedule.phases.size() == 2);
  std::vector<Vec3> x = model.mesh.X;
  for (size_t i = 0; i < x.size(); ++i)
    x[i] += 1e-3 * Vec3(std::sin(40 * x[i].y()), x[i].x() * x[i].z() * 50, -x[i].x());
  auto evaluate = [&](int threads, std::vector<Vec3>& f, std::vector<double>& energy) {
    f.assign(x.size(), Vec3::Constant(0.125));
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
    CHECK(bits_equal(f.data(), f1.data(), f.size() * sizeof(Vec3)));
    CHECK(bits_equal(e.data(), e1.data(), e.size() * sizeof(double)));
    CHECK(bits_equal(&r.stable_dt, &r1.stable_dt, 8));
    CHECK(bits_equal(&r.min_J, &r1.min_J, 8));
  }
}

TEST_CASE("A nodal-pressure run is bitwise the same on 1, 2 and 3 threads",
          "[nodal_pressure][threads]") {
  const Model model = mixed_blocks();
  const Outcome one = run_with(model, 1);
  REQUIRE(one.summary.verdict == Verdict::completed);
  REQUIRE(one.summary.steps > 20);
  for (int threads : {2, 3}) {
    INFO(threads << " threads");
    const Outcome o = run_with(model, threads);
    CHECK(o.summary.threads == threads);
    REQUIRE(o.x.size() == one.x.size());
    CHECK(bits_equal(o.x.data(), one.x.data(), o.x.size() * sizeof(Vec3)));
    CHECK(bits_equal(o.v.data(), one.v.data(), o.v.size() * sizeof(Vec3)));
    REQUIRE(o.history.size() == one.history.size());
    for (size_t k = 0; k < o.history.size(); ++k)
      CHECK(bits_equal(o.history[k].data(), one.history[k].data(), o.history[k].size() * 8));
    CHECK(o.summary.steps == one.summary.steps);
    CHECK(bits_equal(&o.summary.energy_balance_error, &one.summary.energy_balance_error, 8));
  }
}

TEST_CASE("A partitioned run refuses a nodal-pressure body before it starts",
          "[nodal_pressure][threads]") {
  ModelMesh mesh;
  add_body(mesh, "pad", test::neo_hookean(1e6, 0.499, 1000.0),
           structured_box(Vec3(0.02, 0.02, 0.01), 2, 2, 1));
  mesh.bodies.back().element = ElementKind::nodal_pressure;
  const Model model = make_model(std::move(mesh));
  RunOptions opt;
  opt.time.end_time = 1e-4;
  CHECK_THROWS_WITH(
      distributed::run_partitioned(model, opt),
      Catch::Contains("does not support element = \"nodal_pressure\" yet (body 'pad')"));
}
