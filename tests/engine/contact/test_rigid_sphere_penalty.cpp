// The rigid-sphere penalty model (thesis 2.8; engine/contact/rigid_sphere_penalty.hpp):
// forces against the derivative of the penalty energy, momentum and energy through an impact on
// a free body, the 1-DOF closed form (docs/contact-method.md §6(d)), the stable step limit binding
// and its margin, no contact at a distance, and the [contact] table of the scene file.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "engine/contact/rigid_sphere_penalty.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "tests/support/models.hpp"
#include "tests/support/scene_fixtures.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;
using Catch::Contains;

namespace {

const std::vector<Triangle>& boundary(const Model& m, const std::string& body = "box") {
  return m.mesh.surfaces.at(body + "/boundary").triangles;
}

// A free soft box 20 x 20 x 10 mm (4 g) and a sphere of half its mass (R 10 mm) coming down
// obliquely onto the middle of its top face from a 0.5 mm gap: it bounces back. The box drifts
// at 1 mm/s: a body exactly at rest has only round-off energy (1e-33 J), against which the
// engine's relative energy balance reads noise (see the report on the monitor).
Model free_box() {
  Model m = test::box_model(Vec3(0.02, 0.02, 0.01), 4, 4, 2, test::neo_hookean(1e5, 0.3, 1000.0));
  for (Vec3& v : m.initial_velocity) v = Vec3(0.0, 1e-3, 0.0);
  return m;
}

RigidSpherePenaltyParams oblique_impact(double penalty) {
  RigidSpherePenaltyParams p;
  p.sphere.radius = 0.01;
  p.sphere.mass = 2e-3;
  p.sphere.center = Vec3(0.009, 0.011, 0.01 + 0.01 + 5e-4);
  p.sphere.velocity = Vec3(0.05, -0.02, -0.5);
  p.penalty = penalty;
  return p;
}

// One big tet, every node fixed, whose top face z = 0 holds the quadrature point
// q0 = (1/6, 1/6, 0) (2/3 at node 0). A sphere of R = 10 mm moving along the vertical through
// q0 touches q0 and no other point (the others are >= 1/6 m away): exactly one spring K_P,
// along z, between the sphere and an immovable wall. Heavy (rho 1e5) so that the nodes' own
// penalty frequency K_P s_a / m_a (7 rad^2/s^2) is negligible next to K_P / m_s (1e5).
Model fixed_tet() {
  ModelMesh mesh;
  TetMesh g;
  g.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, -1)};
  g.tets = {{0, 2, 1, 3}};
  add_body(mesh, "tet", test::neo_hookean(1e6, 0.3, 1e5), g);
  Model model = make_model(std::move(mesh));
  model.bcs.fix({0, 1, 2, 3});
  return model;
}

constexpr double kTetR = 0.01, kTetMass = 0.1, kTetPenalty = 1e4;  // omega = 316.2 rad/s

RigidSpherePenaltyParams on_q0(double z0, double vz) {
  RigidSpherePenaltyParams p;
  p.sphere = {kTetR, kTetMass, Vec3(1.0 / 6.0, 1.0 / 6.0, z0), Vec3(0.0, 0.0, vz)};
  p.penalty = kTetPenalty;
  return p;
}

// A state at the reference configuration, as the engine sets it up.
State reference_state(const Model& model) {
  State s;
  s.X = model.mesh.X;
  s.x = model.mesh.X;
  s.v.assign(s.x.size(), Vec3::Zero());
  s.a.assign(s.x.size(), Vec3::Zero());
  s.f.assign(s.x.size(), Vec3::Zero());
  s.m_lumped.assign(s.x.size(), 1.0);
  s.inv_m.assign(s.x.size(), 1.0);
  return s;
}

// What the tests record at every output sample.
struct Sample {
  double t;
  Vec3 x_s, v_s, F_s, p_total, L_total;
  double ke_s, penalty_energy, penetration, work, sphere_work;
};

struct Recorder {
  const RigidSpherePenalty& contact;
  std::vector<Sample> samples;
  void operator()(const State& s) {
    const double m_s = contact.params().sphere.mass;
    Sample r{s.t,
             contact.sphere_position(),
             contact.sphere_velocity(),
             contact.contact_force(),
             test::linear_momentum(s) + m_s * contact.sphere_velocity(),
             test::angular_momentum(s) +
                 m_s * contact.sphere_position().cross(contact.sphere_velocity()),
             contact.sphere_kinetic_energy(),
             contact.penalty_energy(),
             contact.penetration_max(),
             contact.work(),
             contact.sphere_work()};
    samples.push_back(r);
  }
};

