// Cost of DCR contact per step (broad + narrow phase + enforcement) against surface size, and its
// ratio to the structural cost per step, on a soft sphere pressed into a clamped plate refined
// two or three times (thesis 2.7.4: exponent 0.99, contact about 3x the structure).
//
//   ./build/bench_contact [--levels N] [--repeats R] [--end T] [--threads N]
//
// Method. Each run times, inside one process and in thread CPU time (CLOCK_THREAD_CPUTIME_ID, so
// that time spent descheduled on a shared machine counts for neither), the contact model's calls
// (begin_step, correct and step_bound: broad phase, CCD, projection, momentum exchange, step
// limit) and the whole steps (begin_step to begin_step); structure = steps - contact. The clock
// is read 6 times per step (about 0.1-0.5 us each, charged to the contact). The ratio contact /
// structure is formed within each run, so a load that slows both alike cancels; each level is
// repeated R times and the median ratio is reported with the range. The exponent is the
// least-squares slope of log(median contact ms/step) against log(surface triangles). The load
// average of the machine is printed before and after: on a shared machine the absolute times move
// with it, the ratios much less.
//
// --threads N runs the structure's loops and the contact's detection on N threads
// (docs/parallel.md, "Threads"); the clock is then the wall clock (CLOCK_MONOTONIC), since thread
// CPU time would miss the other threads' work, for any N, so that N = 1 and N = 2 compare. The
// process CPU time of the whole run is printed beside it.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "bench/bench_statistics.hpp"
#include "engine/bc/node_selection.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"

using namespace ccm;

