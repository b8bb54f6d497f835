// Cost per element-step of the explicit engine on a structured box of 201,600 tets
// (40 x 40 x 21 cells x 6) without contact, on 1 and 2 threads (or the counts given): the
// internal-force kernel alone, and the whole step (internal forces, stable-time-step estimate,
// predict and correct updates, monitor checks and energy sums). Each figure is repeated; the
// minimum, the median and the largest of the wall time are printed, the minimum CPU time per thread
// (which a loaded machine inflates less), and the parallel efficiency t_1 / (N t_N) of the whole
// step; then, for the kernel, each thread's time running its slabs and waiting at the barriers
// (min / median / max over the repetitions). The final positions and velocities of every thread
// count are compared bit for bit.
// --element nodal_pressure runs the averaged-nodal-pressure tet (docs/elements.md) instead of
// the plain tet4, for the cost ratio of the two.
//
//   ./build/bench_element_step [--cells NX NY NZ] [--steps N] [--repeat R] [--threads 1,2]
//                              [--element tet4|nodal_pressure]
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "engine/element/internal_force.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"

using namespace ccm;

namespace {

struct Options {
  int nx = 40, ny = 40, nz = 21;
  int steps = 200;
  int repeat = 5;
  std::vector<int> threads{1, 2};
  ElementKind element = kDefaultElementKind;
};

std::vector<int> parse_list(const char* text) {
  std::vector<int> out;
  for (const char* p = text; *p;) {
    char* end = nullptr;
    const long v = std::strtol(p, &end, 10);
    if (end == p || v < 1) return {};
    out.push_back(static_cast<int>(v));
    p = *end == ',' ? end + 1 : end;
  }
  return out;
}

[[noreturn]] void usage(const char* argv0) {
  std::fprintf(stderr,
               "usage: %s [--cells NX NY NZ] [--steps N] [--repeat R] [--threads N1,N2,...] "
               "[--element tet4|nodal_pressure]\n",
               argv0);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--cells") && i + 3 < argc) {
      o.nx = std::atoi(argv[++i]);
      o.ny = std::atoi(argv[++i]);
      o.nz = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--steps") && i + 1 < argc) {
      o.steps = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      o.repeat = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
      o.threads = parse_list(argv[++i]);
    } else if (!std::strcmp(argv[i], "--element") && i + 1 < argc) {
      if (!parse_element_kind(argv[++i], o.element)) usage(argv[0]);
    } else {
      usage(argv[0]);
    }
  }
  if (o.nx < 1 || o.ny < 1 || o.nz < 1 || o.steps < 1 || o.repeat < 1 || o.threads.empty())
    usage(argv[0]);
  return o;
}

Model make_bench_model(const Options& o) {
  ModelMesh mesh;
  const double h = 0.01;
  add_body(mesh, "block", {MaterialModel::neo_hookean, 1.0e6, 0.45, 1000.0},
           structured_box(Vec3(o.nx * h, o.ny * h, o.nz * h), o.nx, o.ny, o.nz));
  mesh.bodies.back().element = o.element;
  Model model = make_model(std::move(mesh));
  // A twisting initial velocity so every element deforms.
  for (size_t i = 0; i < model.initial_velocity.size(); ++i) {
    const Vec3& X = model.mesh.X[i];
    model.initial_velocity[i] = Vec3(-X.y(), X.x(), 0.1 * X.z());
  }
  return model;
}

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct KernelTime {
  double wall_ns, cpu_ns;  // per element-step; CPU time divided by the thread count
  // Per thread, per element-step: running its slabs, and waiting at the phases' barriers
  // (SlabClock, internal_force.hpp).
  std::vector<double> busy_ns, wait_ns;
};

KernelTime time_kernel(const Model& model, int repeats, int threads) {
  // The integrator's form of the nodes (padded_nodes.hpp).
  PaddedNodes f(model.mesh.X.size()), x(model.mesh.X.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const Vec3& X = model.mesh.X[i];
    x[i] = padded(X + 1e-3 * Vec3(X.y(), X.z(), X.x()));
  }
  double sink = 0.0;
  SlabClock clock;
  const double c0 = process_cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r)
    sink += add_internal_forces(model.elements, x, f, {}, threads, clock).stable_dt;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = process_cpu_seconds() - c0;
  if (sink < 0) std::puts("");
  const double element_steps = repeats * static_cast<double>(model.elements.n_elements());
  KernelTime k{1e9 * s / element_steps, 1e9 * cpu / (threads * element_steps), {}, {}};
  for (const SlabClock::PerThread& p : clock.threads) {
    k.busy_ns.push_back(1e9 * p.busy / element_steps);
    k.wait_ns.push_back(1e9 * p.wait / element_steps);
  }
  return k;
}