// The model with its stiffness bound scaled (to run beyond it on purpose), recording every
// step: its dt, the longest step its bound allows under eq. CT.1 with the default safety 0.9
// (min(0.9 stiffness bound, kinematic bound), the structure left out), and the sphere's height
// at its start.
class Probe : public RigidSpherePenalty {
 public:
  Probe(std::vector<Triangle> surface, RigidSpherePenaltyParams p, double scale = 1.0)
      : RigidSpherePenalty(std::move(surface), std::move(p)), scale_(scale) {}
  ContactStepBound step_bound(const State& s, double ceiling) const override {
    ContactStepBound b = RigidSpherePenalty::step_bound(s, ceiling);
    b.stiffness_dt *= scale_;
    limit_ = std::min(kDefaultDtSafety * b.stiffness_dt, b.kinematic_dt);
    return b;
  }
  void begin_step(const State& s, double dt) override {
    steps.push_back({dt, limit_, sphere_position().z()});
    RigidSpherePenalty::begin_step(s, dt);
  }
  struct Step {
    double dt, limit, z_s;
  };
  std::vector<Step> steps;

 private:
  double scale_;
  mutable double limit_ = 0.0;
};

}  // namespace

TEST_CASE("rigid sphere penalty: the forces are minus the gradient of the penalty energy",
          "[contact][rigid_penalty]") {
  // A sphere sunk 2 mm into the top face of a slightly distorted box: several points active.
  const Model model = free_box();
  State s = reference_state(model);
  for (size_t i = 0; i < s.x.size(); ++i) {
    const Vec3& X = s.X[i];
    s.x[i] = X + 1e-4 * Vec3(std::sin(300 * X.y()), std::cos(200 * X.x()), std::sin(500 * X.x()));
  }
  RigidSpherePenaltyParams p = oblique_impact(1e3);
  p.sphere.center = Vec3(0.0093, 0.0104, 0.01 + 0.01 - 2e-3);
  RigidSpherePenalty contact(boundary(model), p);
  contact.add_forces(s);
  REQUIRE(contact.active_points() >= 6);
  const double E0 = contact.penalty_energy();
  CHECK(E0 > 0.0);
  // Force on the sphere: equal and opposite to the total force on the nodes.
  Vec3 f_sum = Vec3::Zero();
  for (const Vec3& f : s.f) f_sum += f;
  CHECK(test::relative_error(f_sum, Vec3(-contact.contact_force())) < 1e-14);

  // Central differences of E_pen, h = 1e-8 m (delta ~ 1e-3 m): truncation ~ (h/delta)^2 = 1e-10
  // and round-off ~ 1e-16 E / h against f ~ E / delta, 1e-16 delta / h = 1e-11, relative.
  // Measured: 8e-11.
  const double h = 1e-8;
  const auto energy = [&](State& st) {
    std::fill(st.f.begin(), st.f.end(), Vec3::Zero());
    RigidSpherePenalty c(boundary(model), p);
    c.add_forces(st);
    return c.penalty_energy();
  };
  double worst = 0.0, f_max = 0.0;
  for (int n : contact.surface_nodes()) {
    const auto i = static_cast<size_t>(n);
    if (s.f[i].norm() == 0.0) continue;
    f_max = std::max(f_max, s.f[i].norm());
    Vec3 grad;
    for (int c = 0; c < 3; ++c) {
      State st = s;
      st.x[i][c] += h;
      const double Ep = energy(st);
      st.x[i][c] -= 2 * h;
      const double Em = energy(st);
      grad[c] = (Ep - Em) / (2 * h);
    }
    worst = std::max(worst, (s.f[i] + grad).norm());
  }
  INFO("largest |f + dE/dx| = " << worst << " N of f_max " << f_max << " N");
  CHECK(worst < 1e-8 * f_max);
}

TEST_CASE("rigid sphere penalty: momentum of sphere + free body conserved through an impact",
          "[contact][rigid_penalty]") {
  const Model model = free_box();
  RigidSpherePenalty contact(boundary(model), oblique_impact(1e3));
  Recorder rec{contact, {}};
  RunOptions opt;
  opt.time.end_time = 8e-3;  // contact lasts from 1 to 5.5 ms
  opt.time.output_interval = 1e-4;
  opt.contact = &contact;
  opt.on_sample = std::ref(rec);
  const RunSummary r = run_explicit(model, opt);
  REQUIRE(r.verdict == Verdict::completed);
  const auto& S = rec.samples;
  double F_max = 0.0, p_err = 0.0, L_err = 0.0;
  for (const Sample& x : S) {
    F_max = std::max(F_max, x.F_s.norm());
    p_err = std::max(p_err, test::relative_error(x.p_total, S.front().p_total));
    L_err = std::max(L_err, test::relative_error(x.L_total, S.front().L_total));
  }
  INFO("steps " << r.steps << ", F_max " << F_max << " N, sphere v_z " << S.back().v_s.z());
  CHECK(F_max > 0.0);
  CHECK(S.back().F_s.norm() == 0.0);  // the sphere has left
  CHECK(S.back().v_s.z() > 0.0);      // and bounced back
  // Every contact force has an equal and opposite one, and the body's internal forces sum to
  // zero: central difference conserves p exactly. 1e-12 bounds the round-off of a few hundred
  // steps. The penalty force is central (along x_q - x_s, and sum_a N_a x_a x f_q = x_q x f_q),
  // so angular momentum is conserved as well (its reference: the origin).
  INFO("momentum error " << p_err << ", angular momentum error " << L_err);
  CHECK(p_err < 1e-12);
  CHECK(L_err < 1e-12);
}

