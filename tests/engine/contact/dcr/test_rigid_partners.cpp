// Evidence for the free rigid body in the DCR velocity solve (engine/contact/dcr/
// rigid_partners.hpp, eq. RB.6 of docs/rigid-bodies.md): one node striking a free rigid body's
// face off its centre, perfectly inelastic along the normal. The closed form of a point impact:
//   lambda = v0 / (1/m + 1/M + (r x n)^T I^-1 (r x n)),
// after which the normal relative velocity at the contact point is zero, the node's and the
// body's momenta changed by opposite amounts, and the angular momentum about any point is kept.
#include <catch2/catch.hpp>

#include "engine/contact/dcr/contact_impulses.hpp"
#include "engine/contact/dcr/rigid_partners.hpp"

using namespace ccm;
using namespace ccm::dcr;

TEST_CASE(
    "DCR velocity solve: a node striking a free rigid body takes the point-impact impulse "
    "of the body's mobility",
    "[rigid-body][dcr]") {
  // Nodes: 0 the striking node (body 0), 1-3 a face of the rigid body (body 1), 4 another node of
  // the body.
  const double m = 0.02, M = 0.5, v0 = 2.0;
  const Vec3 n = Vec3(0.2, -0.1, 1.0).normalized();
  const Vec3 c(0.01, -0.02, -0.05);  // the body's centre of mass
  const Mat3 I = Vec3(2e-4, 3e-4, 4e-4).asDiagonal();
  State s;
  s.x = {Vec3(0.03, 0.01, 0.0), Vec3(0.02, 0.0, 0.0), Vec3(0.05, 0.0, 0.0), Vec3(0.02, 0.03, 0.0),
         c};
  const Vec3 P = (s.x[1] + s.x[2] + s.x[3]) / 3.0;  // the contact point: the face's centroid
  s.x[0] = P;
  s.v = {-v0 * n, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  const std::vector<int> node_body = {0, 1, 1, 1, 1};
  RigidState body;
  body.body = 1;
  body.center = c;
  body.pivot = c;
  body.inverse_mass = 1.0 / M;
  body.inverse_inertia = I.inverse();
  s.rigid = {body};
  RigidPartners partners;
  partners.reset(s, node_body, 2);
  REQUIRE(partners.size() == 1);

  ContactRow row;  // g = n . (x_0 - centroid): grad on the node n, on each face node -n/3
  row.nodes = {0, 1, 2, 3};
  row.grad = {n, -n / 3.0, -n / 3.0, -n / 3.0};
  row.beta = {1.0, -1.0 / 3.0, -1.0 / 3.0, -1.0 / 3.0};
  row.t1 = n.unitOrthogonal();
  row.t2 = n.cross(row.t1);
  row.S = 1.0;
  row.W_n = 1.0 / m;  // the node's share; the solve adds the body's
  row.W_t = 1.0 / m;
  std::vector<ContactRow> rows = {row};
  const std::vector<double> inv_m = {1.0 / m, 0.0, 0.0, 0.0, 0.0};
  std::vector<Vec3> v = s.v;
  ContactImpulses solver;
  const ImpulseSolve solve =
      solver.solve(rows, {0}, inv_m, v, {.tolerance = 1e-14}, &partners, &s.x);
  REQUIRE(solve.converged);

  const Vec3 r = P - c;
  const double W = 1.0 / m + 1.0 / M + r.cross(n).dot(I.inverse() * r.cross(n));
  const double lambda = v0 / W;
  // One row, solved in one update: the closed form to round-off.
  CHECK(rows[0].lambda_n == Approx(lambda).epsilon(1e-12));
  const RigidPartner& b = partners[0];
  const double rate = n.dot(v[0] - b.velocity_at(P));
  CHECK(std::abs(rate) < 1e-12 * v0);
  // Momentum: the node's change and the body's are opposite; angular momentum about the origin.
  const Vec3 dp_node = m * (v[0] - s.v[0]), dp_body = M * b.velocity;
  CHECK((dp_node + dp_body).norm() < 1e-14 * m * v0);
  const Vec3 dL = P.cross(dp_node) + c.cross(dp_body) + I * b.omega;
  CHECK(dL.norm() < 1e-14 * m * v0 * 0.1);
  // The body turns: the contact point is off its centre.
  CHECK(b.omega.norm() > 0.0);
}

TEST_CASE(
    "DCR velocity solve: a node striking a pinned rigid body takes the impulse of its mobility "
    "about the pin",
    "[rigid-body][dcr]") {
  // The body turns only about the axis e through p (moment of inertia J about it): its mobility
  // at the contact point P along n is ((P - p) x n . e)^2 / J (RB.10), and the closed form of a
  // perfectly inelastic point impact is lambda = v0 / (1/m + ((P - p) x n . e)^2 / J).
  const double m = 0.02, J = 3e-4, v0 = 2.0;
  const Vec3 n = Vec3(0.2, -0.1, 1.0).normalized();
  const Vec3 p(-0.04, 0.01, -0.02), e = Vec3(0.1, 1.0, 0.2).normalized();
  State s;
  s.x = {Vec3::Zero(), Vec3(0.02, 0.0, 0.0), Vec3(0.05, 0.0, 0.0), Vec3(0.02, 0.03, 0.0)};
  const Vec3 P = (s.x[1] + s.x[2] + s.x[3]) / 3.0;
  s.x[0] = P;
  s.v = {-v0 * n, Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  const std::vector<int> node_body = {0, 1, 1, 1};
  RigidState body;
  body.body = 1;
  body.inverse_inertia = e * e.transpose() / J;
  body.pivot = p;
  s.rigid = {body};
  RigidPartners partners;
  partners.reset(s, node_body, 2);
  REQUIRE(partners.size() == 1);
  ContactRow row;
  row.nodes = {0, 1, 2, 3};
  row.grad = {n, -n / 3.0, -n / 3.0, -n / 3.0};
  row.beta = {1.0, -1.0 / 3.0, -1.0 / 3.0, -1.0 / 3.0};
  row.t1 = n.unitOrthogonal();
  row.t2 = n.cross(row.t1);
  row.S = 1.0;
  row.W_n = 1.0 / m;
  row.W_t = 1.0 / m;
  std::vector<ContactRow> rows = {row};
  const std::vector<double> inv_m = {1.0 / m, 0.0, 0.0, 0.0};
  std::vector<Vec3> v = s.v;
  ContactImpulses solver;
  REQUIRE(solver.solve(rows, {0}, inv_m, v, {.tolerance = 1e-14}, &partners, &s.x).converged);
  const double arm = (P - p).cross(n).dot(e);
  CHECK(rows[0].lambda_n == Approx(v0 / (1.0 / m + arm * arm / J)).epsilon(1e-12));
  const RigidPartner& b = partners[0];
  CHECK(std::abs(n.dot(v[0] - b.velocity_at(P))) < 1e-12 * v0);
  // It turns about e only, and the angular momentum about the axis is kept (the pin's reaction
  // has no moment about it); its kinetic energy is J w^2 / 2.
  CHECK((b.omega - b.omega.dot(e) * e).norm() < 1e-15 * b.omega.norm());
  const Vec3 dp_node = m * (v[0] - s.v[0]);
  CHECK(std::abs(e.dot((P - p).cross(dp_node)) + J * b.omega.dot(e)) < 1e-14 * m * v0 * 0.1);
  CHECK(b.kinetic_energy() == Approx(0.5 * J * b.omega.squaredNorm()).epsilon(1e-12));
}