struct StepRun {
  RunSummary summary;
  std::vector<Vec3> x, v;
};

StepRun time_steps(const Model& model, int steps, int threads) {
  RunOptions run;
  const double dt = 0.5 * reference_stable_dt(model.elements, model.mesh.X);
  run.time.max_dt = dt;
  run.time.end_time = steps * dt;
  run.time.output_interval = 0.0;
  run.threads = threads;
  StepRun out;
  run.on_sample = [&](const State& s) {
    out.x = s.x;
    out.v = s.v;
  };
  out.summary = run_explicit(model, run);
  return out;
}

struct Stats {
  double min, median, max;
};

Stats stats(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return {v.front(), n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.back()};
}

// One line per thread of a thread count's kernel runs: its busy and wait time's distribution.
std::string per_thread_text(int threads, const std::vector<std::vector<double>>& busy,
                            const std::vector<std::vector<double>>& wait) {
  std::string out;
  for (size_t i = 0; i < busy.size(); ++i) {
    if (busy[i].empty()) continue;
    const Stats b = stats(busy[i]), w = stats(wait[i]);
    char line[160];
    std::snprintf(
        line, sizeof line,
        "  %d threads, thread %zu: busy %6.2f / %6.2f / %-6.2f wait %5.2f / %5.2f / %.2f\n",
        threads, i, b.min, b.median, b.max, w.min, w.median, w.max);
    out += line;
  }
  return out;
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const Model model = make_bench_model(o);
  const int n_el = model.elements.n_elements();
  std::printf(
      "mesh: %d %s tets, %d nodes (structured box %d x %d x %d cells), %zu slabs in %zu "
      "phases, %d lanes per pack\n",
      n_el, std::string(to_string(o.element)).c_str(), model.mesh.n_nodes(), o.nx, o.ny, o.nz,
      model.elements.schedule.slabs.size(), model.elements.schedule.phases.size(), kLanes);
  std::printf(
      "%d steps per whole-step run, %d repetitions; ns per element-step, min / median / max\n",
      o.steps, o.repeat);
  std::printf("%-8s %-26s %-26s %-12s %-12s %s\n", "threads", "kernel (f_int, dt)", "whole step",
              "kernel CPU", "step CPU", "efficiency (whole step: min, median)");
  bool identical = true;
  std::vector<std::string> per_thread;
  StepRun first;
  double step_one_thread = 0.0, step_one_thread_median = 0.0;
  for (int t : o.threads) {
    time_kernel(model, 3, t);  // warm up
    std::vector<double> kernel, kernel_cpu, step, cpu;
    std::vector<std::vector<double>> busy(static_cast<size_t>(t)), wait(static_cast<size_t>(t));
    for (int r = 0; r < o.repeat; ++r) {
      const KernelTime k = time_kernel(model, o.steps, t);
      kernel.push_back(k.wall_ns);
      kernel_cpu.push_back(k.cpu_ns);
      for (size_t i = 0; i < busy.size() && i < k.busy_ns.size(); ++i) {
        busy[i].push_back(k.busy_ns[i]);
        wait[i].push_back(k.wait_ns[i]);
      }
      StepRun run = time_steps(model, o.steps, t);
      if (run.summary.verdict != Verdict::completed) {
        std::fprintf(stderr, "run ended %s\n", std::string(to_string(run.summary.verdict)).c_str());
        return 1;
      }
      step.push_back(run.summary.ns_per_element_step);
      cpu.push_back(1e9 * run.summary.step_cpu_seconds /
                    (static_cast<double>(run.summary.steps) * n_el * t));
      if (first.x.empty())
        first = std::move(run);
      else
        identical = identical && same_bits(first.x, run.x) && same_bits(first.v, run.v);
    }
    const Stats k = stats(kernel), kc = stats(kernel_cpu), s = stats(step), c = stats(cpu);
    if (t == o.threads.front()) {
      step_one_thread = s.min * t;
      step_one_thread_median = s.median * t;
    }
    std::printf(
        "%-8d %6.2f / %6.2f / %-8.2f %6.2f / %6.2f / %-8.2f %-12.2f %-12.2f %.0f %%, %.0f %%\n", t,
        k.min, k.median, k.max, s.min, s.median, s.max, kc.min, c.min,
        100.0 * step_one_thread / (t * s.min), 100.0 * step_one_thread_median / (t * s.median));
    per_thread.push_back(per_thread_text(t, busy, wait));
  }
  std::printf(
      "kernel per thread, ns per element-step (min / median / max): busy running its slabs, "
      "waiting at the phases' barriers\n");
  for (const std::string& line : per_thread) std::fputs(line.c_str(), stdout);
  std::printf("positions and velocities bitwise identical across thread counts: %s\n",
              identical ? "yes" : "NO");
  return identical ? 0 : 1;
}