TEST_CASE("rigid sphere penalty: energy of sphere + free body conserved through an impact",
          "[contact][rigid_penalty]") {
  // At the step the model allows (about 5e-5 s in contact, the penalty limit binding), and at
  // 1e-5 s. Tolerances: the synchronous kinetic energy of central difference is off by
  // O((omega dt / 2)^2) of the energy in a mode of frequency omega, and the springs switch on
  // and off between steps (an O(dt) error per switch, of the spring energy at the switch).
  // The stiffest mode, the penalty mode of a surface node (omega <= 1.7e4 rad/s by the bound),
  // has omega dt <= 0.87 at the limit and 0.17 at 1e-5 s; most of the energy is in far slower
  // modes (the sphere on its springs: omega ~ 1e3 rad/s). Measured: 5.6e-4 and 1.2e-5.
  struct Case {
    double max_dt, output_interval, tolerance;
  };
  for (const Case c :
       {Case{std::numeric_limits<double>::infinity(), 2.5e-4, 5e-3}, Case{1e-5, 5e-5, 1e-4}}) {
    const Model model = free_box();
    RigidSpherePenalty contact(boundary(model), oblique_impact(1e3));
    Recorder rec{contact, {}};
    HistoryRecorder history(model.mesh, {true, true, false, {}});
    RunOptions opt;
    opt.time.end_time = 8e-3;
    opt.time.output_interval = c.output_interval;  // longer than the step: few clipped steps
    opt.time.max_dt = c.max_dt;
    opt.contact = &contact;
    opt.history = &history;
    opt.on_sample = std::ref(rec);
    const RunSummary r = run_explicit(model, opt);
    REQUIRE(r.verdict == Verdict::completed);
    const auto& rows = history.rows();
    REQUIRE(rows.size() == rec.samples.size());
    const auto total = [&](size_t i) {
      const Sample& x = rec.samples[i];
      return x.ke_s + rows[i][1] + rows[i][2] + x.penalty_energy;
    };
    const double E0 = total(0);
    double worst = 0.0, pen_max = 0.0, transfer = 0.0;
    for (size_t i = 0; i < rows.size(); ++i) {
      worst = std::max(worst, std::abs(total(i) - E0) / E0);
      pen_max = std::max(pen_max, rec.samples[i].penalty_energy / E0);
      transfer = std::max(transfer, (rows[i][1] + rows[i][2]) / E0);
    }
    const Sample& end = rec.samples.back();
    INFO("dt " << r.dt_min << " .. " << r.dt_max << ", steps " << r.steps);
    INFO("max |E - E0| / E0 = " << worst << "; penalty energy up to " << pen_max
                                << " E0; body energy up to " << transfer << " E0");
    INFO("engine energy-balance error " << r.energy_balance_error << "; W_body + W_sphere = "
                                        << (end.work + end.sphere_work) / E0 << " E0");
    CHECK(pen_max > 0.05);  // the springs really took energy
    CHECK(transfer > 0.5);  // and handed most of it to the body
    CHECK(worst < c.tolerance);
    // The contact work closes the engine's own balance of the body (KE + IE - W_contact), and
    // once the sphere has left, the work on the body and on the sphere cancel: the penalty
    // energy went back (the trapezoidal rule is exact for a linear spring; O(dt^2) here).
    CHECK(r.energy_balance_error < c.tolerance);
    CHECK(end.penalty_energy == 0.0);
    CHECK(std::abs(end.work + end.sphere_work) < c.tolerance * E0);
  }
}

