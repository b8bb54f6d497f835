// The evaluation timed per thread (SlabClock, engine/element/internal_force.hpp; what
// bench_element_step prints): the same forces, bit for bit, as without the clock; every thread
// that ran is busy; and each thread's busy and wait time add up to no more than the evaluations'
// wall time (the nodal passes and the region's start and end are in neither).
#include <catch2/catch.hpp>
#include <chrono>
#include <cstring>
#include <vector>

#include "engine/element/internal_force.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"

using namespace ccm;

namespace {

Model twisted_block() {
  ModelMesh mesh;
  add_body(mesh, "block", {MaterialModel::neo_hookean, 1e6, 0.45, 1000.0},
           structured_box(Vec3(0.16, 0.16, 0.16), 16, 16, 16));  // 24,576 tets: 4 slabs or more
  return make_model(std::move(mesh));
}

PaddedNodes deformed(const Model& model) {
  PaddedNodes x(model.mesh.X.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const Vec3& X = model.mesh.X[i];
    x[i] = padded(X + 1e-2 * Vec3(X.y(), X.z(), X.x()));
  }
  return x;
}

}  // namespace

TEST_CASE("slab clock: the same forces, each thread busy, busy + wait within the wall time",
          "[threads]") {
  const Model model = twisted_block();
  REQUIRE(model.elements.schedule.slabs.size() >= 4);
  const PaddedNodes x = deformed(model);
  const int calls = 20;
  for (const int threads : {1, 2}) {
    PaddedNodes plain(x.size()), timed(x.size());
    const InternalForceResult a = add_internal_forces(model.elements, x, plain, {}, threads);
    SlabClock clock;
    const auto t0 = std::chrono::steady_clock::now();
    InternalForceResult b;
    for (int c = 0; c < calls; ++c) {
      std::fill(timed.begin(), timed.end(), PaddedVec3{});
      b = add_internal_forces(model.elements, x, timed, {}, threads, clock);
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CHECK(std::memcmp(plain.data(), timed.data(), plain.size() * sizeof(PaddedVec3)) == 0);
    CHECK(a.stable_dt == b.stable_dt);
    REQUIRE(clock.threads.size() == static_cast<size_t>(threads));
    for (const SlabClock::PerThread& t : clock.threads) {
      CHECK(t.busy > 0.0);
      CHECK(t.wait >= 0.0);
      CHECK(t.busy + t.wait <= wall);
    }
    if (threads == 1)
      CHECK(clock.threads[0].wait < 0.1 * clock.threads[0].busy);  // no one to wait for
  }
}
