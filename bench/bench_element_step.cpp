// Single-thread cost per element-step of the explicit engine on a structured box of
// 201,600 tets (40 x 40 x 21 cells x 6): the internal-force kernel alone, and the whole step
// (internal forces, stable-time-step estimate, predict and correct updates, monitor checks).
//
//   ./build/bench_element_step [--cells NX NY NZ] [--steps N]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "engine/element/internal_force.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"

using namespace ccm;

namespace {

struct Options {
  int nx = 40, ny = 40, nz = 21;
  int steps = 200;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--cells") && i + 3 < argc) {
      o.nx = std::atoi(argv[++i]);
      o.ny = std::atoi(argv[++i]);
      o.nz = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--steps") && i + 1 < argc) {
      o.steps = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--cells NX NY NZ] [--steps N]\n", argv[0]);
      std::exit(2);
    }
  }
  return o;
}

Model make_bench_model(const Options& o) {
  ModelMesh mesh;
  const double h = 0.01;
  add_body(mesh, "block", {MaterialModel::neo_hookean, 1.0e6, 0.45, 1000.0},
           structured_box(Vec3(o.nx * h, o.ny * h, o.nz * h), o.nx, o.ny, o.nz));
  Model model = make_model(std::move(mesh));
  // A twisting initial velocity so every element deforms.
  for (size_t i = 0; i < model.initial_velocity.size(); ++i) {
    const Vec3& X = model.mesh.X[i];
    model.initial_velocity[i] = Vec3(-X.y(), X.x(), 0.1 * X.z());
  }
  return model;
}

double time_kernel(const Model& model, int repeats) {
  std::vector<Vec3> f(model.mesh.X.size(), Vec3::Zero());
  std::vector<Vec3> x = model.mesh.X;
  for (size_t i = 0; i < x.size(); ++i) x[i] += 1e-3 * Vec3(x[i].y(), x[i].z(), x[i].x());
  double sink = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) sink += add_internal_forces(model.elements, x, f).stable_dt;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (sink < 0) std::puts("");
  return 1e9 * s / (repeats * static_cast<double>(model.elements.n_elements()));
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const Model model = make_bench_model(o);
  const int n_el = model.elements.n_elements();
  std::printf("mesh: %d tets, %d nodes (structured box %d x %d x %d cells)\n", n_el,
              model.mesh.n_nodes(), o.nx, o.ny, o.nz);

  time_kernel(model, 5);  // warm up
  const double kernel_ns = time_kernel(model, o.steps);

  RunOptions run;
  const double dt = 0.5 * reference_stable_dt(model.elements, model.mesh.X);
  run.time.max_dt = dt;
  run.time.end_time = o.steps * dt;
  run.time.output_interval = 0.0;
  const RunSummary s = run_explicit(model, run);

  std::printf("internal-force kernel (F, P, f_int, stable dt): %.1f ns per element-step\n",
              kernel_ns);
  std::printf("whole explicit step (%ld steps, verdict %s):      %.1f ns per element-step\n",
              s.steps, std::string(to_string(s.verdict)).c_str(), s.ns_per_element_step);
  return s.verdict == Verdict::completed ? 0 : 1;
}