TEST_CASE("rigid sphere penalty: one spring against a wall follows the closed form",
          "[contact][rigid_penalty]") {
  // docs/contact-method.md §6(d): contact time pi sqrt(m / K_P), F_max = v0 sqrt(K_P m),
  // delta_max = v0 sqrt(m / K_P), rebound speed = impact speed up to the central difference
  // error at omega dt (§5: +-1.1 % at omega dt = 0.3).
  const double v0 = 0.5;
  const double omega = std::sqrt(kTetPenalty / kTetMass);
  const double t_c = std::numbers::pi / omega;
  const double F_max = v0 * std::sqrt(kTetPenalty * kTetMass), delta_max = v0 / omega;
  struct Case {
    double omega_dt, tol_speed, tol_time, tol_peak;
  };
  // Tolerances: the errors of central difference are O((omega dt)^2). At omega dt = 0.3: 1.1 %
  // on the rebound (the worst case quoted in §5; it depends on where contact starts between two
  // steps) and on the contact time; the peaks, sampled once per step, are also off by the phase
  // of the samples, up to 1 - cos(omega dt / 2) = 1.1 %: 1.2 %. At omega dt = 0.05 the same
  // scaled by (0.05 / 0.3)^2 = 1/36: 3e-4, and 4e-4 for the peaks.
  // Measured: rebound 1.0027 and 0.99987, contact time 0.9960 and 0.99990, peaks 0.9952 and
  // 0.99995.
  for (const Case c : {Case{0.3, 0.011, 0.011, 0.012}, Case{0.05, 3e-4, 3e-4, 4e-4}}) {
    const Model model = fixed_tet();
    RigidSpherePenalty contact(boundary(model, "tet"), on_q0(kTetR + 2e-3, -v0));
    Recorder rec{contact, {}};
    RunOptions opt;
    const double dt = c.omega_dt / omega;
    opt.time.max_dt = dt;
    opt.time.output_interval = dt;  // a sample every step
    opt.time.end_time = 2e-3 / v0 + t_c + 2e-3 / v0;
    opt.contact = &contact;
    opt.on_sample = std::ref(rec);
    const RunSummary r = run_explicit(model, opt);
    REQUIRE(r.verdict == Verdict::completed);
    CHECK(r.dt_max <= dt * (1 + 1e-9));
    const auto& S = rec.samples;
    // In free flight the sphere moves on straight lines; contact is where they meet z = R.
    size_t first = 0, last = 0;
    double F_peak = 0.0, pen_peak = 0.0;
    for (size_t i = 0; i < S.size(); ++i) {
      // Exactly one spring along z: no sideways force ever.
      CHECK(S[i].F_s.head<2>().norm() == 0.0);
      if (S[i].F_s.z() == 0.0) continue;
      if (first == 0) first = i;
      last = i;
      F_peak = std::max(F_peak, S[i].F_s.z());
      pen_peak = std::max(pen_peak, S[i].penetration);
    }
    REQUIRE(first > 0);
    REQUIRE(last + 1 < S.size());
    const Sample& in = S[first - 1];
    const Sample& out = S[last + 1];
    CHECK(in.v_s.z() == -v0);
    const double t_in = in.t + (in.x_s.z() - kTetR) / v0;
    const double v1 = out.v_s.z();
    const double t_out = out.t - (out.x_s.z() - kTetR) / v1;
    INFO("omega dt " << c.omega_dt << ": rebound " << v1 / v0 << " v0, contact time "
                     << (t_out - t_in) / t_c << " t_c, F_max " << F_peak / F_max << ", delta_max "
                     << pen_peak / delta_max);
    CHECK(std::abs(v1 / v0 - 1.0) < c.tol_speed);
    CHECK(std::abs((t_out - t_in) / t_c - 1.0) < c.tol_time);
    CHECK(std::abs(F_peak / F_max - 1.0) < c.tol_peak);
    CHECK(std::abs(pen_peak / delta_max - 1.0) < c.tol_peak);
    // The wall does not move: no work on the body, and the sphere's work returns to ~0.
    CHECK(S.back().work == 0.0);
    CHECK(std::abs(S.back().sphere_work) < 2 * c.tol_speed * 0.5 * kTetMass * v0 * v0);
  }
}

// The Kelvin-Voigt contact that never pulls (m d'' + c d' + K d = 0 while K d + c d' > 0),
// entered at speed v0: d = v0 / omega_d e^(-zeta omega t) sin(omega_d t) ends where the force
// vanishes, at omega_d t* = pi - atan2(2 zeta s, 1 - 2 zeta^2), s = sqrt(1 - zeta^2), and
// there |d'| / v0 = exp(-zeta omega t*) exactly (the bracket's magnitude is omega_d there).
// zeta = 1 (the limit): t* = 2 / omega, e = exp(-2).
double kelvin_voigt_restitution(double zeta) {
  if (zeta == 1.0) return std::exp(-2.0);
  const double s = std::sqrt(1.0 - zeta * zeta);
  const double theta = std::numbers::pi - std::atan2(2.0 * zeta * s, 1.0 - 2.0 * zeta * zeta);
  return std::exp(-zeta * theta / s);
}

