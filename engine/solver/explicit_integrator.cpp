#include "engine/solver/explicit_integrator.hpp"

#include <fmt/format.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "engine/body/rigid_bodies.hpp"
#include "engine/monitor/fixed_order_sum.hpp"
#include "engine/solver/lumped_mass.hpp"
#include "engine/threads/index_loop.hpp"
#include "engine/threads/thread_count.hpp"

namespace ccm {

std::string_view to_string(Verdict v) { return v == Verdict::completed ? "completed" : "unstable"; }

std::string_view to_string(RunEnd e) { return e == RunEnd::end_time ? "end_time" : "separated"; }

std::string_view to_string(StepLimiter l) {
  switch (l) {
    case StepLimiter::structure:
      return "structure";
    case StepLimiter::contact:
      return "contact";
    case StepLimiter::max_dt:
      return "max_dt";
    case StepLimiter::landing:
      return "landing";
  }
  return "?";
}

long& StepLimiterCounts::operator[](StepLimiter l) {
  switch (l) {
    case StepLimiter::structure:
      return structure;
    case StepLimiter::contact:
      return contact;
    case StepLimiter::max_dt:
      return max_dt;
    case StepLimiter::landing:
      return landing;
  }
  return landing;
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU time [s] of the calling thread (one thread) or of the process (more): the cost of the step
// loop, unaffected by other processes sharing the machine (wall time is not).
double cpu_seconds(int threads) {
  timespec ts{};
  clock_gettime(threads > 1 ? CLOCK_PROCESS_CPUTIME_ID : CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Node loops shorter than this stay on one thread (a parallel region costs microseconds).
constexpr int kMinParallelNodes = 2048;
// A model of fewer elements runs on one thread whatever was asked: its step lasts tens of
// microseconds, of the order of the cost of the step's parallel regions and barriers.
constexpr int kMinParallelElements = 8192;

int threads_for(const Model& model, const RunOptions& options) {
  const int requested = options.threads > 0 ? options.threads : default_threads();
  return model.mesh.n_elements() >= kMinParallelElements ? requested : 1;
}

struct StepChoice {
  double dt;
  StepLimiter limiter;
};

// Work of the prescribed surface loads, by the trapezoidal rule over each step, on the nodes the
// domain owns (a partitioned run's rigid-body replicas carry the load too, counted by rank 0).
class LoadWork {
 public:
  explicit LoadWork(const BoundaryConditions& bcs) : bcs_(bcs) {}
  void before_step(const State& s) {
    x_n_.clear();
    for (const SurfaceLoad& l : bcs_.loads)
      for (int n : l.nodes) x_n_.push_back(s.x[static_cast<size_t>(n)]);
  }
  void after_step(const State& s, double t_n, double t_np1, int owned_nodes) {
    size_t k = 0;
    for (const SurfaceLoad& l : bcs_.loads) {
      const Vec3 F_mid = 0.5 * (l.magnitude(t_n) + l.magnitude(t_np1)) * l.direction;
      for (size_t i = 0; i < l.nodes.size(); ++i, ++k)
        if (l.nodes[i] < owned_nodes)
          work_ += l.area_share[i] * F_mid.dot(s.x[static_cast<size_t>(l.nodes[i])] - x_n_[k]);
    }
  }
  double work() const { return work_; }

 private:
  const BoundaryConditions& bcs_;
  std::vector<Vec3> x_n_;
  double work_ = 0.0;
};

class CentralDifference {
 public:
  CentralDifference(const Model& model, const RunOptions& options)
      : model_(model),
        opt_(options),
        threads_(threads_for(model, options)),
        load_work_(model.bcs),
        rigid_(model.mesh, model.rigid_bodies),
        body_energy_(model.mesh.bodies.size(), 0.0) {}

  RunSummary run();

 private:
  void initialise();
  StepChoice next_dt() const;
  void count_step(const StepChoice& step, double t_n);
  void predict(double dt);
  void evaluate(bool with_energy);
  void correct_contact(double dt);
  void apply_fixed_nodes();
  void correct(double dt);
  double gravity_work() const;
  double energy_floor() const;
  double total_internal_energy() const;
  bool output_due() const;
  void sample();
  void track_separation();
  bool separated_long_enough() const;
  std::optional<Instability> check(bool energy_check);
  void report_progress(double dt, Clock::time_point start, double& last_report);
  void couple_evaluation(bool with_energy);

  int owned_nodes() const { return opt_.coupling ? opt_.coupling->owned_nodes() : s_.n_nodes(); }

  bool parallel_nodes() const { return threads_ > 1 && s_.n_nodes() >= kMinParallelNodes; }

  const Model& model_;
  const RunOptions& opt_;
  const int threads_;
  State s_;
  LoadWork load_work_;
  RigidBodies rigid_;              // their nodes follow their poses (engine/body/rigid_bodies.hpp)
  std::vector<HeldImpulse> held_;  // scratch: the contact's impulses on held bodies
  EnergyBalance energy_;
  std::vector<double> body_energy_;
  // x and the internal forces in the element kernel's padded form (padded_nodes.hpp): the
  // predictor writes x_padded_ as it moves x; every other change of x is copied in by evaluate.
  PaddedNodes x_padded_, f_internal_;
  bool x_padded_current_ = false;
  InternalForceResult last_eval_;
  long next_output_index_ = 1;
  double last_dt_ = 0.0;
  long steps_since_energy_check_ = 0;
  double open_since_ = -1.0;  // when the contact opened after touching; -1 while it touches
  bool elements_valid_everywhere_ = true;  // partitioned runs: no subdomain has a bad element
  RunSummary summary_;
};

void CentralDifference::initialise() {
  const ModelMesh& mesh = model_.mesh;
  s_.X = mesh.X;
  s_.x = mesh.X;
  s_.v = model_.initial_velocity;
  s_.a.assign(mesh.X.size(), Vec3::Zero());
  s_.f.assign(mesh.X.size(), Vec3::Zero());
  x_padded_.assign(mesh.X.size(), PaddedVec3{});
  f_internal_.assign(mesh.X.size(), PaddedVec3{});
  s_.m_lumped = lumped_mass(mesh, model_.elements);
  s_.inv_m.resize(s_.m_lumped.size());
  if (opt_.coupling) opt_.coupling->assemble(s_.m_lumped, 1);
  // A rigid body's nodes carry no mass of their own (0: its motion is the body's).
  for (size_t i = 0; i < s_.m_lumped.size(); ++i)
    s_.inv_m[i] = s_.m_lumped[i] > 0.0 ? 1.0 / s_.m_lumped[i] : 0.0;
  for (int n : model_.bcs.fixed_nodes) s_.v[static_cast<size_t>(n)].setZero();
  rigid_.initialise(s_);
  s_.t = 0.0;
  evaluate(true);
  apply_fixed_nodes();
  for (KinematicConstraint* c : opt_.constraints) c->initialise(s_);
  summary_.dt_initial = opt_.time.dt_safety * last_eval_.stable_dt;
  // A model of rigid bodies alone has no stable step: its first step is max_dt (or, with none,
  // one step to the end, for which the leapfrog measure takes no correction).
  last_dt_ = std::min(summary_.dt_initial, opt_.time.max_dt);
  if (!std::isfinite(last_dt_)) last_dt_ = 0.0;
  double kinetic = leapfrog_kinetic_energy(s_, last_dt_, threads_, owned_nodes());
  if (opt_.coupling) opt_.coupling->sum_over_domains(std::span<double>(&kinetic, 1));
  energy_.start(kinetic + rigid_.kinetic_energy(), total_internal_energy(), energy_floor());
  summary_.n_nodes = mesh.n_nodes();
  summary_.threads = threads_;
  // The elements the step evaluates: a rigid body's are not (ns per element-step counts these).
  summary_.n_elements = 0;
  for (const Body& b : mesh.bodies)
    if (!b.rigid) summary_.n_elements += b.n_elements;
}

// The one safety factor s = dt_safety applies here, to the structure's stable step and to the
// stiffness a contact model adds, combined in squares; a contact's kinematic bound caps the
// step as it is (eq. CT.1, engine/contact/contact_model.hpp; docs/contact-time-step.md).
StepChoice CentralDifference::next_dt() const {
  const double s = opt_.time.dt_safety;
  StepChoice step{s * last_eval_.stable_dt, StepLimiter::structure};
  if (opt_.contact) {
    const ContactStepBound bound =
        opt_.contact->step_bound(s_, std::min(step.dt, opt_.time.max_dt));
    if (std::isfinite(bound.stiffness_dt)) {
      const double dt_s = last_eval_.stable_dt;
      const double combined =
          s / std::sqrt(1.0 / (dt_s * dt_s) + 1.0 / (bound.stiffness_dt * bound.stiffness_dt));
      if (combined < step.dt) step = {combined, StepLimiter::contact};
    }
    if (bound.kinematic_dt < step.dt) step = {bound.kinematic_dt, StepLimiter::contact};
  }
  if (opt_.time.max_dt < step.dt) step = {opt_.time.max_dt, StepLimiter::max_dt};
  double stop = opt_.time.end_time;
  if (opt_.time.output_interval > 0.0)
    stop = std::min(stop, static_cast<double>(next_output_index_) * opt_.time.output_interval);
  // Land exactly on the next output time or the end, rather than step a hair short of it. The
  // steps to an output time are made equal (remaining / n, as many as full steps and a short one
  // would take, each within the bound): a short step once per output interval is a periodic
  // change of the step, and at the stability limit's 0.9 it drove a parametric instability of
  // the leapfrog (a stiff spinning bar, 500 steps per interval: energy error 5.8 % and unstable
  // at 0.11 s; 4.3e-7 with equal steps, docs/time-step.md "Landing on output times"). The
  // leapfrog energy measure is also consistent only between steps of one length (with an output
  // interval of 1.33 steps, the coarse Hertz test's energy balance read 0.8 % at -O3 and 5 % at
  // -O1 with a full and a short step, 3e-5 with equal ones). The end time is met by one short
  // step (no period). A step that lands counts as `landing`; an equal share keeps the bound that
  // set it.
  const double remaining = stop - s_.t;
  if (s_.t + step.dt * (1.0 + 1e-9) >= stop) return {remaining, StepLimiter::landing};
  const double n = std::ceil(remaining / step.dt * (1.0 - 1e-9));
  if (stop < opt_.time.end_time) step.dt = remaining / n;
  return step;
}

void CentralDifference::count_step(const StepChoice& step, double t_n) {
  if (summary_.steps == 0) summary_.dt_first = step.dt;
  ++summary_.steps;
  ++summary_.limiters[step.limiter];
  summary_.dt_min = std::min(summary_.dt_min, step.dt);
  summary_.dt_max = std::max(summary_.dt_max, step.dt);
  if (step.limiter != StepLimiter::contact) return;
  summary_.dt_contact_min = std::min(summary_.dt_contact_min, step.dt);
  if (summary_.first_contact_step_time < 0.0) summary_.first_contact_step_time = t_n;
}

// x_{n+1} = x_n + dt v_n + dt^2/2 a_n ;  v* = v_n + dt/2 a_n   (eq. 2.27-2.28)
void CentralDifference::predict(double dt) {
  const double half_dt = 0.5 * dt;
  const auto n = s_.x.size();
  // The arrays' addresses in locals (here and in the loops below): otherwise a store through one
  // may, as far as the compiler can tell, change another's address, and it reloads them per node.
  Vec3* x = s_.x.data();
  Vec3* v = s_.v.data();
  const Vec3* a = s_.a.data();
  PaddedVec3* xp = x_padded_.data();
  for_each_index(n, threads_, parallel_nodes(), [=](size_t i) {
    v[i] += half_dt * a[i];
    x[i] += dt * v[i];
    xp[i] = padded(x[i]);
  });
  x_padded_current_ = true;
  if (rigid_.empty()) return;
  rigid_.predict(s_, dt, s_.t);
  for (const RigidBodyModel& r : model_.rigid_bodies) {
    const Body& body = model_.mesh.bodies[static_cast<size_t>(r.body)];
    for (int node = body.first_node; node < body.first_node + body.n_nodes; ++node)
      x_padded_[static_cast<size_t>(node)] = padded(s_.x[static_cast<size_t>(node)]);
  }
}

// a_{n+1} = M^-1 (f_ext + f_int) + g   (eq. 2.29). The internal forces are summed apart, in
// f_internal_, and added to the external ones (loads, then contact) in the acceleration.
void CentralDifference::evaluate(bool with_energy) {
  const auto n = s_.f.size();
  const bool copy_x = !x_padded_current_;
  Vec3* f = s_.f.data();
  PaddedVec3* fi = f_internal_.data();
  PaddedVec3* xp = x_padded_.data();
  const Vec3* x = s_.x.data();
  for_each_index(n, threads_, parallel_nodes(), [=](size_t i) {
    f[i].setZero();
    fi[i] = PaddedVec3{};
    if (copy_x) xp[i] = padded(x[i]);
  });
  x_padded_current_ = false;
  for (const SurfaceLoad& load : model_.bcs.loads) load.add_to(s_.f, s_.t);
  for (StateLoad* load : opt_.loads) load->add_forces(s_, s_.f);
  // A block without elements (a subdomain may hold none of a body's) is not written.
  if (with_energy) std::fill(body_energy_.begin(), body_energy_.end(), 0.0);
  last_eval_ = add_internal_forces(
      model_.elements, x_padded_, f_internal_,
      with_energy ? std::span<double>(body_energy_) : std::span<double>(), threads_);
  if (opt_.coupling) couple_evaluation(with_energy);
  if (opt_.contact) opt_.contact->add_forces(s_);
  const Vec3 g = model_.bcs.gravity;
  Vec3* a = s_.a.data();
  const double* inv_m = s_.inv_m.data();
  const Vec3* f_ext = s_.f.data();
  const PaddedVec3* f_int = f_internal_.data();
  for_each_index(n, threads_, parallel_nodes(),
                 [=](size_t i) { a[i] = inv_m[i] * (f_ext[i] + unpadded(f_int[i])) + g; });
  rigid_.gather(s_, g);
}

// A partitioned run: the shared nodes' forces completed (neighbour halos), and the stable step,
// the element check and the stored energy made global, so every subdomain decides alike.
void CentralDifference::couple_evaluation(bool with_energy) {
  // One halo exchange: the internal forces join the external ones first.
  for (size_t i = 0; i < s_.f.size(); ++i) {
    s_.f[i] += unpadded(f_internal_[i]);
    f_internal_[i] = PaddedVec3{};
  }
  opt_.coupling->assemble(std::span<double>(s_.f.data()->data(), 3 * s_.f.size()), 3);
  double local[2] = {last_eval_.stable_dt, last_eval_.first_bad_element < 0 ? 1.0 : 0.0};
  opt_.coupling->min_over_domains(local);
  last_eval_.stable_dt = local[0];
  elements_valid_everywhere_ = local[1] > 0.0;
  if (with_energy) opt_.coupling->sum_over_domains(body_energy_);
}

// Step 3; a rigid body takes the impulses the contact gave the nodes it held (rigid_bodies.hpp).
void CentralDifference::correct_contact(double dt) {
  opt_.contact->correct(s_, dt);
  // The next step starts from the corrected positions: where the correction squeezed elements,
  // their stable step is shorter than the one measured before it (docs/time-step.md).
  last_eval_.stable_dt =
      std::min(last_eval_.stable_dt, opt_.contact->corrected_elements_stable_dt());
  if (rigid_.empty()) return;
  held_.assign(model_.mesh.bodies.size(), HeldImpulse{});
  opt_.contact->add_held_impulses(held_);
  rigid_.take_impulses(held_);
}

void CentralDifference::apply_fixed_nodes() {
  for (int n : model_.bcs.fixed_nodes) {
    const auto i = static_cast<size_t>(n);
    s_.x[i] = s_.X[i];
    s_.v[i].setZero();
    s_.a[i].setZero();
  }
}

// v_{n+1} = v* + dt/2 a_{n+1}   (eq. 2.31)
void CentralDifference::correct(double dt) {
  const double half_dt = 0.5 * dt;
  const auto n = s_.v.size();
  Vec3* v = s_.v.data();
  const Vec3* a = s_.a.data();
  for_each_index(n, threads_, parallel_nodes(), [=](size_t i) { v[i] += half_dt * a[i]; });
  rigid_.finish(s_, dt);
}

// Work of gravity = sum m g . u (exact: gravity is a constant field). A partitioned run's rigid
// bodies are stepped alike on every rank: their part is added once, after the sum over domains.
double CentralDifference::gravity_work() const {
  if (!model_.bcs.has_gravity()) return 0.0;
  return fixed_order_sum(owned_nodes(), threads_,
                         [&](int n) {
                           const auto i = static_cast<size_t>(n);
                           return s_.m_lumped[i] * model_.bcs.gravity.dot(s_.x[i] - s_.X[i]);
                         }) +
         (opt_.coupling ? 0.0 : rigid_.gravity_work(model_.bcs.gravity));
}

// 1e-12 of the energy the model would carry with every node moving at the fastest wave speed:
// far below any physical energy of a run, far above the round-off of a body at rest.
double CentralDifference::energy_floor() const {
  double c_max = 0.0, mass = 0.0;
  for (const ElementBlock& b : model_.elements.blocks) c_max = std::max(c_max, b.wave_speed);
  for (int i = 0; i < owned_nodes(); ++i) mass += s_.m_lumped[static_cast<size_t>(i)];
  if (opt_.coupling) {
    double bounds[2] = {-c_max, 0.0};
    opt_.coupling->min_over_domains(bounds);
    opt_.coupling->sum_over_domains(std::span<double>(&mass, 1));
    c_max = -bounds[0];
  }
  for (int k = 0; k < rigid_.size(); ++k) mass += rigid_.body(k).mass();  // on every rank alike
  return 1e-12 * mass * c_max * c_max;
}

double CentralDifference::total_internal_energy() const {
  double e = 0.0;
  for (double b : body_energy_) e += b;
  return e;
}

bool CentralDifference::output_due() const {
  if (opt_.time.output_interval <= 0.0) return false;
  const double t_out = static_cast<double>(next_output_index_) * opt_.time.output_interval;
  return s_.t >= t_out * (1.0 - 1e-12);
}

// The contact's state after a step: touching, or open since when (TimeControl::
// end_after_separation).
void CentralDifference::track_separation() {
  if (!opt_.contact) return;
  if (opt_.contact->ledger().touching) {
    summary_.touched = true;
    open_since_ = -1.0;
  } else if (summary_.touched && open_since_ < 0.0) {
    open_since_ = s_.t;  // the first step that ends open
  }
}

bool CentralDifference::separated_long_enough() const {
  const double hold = opt_.time.end_after_separation;
  return hold >= 0.0 && summary_.touched && open_since_ >= 0.0 &&
         s_.t - open_since_ >= hold * (1.0 - 1e-12) &&
         s_.t >= opt_.time.earliest_end * (1.0 - 1e-12);
}

void CentralDifference::sample() {
  rigid_.place_interior(s_);  // a sample reads every node
  if (opt_.coupling) return opt_.coupling->sample(s_, body_energy_);
  if (opt_.history) opt_.history->sample(s_, body_energy_);
  if (opt_.on_sample) opt_.on_sample(s_);
}

std::optional<Instability> CentralDifference::check(bool energy_check) {
  if (auto bad = check_elements(last_eval_, s_.t)) return bad;
  if (!elements_valid_everywhere_)
    return Instability{s_.t, "an element failed in another subdomain", -1, -1};
  if (!rigid_.failure().empty()) return Instability{s_.t, rigid_.failure(), -1, -1};
  if (opt_.contact) {
    const std::string& reason = opt_.contact->ledger().failure;
    if (!reason.empty())
      return Instability{s_.t, fmt::format("contact ({}): {}", opt_.contact->name(), reason), -1,
                         -1};
  }
  if (!energy_check) return std::nullopt;
  std::optional<Instability> not_finite = check_finite(s_);
  // The contact model of a partitioned run is replicated: its work is global already.
  const bool replicated_contact = opt_.contact && opt_.coupling;
  double w_ext = load_work_.work() + gravity_work() +
                 (opt_.contact && !replicated_contact ? opt_.contact->ledger().work : 0.0);
  // A partitioned run's constraints are replicated (every rank holds the same work): added once,
  // after the sums over domains.
  if (!opt_.coupling)
    for (const KinematicConstraint* c : opt_.constraints) w_ext += c->work();
  for (const StateLoad* load : opt_.loads) w_ext += load->work();
  double kinetic = leapfrog_kinetic_energy(s_, last_dt_, threads_, owned_nodes());
  if (opt_.coupling) {
    double sums[3] = {kinetic, w_ext, not_finite ? 1.0 : 0.0};
    opt_.coupling->sum_over_domains(sums);
    kinetic = sums[0];
    w_ext = sums[1];
    if (!not_finite && sums[2] > 0.0)
      not_finite = Instability{s_.t, "non-finite state in another subdomain", -1, -1};
  }
  if (not_finite) return not_finite;
  if (replicated_contact) w_ext += opt_.contact->ledger().work;
  if (opt_.coupling) {
    w_ext += rigid_.gravity_work(model_.bcs.gravity);  // see gravity_work()
    for (const KinematicConstraint* c : opt_.constraints) w_ext += c->work();
  }
  kinetic += rigid_.kinetic_energy();
  w_ext += rigid_.contact_work() + rigid_.joint_work();
  const double err = energy_.update(kinetic, total_internal_energy(), w_ext);
  summary_.energy_balance_error = energy_.max_relative_error();
  if (auto bad = check_energy(err, opt_.monitor.energy_tolerance, s_.t)) return bad;
  if (!opt_.contact) return std::nullopt;
  return check_contact_energy(opt_.contact->name(), opt_.contact->ledger().injected_energy,
                              energy_.scale(), opt_.monitor.energy_tolerance, s_.t);
}

void CentralDifference::report_progress(double dt, Clock::time_point start, double& last_report) {
  if (!opt_.progress) return;
  const double wall = seconds_since(start);
  if (wall - last_report < opt_.progress_seconds) return;
  last_report = wall;
  opt_.progress({s_.t, opt_.time.end_time, summary_.steps, dt, wall});
}

RunSummary CentralDifference::run() {
  const auto start = Clock::now();
  initialise();
  const auto loop_start = Clock::now();
  const double loop_cpu_start = cpu_seconds(threads_);
  if (auto bad = check(true)) {
    summary_.verdict = Verdict::unstable;
    summary_.instability = *bad;
  }
  sample();
  double last_report = 0.0;
  const double t_end = opt_.time.end_time;
  while (summary_.verdict == Verdict::completed && s_.t < t_end * (1.0 - 1e-12)) {
    if (opt_.time.max_steps > 0 && summary_.steps >= opt_.time.max_steps) {
      summary_.verdict = Verdict::unstable;
      summary_.instability = {s_.t, "step limit reached before the end time", -1, -1};
      break;
    }
    const StepChoice step = next_dt();
    const double dt = step.dt;
    const bool output_step = (s_.t + dt >= t_end * (1.0 - 1e-12));
    const double t_n = s_.t;
    if (auto bad = check_time_step(opt_.time.dt_safety * last_eval_.stable_dt, summary_.dt_initial,
                                   opt_.monitor.dt_collapse_ratio, s_.t)) {
      summary_.verdict = Verdict::unstable;
      summary_.instability = *bad;
      break;
    }
    load_work_.before_step(s_);
    if (opt_.contact) opt_.contact->begin_step(s_, dt);
    predict(dt);  // 1
    s_.t = t_n + dt;
    const bool sample_now = output_step || output_due();
    // The leapfrog energy measure is consistent only where dt did not jump, so the balance is
    // checked on regular steps, never on the steps shortened to land on an output time; a run whose
    // step changes every step (a contact limit, say) is still checked once 4 intervals have passed,
    // accepting the O(dt change) measurement error.
    const bool regular_step = std::abs(dt - last_dt_) <= 0.01 * last_dt_;
    const long interval = opt_.monitor.check_interval;
    const bool energy_check = (regular_step && steps_since_energy_check_ + 1 >= interval) ||
                              steps_since_energy_check_ + 1 >= 4 * interval;
    steps_since_energy_check_ = energy_check ? 0 : steps_since_energy_check_ + 1;
    evaluate(energy_check || sample_now);   // 2
    if (opt_.contact) correct_contact(dt);  // 3
    apply_fixed_nodes();                    // 4
    for (KinematicConstraint* c : opt_.constraints) c->apply(s_, dt);
    correct(dt);  // 5
    if (opt_.contact) opt_.contact->end_step(s_, dt);
    for (StateLoad* load : opt_.loads) load->end_step(s_, dt);
    last_dt_ = dt;
    load_work_.after_step(s_, t_n, s_.t, owned_nodes());
    count_step(step, t_n);
    track_separation();
    if (auto bad = check(energy_check)) {
      summary_.verdict = Verdict::unstable;
      summary_.instability = *bad;
      break;
    }
    if (sample_now) {
      sample();
      if (output_due()) ++next_output_index_;
      if (separated_long_enough()) {
        summary_.ended_by = RunEnd::separated;
        summary_.contact_opened_at = open_since_;
        break;
      }
    }
    report_progress(dt, start, last_report);
  }
  summary_.step_cpu_seconds = cpu_seconds(threads_) - loop_cpu_start;
  summary_.step_wall_seconds = seconds_since(loop_start);
  summary_.end_time = s_.t;
  summary_.wall_seconds = seconds_since(start);
  if (summary_.steps > 0)
    summary_.dt_mean = summary_.end_time / static_cast<double>(summary_.steps);
  if (summary_.steps > 0 && summary_.n_elements > 0)
    summary_.ns_per_element_step = 1e9 * summary_.step_wall_seconds /
                                   (static_cast<double>(summary_.steps) * summary_.n_elements);
  return summary_;
}

}  // namespace

RunSummary run_explicit(const Model& model, const RunOptions& options) {
  return CentralDifference(model, options).run();
}

}  // namespace ccm
