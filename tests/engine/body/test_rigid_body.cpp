// Evidence for the rigid body (engine/body/; docs/rigid-bodies.md): mass properties of a meshed
// box against the closed form; a torque-free asymmetric body spun near its intermediate axis
// keeps its energy and angular momentum over 100 flips and flips at the rate of the exact
// (Jacobi elliptic) solution (3.3 million steps: [heavy], left out of the sanitizer pass, whose
// runs of the rigid body in tests/engine/body/test_rigid_in_run.cpp step the same code); a
// constant force and a constant torque give the closed-form motion.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/body/mass_properties.hpp"
#include "engine/body/rigid_body.hpp"
#include "engine/mesh/structured_box.hpp"

using namespace ccm;

namespace {

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Principal moments 1, 2, 3 kg m^2 with the principal axes along x, y, z.
MassProperties asymmetric_body() {
  MassProperties p;
  p.mass = 2.0;
  p.center = Vec3(0.1, -0.2, 0.3);
  p.inertia = Vec3(1.0, 2.0, 3.0).asDiagonal();
  return p;
}

}  // namespace

TEST_CASE("tet mass properties of a box equal the closed form", "[rigid-body]") {
  const Vec3 size(0.3, 0.2, 0.1);
  const double rho = 1200.0;
  const TetMesh box = structured_box(size, 3, 4, 5);
  const MassProperties p = tet_mass_properties(box.tets, box.nodes, rho);
  const double m = rho * size.prod();
  // Linear tets integrate x x^T exactly: round-off only (1e-12).
  CHECK(relative(p.mass, m) < 1e-12);
  CHECK((p.center - 0.5 * size).norm() < 1e-12 * size.norm());
  const Vec3 s2 = size.cwiseProduct(size);
  const Mat3 exact =
      Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y()).asDiagonal() * (m / 12.0);
  CHECK((p.inertia - exact).norm() < 1e-12 * exact.norm());
  // The parallel axis theorem about a corner: I_xx = m (b^2 + c^2) / 3.
  const Mat3 corner = inertia_about(p, -p.center);
  CHECK(relative(corner(0, 0), m * (s2.y() + s2.z()) / 3.0) < 1e-12);
  CHECK(relative(corner(0, 1), -m * size.x() * size.y() / 4.0) < 1e-12);
}