TEST_CASE("rigid sphere penalty: a damped spring against a wall follows the closed form",
          "[contact][rigid_penalty]") {
  // The single spring of the test above with a dashpot of zeta: rebound speed
  // kelvin_voigt_restitution(zeta) v0 (0.5717 at 0.2, 0.1353 at 1), the energy taken
  // 1/2 m v0^2 (1 - e^2) booked as the dashpot's work. omega uses the reduced mass
  // mu = m_q m_s / (m_q + m_s), m_q = rho V / 4 / 3 (one tet: every node on 3 faces), 7e-5 below
  // m_s. Tolerance 1 % of v0: the dashpot reads the mid-step velocity, half a step behind the
  // spring, an O(omega dt) error: at omega dt = 0.02 about zeta x 1 % of the rebound.
  // Measured: see the INFO line.
  const double v0 = 0.5;
  const double m_q = 1e5 / 24.0 / 3.0;
  const double mu = m_q * kTetMass / (m_q + kTetMass);
  const double omega = std::sqrt(kTetPenalty / mu);
  for (const double zeta : {0.2, 1.0}) {
    const Model model = fixed_tet();
    RigidSpherePenaltyParams p = on_q0(kTetR + 2e-3, -v0);
    p.damping = zeta;
    RigidSpherePenalty contact(boundary(model, "tet"), p);
    Recorder rec{contact, {}};
    RunOptions opt;
    const double dt = 0.02 / omega;
    opt.time.max_dt = dt;
    opt.time.output_interval = 50 * dt;
    opt.time.end_time = 2 * 2e-3 / v0 + 2 * std::numbers::pi / omega;
    opt.contact = &contact;
    opt.on_sample = std::ref(rec);
    const RunSummary r = run_explicit(model, opt);
    REQUIRE(r.verdict == Verdict::completed);
    const Sample& out = rec.samples.back();
    REQUIRE(out.F_s.z() == 0.0);  // left the wall
    const double e = out.v_s.z() / v0;
    const double ke_in = 0.5 * kTetMass * v0 * v0;
    INFO("zeta " << zeta << ": rebound " << e << " v0 against " << kelvin_voigt_restitution(zeta)
                 << "; dashpot work " << contact.damping_work() << " J, sphere's KE change "
                 << out.ke_s - ke_in << " J");
    CHECK(std::abs(e - kelvin_voigt_restitution(zeta)) < 0.01);
    // The wall does not move: the sphere's loss is the dashpot's work. damping_work() books the
    // dashpot's power at the mid-step velocity, half a step from the displacement the forces
    // work on: an O(zeta omega dt) difference, 3 % of KE_in allowed (measured: 0.27 % at
    // zeta 0.2, 2.0 % at zeta 1). The energy balance itself uses work(), not this figure.
    CHECK(contact.damping_work() < 0.0);
    CHECK(std::abs(contact.damping_work() - (out.ke_s - ke_in)) < 0.03 * ke_in);
    CHECK(std::abs((out.ke_s - ke_in) / ke_in -
                   (std::pow(kelvin_voigt_restitution(zeta), 2) - 1.0)) < 0.02);
  }
}

