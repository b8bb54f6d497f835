#include "engine/contact/dcr/projection_update.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/element/stable_step.hpp"
#include "engine/material/linear_elastic.hpp"
#include "engine/material/neo_hookean.hpp"

namespace ccm::dcr {
namespace {

// The largest distance a node of a tet moved.
double largest_move(const Vec3 (&before)[4], const Vec3 (&after)[4]) {
  double d2 = 0.0;
  for (int c = 0; c < 4; ++c) d2 = std::max(d2, (after[c] - before[c]).squaredNorm());
  return std::sqrt(d2);
}

// W(F) and P(F) of the body's material (eq. 2.1; eq. 2.2-2.3).
double energy_density(MaterialModel model, const Mat3& F, const Lame& lame) {
  switch (model) {
    case MaterialModel::neo_hookean:
      return neo_hookean::strain_energy_density(F, lame);
    case MaterialModel::linear_elastic:
      return linear_elastic::strain_energy_density(F, lame);
  }
  throw std::logic_error("projection update: unknown material model");
}

Mat3 first_piola(MaterialModel model, const Mat3& F, const Lame& lame) {
  switch (model) {
    case MaterialModel::neo_hookean: {
      const double J = F.determinant();
      return neo_hookean::first_piola(F, J * F.inverse().transpose(), J, lame);
    }
    case MaterialModel::linear_elastic:
      return linear_elastic::stress(F, lame);  // P = sigma at small strain
  }
  throw std::logic_error("projection update: unknown material model");
}

// The element part of the energy: the whole W for a plain tet, W_e = W with lambda = 0 for the
// nodal-pressure tet (eq. NP.2; its volumetric part is NodalPressureUpdate's).
Lame element_lame(const Body& body) {
  Lame lame = lame_from(body.material);
  if (body.element == ElementKind::nodal_pressure) lame.lambda = 0.0;
  return lame;
}

}  // namespace

ProjectionUpdate::ProjectionUpdate(const ModelMesh& mesh, std::span<const int> movable)
    : nodal_pressure_(mesh, movable) {
  const auto n_nodes = static_cast<size_t>(mesh.n_nodes());
  std::vector<bool> is_movable(n_nodes, false);
  for (int n : movable) is_movable[static_cast<size_t>(n)] = true;
  std::vector<Tet> prepared;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const Tet& t = mesh.tets[static_cast<size_t>(e)];
    bool touches = false;
    for (int n : t) touches = touches || is_movable[static_cast<size_t>(n)];
    if (!touches) continue;
    const auto& X = mesh.X;
    const auto reference = make_tet_reference(X[t[0]], X[t[1]], X[t[2]], X[t[3]]);
    if (!reference) throw std::invalid_argument("projection update: degenerate reference tet");
    const Body& body = mesh.bodies[static_cast<size_t>(mesh.element_body[static_cast<size_t>(e)])];
    elements_.push_back({t, *reference, body.material.model, element_lame(body),
                         lame_from(body.material), body.material.rho});
    prepared.push_back(t);
  }
  around_ =
      NodeElements(n_nodes, prepared, [&](int n) { return is_movable[static_cast<size_t>(n)]; });
  stamp_.assign(elements_.size(), -1);
  before_index_.assign(n_nodes, -1);
}

// F = Ds Dm^-1; f_a = -V0 P grad N_a: columns of -V0 P Dm^-T for a = 1..3, f_0 = -(f_1+f_2+f_3).
double ProjectionUpdate::evaluate(const Element& e, const Vec3 (&x)[4], double sign,
                                  Vec3 (&f)[4]) const {
  const Mat3 F = edge_matrix(x[0], x[1], x[2], x[3]) * e.reference.Dm_inv;
  const Mat3 H = -e.reference.V0 * first_piola(e.model, F, e.lame) * e.reference.Dm_inv.transpose();
  for (int a = 1; a < 4; ++a) {
    f[a] += sign * H.col(a - 1);
    f[0] -= sign * H.col(a - 1);
  }
  return e.reference.V0 * energy_density(e.model, F, e.lame);
}

std::vector<int> ProjectionUpdate::element_nodes(std::span<const int> moved) const {
  std::vector<int> nodes;
  for (int n : moved)
    for (int j = around_.begin(n); j < around_.end(n); ++j) {
      const Tet& t = elements_[static_cast<size_t>(around_.at(j))].nodes;
      nodes.insert(nodes.end(), t.begin(), t.end());
    }
  return nodes;
}

ProjectionUpdate::EnergyChange ProjectionUpdate::apply(std::span<const int> moved,
                                                       std::span<const Vec3> before, State& s,
                                                       std::span<const double> inv_m, double dt) {
  const std::vector<Vec3>& x = s.x;
  ++epoch_;
  for (size_t k = 0; k < moved.size(); ++k)
    before_index_[static_cast<size_t>(moved[k])] = static_cast<int>(k);
  EnergyChange dE;
  for (int n : moved)
    for (int j = around_.begin(n); j < around_.end(n); ++j) {
      const auto k = static_cast<size_t>(around_.at(j));
      if (stamp_[k] == epoch_) continue;
      stamp_[k] = epoch_;
      const Element& e = elements_[k];
      Vec3 x_new[4], x_old[4], df[4];
      for (int c = 0; c < 4; ++c) {
        const auto i = static_cast<size_t>(e.nodes[c]);
        x_new[c] = x[i];
        const int b = before_index_[i];
        x_old[c] = b >= 0 ? before[static_cast<size_t>(b)] : x[i];
        df[c].setZero();
      }
      dE.stored += evaluate(e, x_new, 1.0, df) - evaluate(e, x_old, -1.0, df);
      const Mat3 Ds = edge_matrix(x_new[0], x_new[1], x_new[2], x_new[3]);
      dE.stable_dt = std::min(
          dE.stable_dt, element_stable_dt(e.model, Ds, e.reference.Dm_inv, e.stiffness, e.rho0));
      dE.jump_ratio =
          std::max(dE.jump_ratio, largest_move(x_old, x_new) / characteristic_length(Ds));
      for (int c = 0; c < 4; ++c) {
        const auto i = static_cast<size_t>(e.nodes[c]);
        if (inv_m[i] == 0.0) continue;  // fixed: the boundary condition keeps it at rest
        s.a[i] += inv_m[i] * df[c];
        dE.kinetic += 0.5 * dt * s.v[i].dot(df[c]);
      }
    }
  const NodalPressureUpdate::Change nodal =
      nodal_pressure_.apply(moved, before, before_index_, s, inv_m, dt);
  dE.stored += nodal.stored;
  dE.kinetic += nodal.kinetic;
  for (int n : moved) before_index_[static_cast<size_t>(n)] = -1;
  return dE;
}

}  // namespace ccm::dcr
