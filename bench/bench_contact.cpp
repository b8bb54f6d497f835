// Cost of DCR contact per step (broad + narrow phase + enforcement) against surface size, on a
// soft sphere pressed into a clamped plate, refined three times; and its ratio to the
// structural cost per step.  ./build/bench_contact
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/bc/node_selection.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"

using namespace ccm;
using Clock = std::chrono::steady_clock;

namespace {

// Forwards to a contact model and accumulates the wall time spent in it.
class TimedContact : public ContactModel {
 public:
  explicit TimedContact(ContactModel& inner) : inner_(inner) {}
  std::string_view name() const override { return inner_.name(); }
  void begin_step(const State& s, double dt) override {
    timed([&] { inner_.begin_step(s, dt); });
  }
  void correct(State& s, double dt) override {
    timed([&] { inner_.correct(s, dt); });
  }
  double stable_dt_limit(const State& s) const override { return inner_.stable_dt_limit(s); }
  double work() const override { return inner_.work(); }
  double seconds = 0.0;

 private:
  template <typename F>
  void timed(F f) {
    const auto t0 = Clock::now();
    f();
    seconds += std::chrono::duration<double>(Clock::now() - t0).count();
  }
  ContactModel& inner_;
};

struct Result {
  int surface_triangles;
  int elements;
  long steps;
  double contact_ms, structure_ms;
};

Result run(int level) {
  const double h = 0.01 / (1 << level);  // plate cell and sphere mesh size
  const int n = 8 << level;
  ModelMesh mesh;
  add_body(mesh, "plate", {MaterialModel::neo_hookean, 1e6, 0.45, 1000.0},
           structured_box(Vec3(0.08, 0.08, 0.02), n, n, std::max(2, n / 4)));
  PrimitiveSpec ball{PrimitiveKind::sphere};
  ball.radius = 0.02;
  ball.mesh_size = 1.5 * h;
  add_body(mesh, "ball", {MaterialModel::neo_hookean, 1e6, 0.45, 1000.0},
           mesh_primitive(ball, Placement{Vec3(0.04, 0.04, 0.02 + 0.02 + 1e-4)}));
  Model model = make_model(std::move(mesh));
  model.bcs.fix(nodes_on_plane(model.mesh, 0, Vec3::Zero(), Vec3::UnitZ(), 1e-9));
  const Body& b = model.mesh.bodies[1];
  for (int i = b.first_node; i < b.first_node + b.n_nodes; ++i)
    model.initial_velocity[static_cast<size_t>(i)] = Vec3(0, 0, -2.0);
  dcr::DcrContact dcr(model.mesh, {{"plate/boundary", "ball/boundary"}}, model.bcs.fixed_nodes);
  TimedContact timed(dcr);
  RunOptions opt;
  opt.contact = &timed;
  opt.time.end_time = 2e-3;  // the ball is in contact for most of it
  const RunSummary s = run_explicit(model, opt);
  const double steps = static_cast<double>(s.steps);
  const double loop_s = s.ns_per_element_step * 1e-9 * steps * s.n_elements;
  return {dcr.features().n_faces(), s.n_elements, s.steps, 1e3 * timed.seconds / steps,
          1e3 * (loop_s - timed.seconds) / steps};
}

}  // namespace

int main() {
  std::printf("%10s %10s %7s %14s %16s %8s\n", "triangles", "tets", "steps", "contact ms/step",
              "structure ms/step", "ratio");
  std::vector<Result> results;
  for (int level = 0; level < 3; ++level) {
    const Result r = run(level);
    results.push_back(r);
    std::printf("%10d %10d %7ld %14.3f %16.3f %8.2f\n", r.surface_triangles, r.elements, r.steps,
                r.contact_ms, r.structure_ms, r.contact_ms / r.structure_ms);
  }
  // Least-squares slope of log(contact time) against log(surface size).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Result& r : results) {
    const double x = std::log(r.surface_triangles), y = std::log(r.contact_ms);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double k = static_cast<double>(results.size());
  std::printf("fitted exponent of contact time vs surface size: %.2f\n",
              (k * sxy - sx * sy) / (k * sxx - sx * sx));
  return 0;
}