TEST_CASE("rigid sphere penalty: the stable step limit", "[contact][rigid_penalty]") {
  SECTION("its value on the single-spring configuration") {
    // Sphere resting on q0: only q0 inside, the sphere at rest, so exactly one point
    // counts; its triangle's nodes each belong to 3 of the tet's faces (s_a = 3).
    const Model model = fixed_tet();
    State s = reference_state(model);
    for (size_t i = 0; i < s.x.size(); ++i) s.inv_m[i] = 1.0 / (1e5 / 24.0);  // rho V / 4
    RigidSpherePenalty contact(boundary(model, "tet"), on_q0(kTetR - 1e-4, 0.0));
    const double omega2 = kTetPenalty * 3.0 / (1e5 / 24.0) + kTetPenalty / kTetMass;
    // The bound carries no safety factor: the integrator applies dt_safety (eq. CT.1).
    const double expected = 2.0 / std::sqrt(omega2);
    CHECK(test::relative_error(contact.step_bound(s, kNoStepCeiling).stiffness_dt, expected) <
          1e-14);
    CHECK(std::isinf(contact.step_bound(s, kNoStepCeiling).kinematic_dt));
    // With dashpots at zeta: times sqrt(1 + zeta^2) - zeta (sqrt(2) - 1 at zeta = 1).
    RigidSpherePenaltyParams damped = on_q0(kTetR - 1e-4, 0.0);
    damped.damping = 1.0;
    RigidSpherePenalty with_dashpot(boundary(model, "tet"), damped);
    CHECK(test::relative_error(with_dashpot.step_bound(s, kNoStepCeiling).stiffness_dt,
                               (std::sqrt(2.0) - 1.0) * expected) < 1e-14);
    // Far away and at rest: no limit. Far away and approaching: the time to come within reach
    // at twice the predictor's reach bound (docs/contact-time-step.md): gap - 1e-6 R at
    // 2 x 2 m/s, or, falling from rest under gravity, 2 g tau^2 / 2 = gap - 1e-6 R.
    RigidSpherePenalty far(boundary(model, "tet"), on_q0(1.0, 0.0));
    CHECK(std::isinf(far.step_bound(s, kNoStepCeiling).stiffness_dt));
    CHECK(std::isinf(far.step_bound(s, kNoStepCeiling).kinematic_dt));
    const double reach = 1.0 - kTetR - 1e-6 * kTetR;
    RigidSpherePenalty coming(boundary(model, "tet"), on_q0(1.0, -2.0));
    CHECK(test::relative_error(coming.step_bound(s, kNoStepCeiling).kinematic_dt, reach / 4.0) <
          1e-12);
    RigidSpherePenaltyParams dropped = on_q0(1.0, 0.0);
    dropped.gravity = Vec3(0.0, 0.0, -9.81);
    RigidSpherePenalty falling(boundary(model, "tet"), dropped);
    CHECK(test::relative_error(falling.step_bound(s, kNoStepCeiling).kinematic_dt,
                               std::sqrt(reach / 9.81)) < 1e-12);
  }

  SECTION("a huge K_P shortens the step of a run, which stays stable") {
    const Model model = free_box();
    Probe soft(boundary(model), oblique_impact(1e3));
    Probe stiff(boundary(model), oblique_impact(1e7));
    RunOptions opt;
    opt.time.end_time = 2e-3;
    opt.time.output_interval = 1e-3;
    opt.contact = &soft;
    const RunSummary r_soft = run_explicit(model, opt);
    opt.contact = &stiff;
    const RunSummary r_stiff = run_explicit(model, opt);
    REQUIRE(r_soft.verdict == Verdict::completed);
    REQUIRE(r_stiff.verdict == Verdict::completed);
    const auto min_limit = [](const Probe& p) {
      double m = std::numeric_limits<double>::infinity();
      for (const Probe::Step& st : p.steps) m = std::min(m, st.limit);
      return m;
    };
    // With the springs far stiffer than the box, eq. CT.1 gives dt = 0.9 k / sqrt(1 + (k /
    // dt_s)^2) = 0.9 k to within 1e-4 (k < 0.01 dt_s): a step "at the bound" is within 0.1 % of it.
    long bound = 0;
    for (const Probe::Step& st : stiff.steps) {
      CHECK(st.dt <= st.limit * (1.0 + 1e-12));
      if (st.dt >= 0.999 * st.limit) ++bound;
    }
    INFO("structural dt " << r_stiff.dt_initial << " s; smallest limit: K_P 1e3 " << min_limit(soft)
                          << " s, 1e7 " << min_limit(stiff) << " s; " << bound << " of "
                          << stiff.steps.size() << " steps at the limit; energy error "
                          << r_stiff.energy_balance_error << ", penetration "
                          << stiff.penetration_max());
    // The rest are the structural steps before the sphere can reach the box and the steps that
    // land on an output time, split into equal shares (measured: 102 of 115 at the bound).
    CHECK(bound > static_cast<long>(stiff.steps.size()) * 8 / 10);
    // (The steps before the sphere can reach the box, 0.5 mm away, are structural.)
    // K_P 1e7 makes the springs' bound about 1/90 of the box's (measured 1.83e-6 s against the
    // structural 1.58e-4 s): the step falls by that factor.
    CHECK(r_stiff.dt_contact_min < 0.02 * r_stiff.dt_initial);
    // The node term K_P s_a / m_a dominates: the limit scales as 1 / sqrt(K_P), 100x shorter
    // for 1e4 x K_P, to the few per cent the sphere term K_P n_s / m_s adds.
    CHECK(min_limit(stiff) / min_limit(soft) == Approx(0.01).epsilon(0.05));
    CHECK(r_stiff.energy_balance_error < 0.01);
  }

  SECTION("forced beyond it") {
    // The sphere rests on the single spring under gravity (static penetration m g / K_P = 1e-4
    // m) and oscillates about it (amplitude 2e-5 m): a linear oscillator while in contact.
    // The bound is 2 / omega, tight here (omega^2 = K_P / m_s + 7, exact to 1e-4), and the step
    // taken is eq. CT.1 with s = 0.9. Scaling the bound by 0.65 / 0.9 gives omega dt = 1.3: the
    // motion stays bounded; by 1.5 / 0.9, omega dt = 3 > 2: it blows up.
    const double g = 10.0, z_eq = kTetR - kTetMass * g / kTetPenalty;
    const double omega = std::sqrt(kTetPenalty / kTetMass);
    for (const double scale : {0.65 / 0.9, 1.5 / 0.9}) {
      const Model model = fixed_tet();
      RigidSpherePenaltyParams p = on_q0(z_eq - 2e-5, 0.0);
      p.gravity = Vec3(0.0, 0.0, -g);
      Probe contact(boundary(model, "tet"), p, scale);
      RunOptions opt;
      opt.time.end_time = 20 * 2 * std::numbers::pi / omega;  // 20 periods
      opt.contact = &contact;
      const RunSummary r = run_explicit(model, opt);
      double excursion = 0.0, omega_dt = 0.0;
      for (const Probe::Step& st : contact.steps) {
        excursion = std::max(excursion, std::abs(st.z_s - z_eq));
        omega_dt = std::max(omega_dt, omega * st.dt);
      }
      INFO("scale " << scale << ": omega dt " << omega_dt << ", steps " << r.steps
                    << ", largest |z - z_eq| " << excursion << ", " << to_string(r.verdict) << " "
                    << r.instability.reason);
      // The step eq. CT.1 gives: the structural step dt_s = dt_initial / 0.9 (the tet is fixed).
      const double dt_s = r.dt_initial / 0.9, k = scale * 2.0 / omega;
      const double expected = omega * 0.9 / std::sqrt(1.0 / (dt_s * dt_s) + 1.0 / (k * k));
      if (scale < 1.0) {
        // Central difference at omega dt = 1.3 keeps the amplitude; the synchronous position
        // samples it within 1 / sqrt(1 - (omega dt / 2)^2) = 1.3.
        REQUIRE(expected < 1.4);
        CHECK(omega_dt == Approx(expected).epsilon(1e-3));
        CHECK(excursion < 1.35 * 2e-5);
      } else {
        // It blows up within a few steps: the sphere is thrown off, or driven through the
        // penetration-failure depth 0.5 R (= 250 x the amplitude), which ends the run.
        REQUIRE(expected > 2.5);
        CHECK(omega * contact.steps.front().dt == Approx(expected).epsilon(1e-3));
        CHECK(excursion > 250 * 2e-5);
        CHECK((excursion > 1e3 * 2e-5 || r.verdict == Verdict::unstable));
      }
    }
  }
}