namespace {

// The clock of the timings: CPU time of this thread (time the thread spends descheduled on a
// shared machine is not counted, for the contact and the structure alike), or with --threads the
// wall clock.
clockid_t g_clock = CLOCK_THREAD_CPUTIME_ID;

double seconds_on(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double thread_seconds() { return seconds_on(g_clock); }

// Forwards to a contact model, accumulating the thread CPU time spent in it (`contact`) and in
// whole steps (`loop`: from one begin_step to the next, and the last one to its end_step).
class TimedContact : public ContactModel {
 public:
  explicit TimedContact(ContactModel& inner)
      : ContactModel(inner.name(), inner.phases()), inner_(inner) {}
  void begin_step(const State& s, double dt) override {
    const double now = thread_seconds();
    if (step_start_ >= 0.0) loop += now - step_start_;
    step_start_ = now;
    inner_.begin_step(s, dt);
    contact += thread_seconds() - now;
  }
  void add_forces(State& s) override {
    timed([&] { inner_.add_forces(s); });
  }
  void correct(State& s, double dt) override {
    timed([&] { inner_.correct(s, dt); });
  }
  void end_step(const State& s, double dt) override {
    timed([&] { inner_.end_step(s, dt); });
    ledger_ = inner_.ledger();
    last_end_ = thread_seconds();
  }
  ContactStepBound step_bound(const State& s, double ceiling) const override {
    ContactStepBound bound;
    timed([&] { bound = inner_.step_bound(s, ceiling); });
    return bound;
  }
  double corrected_elements_stable_dt() const override {
    return inner_.corrected_elements_stable_dt();
  }
  // Closes the last step.
  void finish() {
    if (step_start_ >= 0.0) loop += last_end_ - step_start_;
    step_start_ = -1.0;
  }
  mutable double contact = 0.0;
  double loop = 0.0;

 private:
  template <typename F>
  void timed(F f) const {
    const double t0 = thread_seconds();
    f();
    contact += thread_seconds() - t0;
  }
  ContactModel& inner_;
  double step_start_ = -1.0, last_end_ = 0.0;
};

struct Result {
  int surface_triangles;
  int elements;
  long steps;
  double contact_ms, structure_ms;  // per step
  double cpu_s;                     // process CPU time of the run [s]
  long threaded_loops;              // detection loops that ran on more than one thread
  double ratio() const { return contact_ms / structure_ms; }
};

// A sphere (R 20 mm, 2 m/s) 0.1 mm above a plate 80 x 80 x 20 mm clamped at its base, both
// neo-Hookean E = 1 MPa, nu = 0.45; plate cell and sphere mesh size halve with each level.
Model sphere_on_plate(int level) {
  const double h = 0.01 / (1 << level);
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
  return model;
}

Result run(const Model& model, double end_time, int threads) {
  dcr::DcrSettings settings;
  settings.surfaces = {"plate/boundary", "ball/boundary"};
  settings.threads.threads = threads;
  dcr::DcrContact dcr(model.mesh, settings, model.bcs.fixed_nodes);
  TimedContact timed(dcr);
  RunOptions opt;
  opt.contact = &timed;
  opt.time.end_time = end_time;
  opt.threads = threads;
  const double cpu_start = seconds_on(CLOCK_PROCESS_CPUTIME_ID);
  const RunSummary s = run_explicit(model, opt);
  const double cpu = seconds_on(CLOCK_PROCESS_CPUTIME_ID) - cpu_start;
  if (s.verdict != Verdict::completed)
    std::fprintf(stderr, "warning: run ended %s: %s\n", std::string(to_string(s.verdict)).c_str(),
                 s.instability.reason.c_str());
  timed.finish();
  const double steps = static_cast<double>(s.steps);
  return {dcr.features().n_faces(),
          s.n_elements,
          s.steps,
          1e3 * timed.contact / steps,
          1e3 * (timed.loop - timed.contact) / steps,
          cpu,
          dcr.threaded_loops()};
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

// Least-squares slope of log(y) against log(x).
double fitted_exponent(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  const double k = static_cast<double>(x.size());
  return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

struct Options {
  int levels = 3;
  int repeats = 3;
  double end_time = 2e-3;  // the ball touches at 0.05 ms and is in contact to about 1.8 ms
  int threads = 0;         // 0: not given (thread CPU clock, one thread)
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--levels"))
      o.levels = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeats"))
      o.repeats = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--end"))
      o.end_time = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--threads"))
      o.threads = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr,
                   "usage: bench_contact [--levels N] [--repeats R] [--end T] [--threads N]\n");
      std::exit(2);
    }
  }
  if (o.levels < 2 || o.repeats < 1 || !(o.end_time > 0) || o.threads < 0) {
    std::fprintf(stderr,
                 "bench_contact: need --levels >= 2, --repeats >= 1, --end > 0, --threads >= 1\n");
    std::exit(2);
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  if (o.threads > 0) g_clock = CLOCK_MONOTONIC;
  const int threads = std::max(1, o.threads);
  std::printf(
      "DCR contact cost per step vs structure, sphere on plate, %d levels x %d repeats, "
      "end %g s\n"
      "contact = begin_step + correct + end_step + step_bound of the DCR model (broad phase with a "
      "Verlet candidate cache, CCD, projection, momentum exchange);\n"
      "structure = whole steps - contact; both in %s, in one process, %d thread(s). "
      "load average before: %s\n",
      o.levels, o.repeats, o.end_time, o.threads > 0 ? "wall time" : "thread CPU time", threads,
      load_average().c_str());
  std::printf("%6s %10s %8s %6s %8s %14s %17s %7s %8s %9s\n", "level", "triangles", "tets",
              "repeat", "steps", "contact ms/step", "structure ms/step", "ratio", "cpu s",
              "thr.loops");
  std::vector<double> triangles, contact_ms, ratios;
  double worst_ratio = 0.0;
  for (int level = 0; level < o.levels; ++level) {
    const Model model = sphere_on_plate(level);
    std::vector<double> contact, ratio;
    for (int r = 0; r < o.repeats; ++r) {
      const Result res = run(model, o.end_time, threads);
      std::printf("%6d %10d %8d %6d %8ld %14.4f %17.4f %7.3f %8.3f %9ld\n", level,
                  res.surface_triangles, res.elements, r, res.steps, res.contact_ms,
                  res.structure_ms, res.ratio(), res.cpu_s, res.threaded_loops);
      contact.push_back(res.contact_ms);
      ratio.push_back(res.ratio());
      if (r == 0) triangles.push_back(res.surface_triangles);
    }
    contact_ms.push_back(bench::median(contact));
    ratios.push_back(bench::median(ratio));
    worst_ratio = std::max(worst_ratio, *std::max_element(ratio.begin(), ratio.end()));
    std::printf("level %d: median contact %.4f ms/step, median ratio %.3f (range %.3f - %.3f)\n",
                level, contact_ms.back(), ratios.back(),
                *std::min_element(ratio.begin(), ratio.end()),
                *std::max_element(ratio.begin(), ratio.end()));
  }
  std::printf("fitted exponent of contact time vs surface size: %.2f (thesis 0.99, floor 1.1)\n",
              fitted_exponent(triangles, contact_ms));
  std::printf(
      "median contact/structure ratio on the finest level: %.3f (floor 1), worst run %.3f\n",
      ratios.back(), worst_ratio);
  std::printf("load average after: %s\n", load_average().c_str());
  return 0;
}