TEST_CASE("mass properties refuse an empty or inverted volume", "[rigid-body]") {
  const TetMesh box = structured_box(Vec3(1, 1, 1), 1, 1, 1);
  CHECK_THROWS_AS(tet_mass_properties({}, box.nodes, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(tet_mass_properties(box.tets, box.nodes, 0.0), std::invalid_argument);
  std::vector<Tet> inverted = box.tets;
  for (Tet& t : inverted) std::swap(t[0], t[1]);
  CHECK_THROWS_AS(tet_mass_properties(inverted, box.nodes, 1.0), std::invalid_argument);
}

// Landau & Lifshitz, Mechanics, section 37: for M^2 > 2 E I2 the body-frame omega_2 is
// proportional to sn(tau, k) with tau = t sqrt((I3 - I2)(M^2 - 2 E I1) / (I1 I2 I3)) and
// k^2 = (I2 - I1)(2 E I3 - M^2) / ((I3 - I2)(M^2 - 2 E I1)): it changes sign every 2 K(k) of tau.
TEST_CASE(
    "a torque-free body spun near its intermediate axis flips at the exact rate and keeps "
    "its energy and angular momentum over 100 flips",
    "[rigid-body][heavy]") {
  RigidBody body(asymmetric_body());
  const Vec3 I = body.principal_moments();
  REQUIRE(I.isApprox(Vec3(1.0, 2.0, 3.0)));
  const Vec3 omega0(0.01, 1.0, 0.01);  // rad/s, near the intermediate axis (y)
  body.set_angular_velocity(omega0);
  const double E0 = body.kinetic_energy();
  const Vec3 L0 = body.angular_momentum();
  const double M2 = L0.squaredNorm();
  REQUIRE(M2 > 2.0 * E0 * I.y());
  const double rate = std::sqrt((I.z() - I.y()) * (M2 - 2.0 * E0 * I.x()) / I.prod());
  const double k2 =
      (I.y() - I.x()) * (2.0 * E0 * I.z() - M2) / ((I.z() - I.y()) * (M2 - 2.0 * E0 * I.x()));
  const double flip_interval = 2.0 * std::comp_ellint_1(std::sqrt(k2)) / rate;

  const double h = 1e-3;  // s: h |omega| = 1e-3
  auto intermediate = [&] { return body.angular_velocity().dot(body.rotation() * Vec3::UnitY()); };
  // The body-frame component along the intermediate axis: omega . (R e_y), R the rotation since
  // the reference (the reference principal frame is the world frame here).
  double last = intermediate();
  int flips = 0;
  double first_flip = -1.0, last_flip = -1.0, t = 0.0, worst_energy = 0.0, worst_momentum = 0.0;
  bool converged = true;
  while (flips < 101 && t < 5000.0) {
    body.kick(Vec3::Zero(), Vec3::Zero(), 0.5 * h);
    converged = body.drift(h) && converged;
    body.kick(Vec3::Zero(), Vec3::Zero(), 0.5 * h);
    t += h;
    const double now = intermediate();
    if ((now > 0.0) != (last > 0.0)) {
      ++flips;
      const double t_cross = t - h * now / (now - last);  // linear interpolation
      if (first_flip < 0.0) first_flip = t_cross;
      last_flip = t_cross;
    }
    last = now;
    worst_energy = std::max(worst_energy, relative(body.kinetic_energy(), E0));
    // The angular momentum rebuilt from the orientation and the angular velocity.
    const Vec3 L = body.inertia_world() * body.angular_velocity();
    worst_momentum = std::max(worst_momentum, (L - L0).norm() / L0.norm());
  }
  CHECK(converged);
  REQUIRE(flips >= 101);
  // Round-off per step (1e-16) summed over 3.3 million steps, as a random walk: about 1e-13.
  CHECK(worst_energy < 1e-10);
  CHECK(worst_momentum < 1e-10);
  // The midpoint rule's phase error is O((h omega)^2) = 1e-6 of the rate; the separatrix makes
  // the interval sensitive to k, which the scheme keeps exactly (E and M kept): 1e-4.
  const double measured = (last_flip - first_flip) / (flips - 1);
  CHECK(relative(measured, flip_interval) < 1e-4);
}

TEST_CASE(
    "kick-drift-kick is exact for a constant force and a constant torque about a "
    "principal axis",
    "[rigid-body]") {
  RigidBody body(asymmetric_body());
  const Vec3 c0 = body.center(), v0(1.0, 0.0, -2.0), F(0.0, 0.0, -19.62), tau(0.0, 0.0, 0.6);
  body.set_velocity(v0);
  const double h = 1e-3;
  const int steps = 2000;
  for (int n = 0; n < steps; ++n) {
    body.kick(F, tau, 0.5 * h);
    REQUIRE(body.drift(h));
    body.kick(F, tau, 0.5 * h);
  }
  const double t = steps * h;
  const Vec3 c = c0 + v0 * t + 0.5 * F / body.mass() * t * t;
  // The leapfrog integrates a constant acceleration exactly: round-off (1e-12).
  CHECK((body.center() - c).norm() < 1e-12 * c.norm());
  const Vec3 v = v0 + F / body.mass() * t;
  CHECK((body.velocity() - v).norm() < 1e-12 * v.norm());
  // About the z principal axis (I3 = 3): omega = tau t / I3, angle = tau t^2 / (2 I3) in exact
  // arithmetic; the midpoint rotation with linearly growing omega is exact for rotation about a
  // fixed axis up to the Cayley map's angle error, 2 atan(h w / 2) - h w = O((h w)^3) a step.
  CHECK(body.angular_velocity().isApprox(Vec3(0.0, 0.0, tau.z() * t / 3.0), 1e-12));
  const double angle = 2.0 * std::atan2(body.rotation().vec().z(), body.rotation().w());
  CHECK(std::abs(angle - tau.z() * t * t / 6.0) < 1e-6);
}