TEST_CASE("rigid sphere penalty: no contact, no force and no work", "[contact][rigid_penalty]") {
  const Model model = free_box();
  RigidSpherePenaltyParams p = oblique_impact(1e6);
  p.sphere.center = Vec3(0.01, 0.01, 0.05);  // 29 mm above the box
  p.sphere.velocity = Vec3(0.3, -0.1, 0.0);  // passing by
  p.gravity = Vec3(0.0, 0.0, 1.0);           // and going up
  RigidSpherePenalty contact(boundary(model), p);
  Recorder rec{contact, {}};
  RunOptions opt;
  opt.time.end_time = 5e-3;
  opt.time.output_interval = 1e-3;
  opt.contact = &contact;
  opt.on_sample = std::ref(rec);
  const RunSummary with = run_explicit(model, opt);
  opt.contact = nullptr;
  opt.on_sample = nullptr;
  const RunSummary without = run_explicit(model, opt);
  REQUIRE(with.verdict == Verdict::completed);
  // The penalty limit does not act before the sphere can arrive: the same steps.
  CHECK(with.steps == without.steps);
  CHECK(with.dt_min == without.dt_min);
  for (const Sample& x : rec.samples) {
    CHECK(x.F_s == Vec3::Zero());
    CHECK(x.work == 0.0);
    CHECK(x.sphere_work == 0.0);
    CHECK(x.penetration == 0.0);
    // Free flight under constant acceleration is exact for central difference.
    const Vec3 expected = p.sphere.center + x.t * p.sphere.velocity + 0.5 * x.t * x.t * p.gravity;
    CHECK(test::relative_error(x.x_s, expected) < 1e-14);
  }
  CHECK(contact.work() == 0.0);
}

// ---------------------------------------------------------------------------------------------
// The [contact] table of the scene file

namespace {

const std::string& kScene = test::kOneCubeScene;  // 12 lines; [contact] starts on line 13
using test::scene_error_of;

}  // namespace

TEST_CASE("scene [contact]: rigid_penalty parses, builds and records", "[contact][scene]") {
  const Scene none = parse_scene(kScene, "s.toml");
  CHECK(none.contacts.empty());
  CHECK(parse_scene(kScene + "[contact]\nmodel = \"none\"\n", "s.toml").contacts.empty());

  const std::string text = kScene + R"([contact]
model = "rigid_penalty"
body = "cube"
penalty = 2e5
[contact.sphere]
name = "ball"
radius = 0.02
density = 1000.0
center = [0.005, 0.005, 0.031]
velocity = [0.0, 0.0, -1.0]
)";
  const Scene scene = parse_scene(text, "s.toml");
  const ContactSpec& c = scene.contacts.at(0);
  REQUIRE(c.kind == ContactKind::rigid_penalty);
  CHECK(c.body == "cube");
  CHECK(!c.surface);
  CHECK(c.penalty == 2e5);
  CHECK(c.sphere.name == "ball");
  CHECK(c.sphere.mass == Approx(1000.0 * 4.0 / 3.0 * std::numbers::pi * 8e-6).epsilon(1e-14));
  CHECK(c.sphere.velocity == Vec3(0.0, 0.0, -1.0));

  const Model model = build_model(scene);
  ContactSetup setup = build_contact(scene, model);
  REQUIRE(setup.model);
  REQUIRE(setup.histories.size() == 1);
  CHECK(setup.model_name == "rigid_penalty");
  CHECK_THAT(setup.description, Contains("'ball'") && Contains("cube/boundary"));
  const std::vector<std::string> columns = setup.histories[0]->history_columns();
  CHECK(columns.front() == "ball.sphere_x");
  CHECK(columns.back() == "ball.penetration_max");
  CHECK(std::find(columns.begin(), columns.end(), "ball.contact_force_axis") != columns.end());

  // Defaults: penalty 1e6 (thesis), sphere "sphere", velocity 0; the axis is then gravity's.
  const Scene defaults = parse_scene(kScene + R"([gravity]
acceleration = [0.0, -9.81, 0.0]
[contact]
model = "rigid_penalty"
body = "cube"
surface = "boundary"
sphere = { radius = 0.01, mass = 0.1, center = [0.0, 0.0, 1.0] }
)",
                                     "s.toml");
  CHECK(defaults.contacts.at(0).penalty == 1e6);
  CHECK(defaults.contacts.at(0).sphere.name == "sphere");
  CHECK(defaults.contacts.at(0).sphere.velocity == Vec3::Zero());
  ContactSetup d = build_contact(defaults, build_model(defaults));
  const auto& rp = dynamic_cast<const RigidSpherePenalty&>(*d.model);
  CHECK(rp.force_axis() == Vec3(0.0, -1.0, 0.0));
  CHECK(rp.params().gravity == Vec3(0.0, -9.81, 0.0));
}

TEST_CASE("scene [contact]: errors name the file, the line and the key", "[contact][scene]") {
  const std::string head = kScene + "[contact]\nmodel = \"rigid_penalty\"\nbody = \"cube\"\n";
  const std::string sphere = "[contact.sphere]\nradius = 0.01\nmass = 0.1\ncenter = [0, 0, 1]\n";
  // Line 13 [contact], 14 model, 15 body, 16 the next line.
  CHECK(scene_error_of(kScene + "[contact]\nmodel = \"dcr\"\n") ==
        "s.toml:13: contact.surfaces: required key is missing");
  CHECK_THAT(scene_error_of(kScene + "[contact]\nmodel = \"rigid\"\n"),
             Contains("s.toml:14: contact.model: must be one of \"none\", \"dcr\", \"rigid_penalty\""));
  CHECK(scene_error_of(head + "penalti = 1e6\n" + sphere) ==
        "s.toml:16: contact.penalti: unknown key 'penalti' (did you mean 'penalty'?)");
  CHECK(
      scene_error_of(head + "[contact.sphere]\nradius = 0.01\nmass = 0.1\ncentre = [0, 0, 1]\n") ==
      "s.toml:19: contact.sphere.centre: unknown key 'centre' (did you mean 'center'?)");
  CHECK(scene_error_of(head + "[contact.sphere]\nradius = -1\nmass = 0.1\ncenter = [0, 0, 1]\n") ==
        "s.toml:17: contact.sphere.radius: must be > 0 (got -1)");
  CHECK(scene_error_of(head + "penalty = 0\n" + sphere) ==
        "s.toml:16: contact.penalty: must be > 0 (got 0)");
  // Neither the analytic sphere nor a meshed rigid body (docs/rigid-bodies.md, "Penalty").
  CHECK(scene_error_of(head) == "s.toml:13: contact: needs one of: sphere, rigid");
  CHECK_THAT(scene_error_of(head + "[contact.sphere]\nradius = 0.01\nmass = 0.1\ndensity = 1.0\n"
                                   "center = [0, 0, 1]\n"),
             Contains("s.toml:19: contact.sphere.density: give only one of: mass, density"));
  CHECK(scene_error_of(head + "[contact.sphere]\nname = \"cube\"\nradius = 0.01\nmass = 0.1\n"
                              "center = [0, 0, 1]\n") ==
        "s.toml:17: contact.sphere.name: 'cube' is also the name of a body (their history "
        "columns would clash)");
  CHECK_THAT(scene_error_of(kScene + "[contact]\nmodel = \"none\"\nbody = \"cube\"\n"),
             Contains("s.toml:15: contact.body: unknown key 'body'"));

  // Builder: names that do not exist.
  const Scene wrong_body = parse_scene(
      kScene + "[contact]\nmodel = \"rigid_penalty\"\nbody = \"cub\"\n" + sphere, "s.toml");
  const Model model = build_model(wrong_body);
  CHECK_THROWS_WITH(build_contact(wrong_body, model),
                    "s.toml:15: contact.body: no body named 'cub' (bodies: cube)");
  const Scene wrong_surface = parse_scene(head + "surface = \"top\"\n" + sphere, "s.toml");
  CHECK_THROWS_WITH(build_contact(wrong_surface, model),
                    Contains("s.toml:16: contact.surface: no surface named 'cube/top'"));
}

TEST_CASE("scene [contact]: the sphere_on_plate example parses and builds", "[contact][scene]") {
  const Scene scene =
      parse_scene_file(std::string(CCM_SOURCE_DIR) + "/scenes/examples/sphere_on_plate.toml");
  CHECK(scene.warnings.empty());
  REQUIRE(scene.contacts.at(0).kind == ContactKind::rigid_penalty);
  const Model model = build_model(scene);
  const ContactSetup setup = build_contact(scene, model);
  REQUIRE(setup.model);
  // The sphere starts clear of the plate.
  State s = reference_state(model);
  setup.model->add_forces(s);
  CHECK(dynamic_cast<const RigidSpherePenalty&>(*setup.model).active_points() == 0);
}
