#include "engine/contact/dcr/nodal_pressure_update.hpp"

#include <Eigen/Geometry>  // cross
#include <cmath>

#include "engine/material/material.hpp"

namespace ccm::dcr {
namespace {

bool uses_nodal_pressure(const ModelMesh& mesh, int element) {
  const Body& b = mesh.bodies[static_cast<size_t>(mesh.element_body[static_cast<size_t>(element)])];
  return b.element == ElementKind::nodal_pressure;
}

// Marks the nodal-pressure elements holding a node of `nodes` and returns them.
std::vector<int> elements_at(const ModelMesh& mesh, const std::vector<char>& nodes) {
  std::vector<int> out;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    if (!uses_nodal_pressure(mesh, e)) continue;
    bool touches = false;
    for (int n : mesh.tets[static_cast<size_t>(e)])
      touches = touches || nodes[static_cast<size_t>(n)];
    if (touches) out.push_back(e);
  }
  return out;
}

// U(J) = lambda/2 (ln J)^2 and p = U'(J) = lambda ln J / J (eq. NP.2-NP.3); J <= 0 (next to an
// inverted element) counts as the kernel does: p = 0, U = 0.
struct Volumetric {
  double U = 0.0, p = 0.0;
};
Volumetric volumetric(double V, double V0, double lambda) {
  const double J = V / V0;
  if (!(J > 0.0)) return {};
  const double log_J = std::log(J);
  return {0.5 * lambda * log_J * log_J, lambda * log_J / J};
}

Vec3 position_before(int i, std::span<const Vec3> before, std::span<const int> before_index,
                     const std::vector<Vec3>& x) {
  const int b = before_index[static_cast<size_t>(i)];
  return b >= 0 ? before[static_cast<size_t>(b)] : x[static_cast<size_t>(i)];
}

}  // namespace

NodalPressureUpdate::NodalPressureUpdate(const ModelMesh& mesh, std::span<const int> movable) {
  const auto n_nodes = static_cast<size_t>(mesh.n_nodes());
  std::vector<char> ring(n_nodes, 0);
  for (int n : movable) ring[static_cast<size_t>(n)] = 1;
  for (int e : elements_at(mesh, ring))  // N1 candidates: the nodes of E1 candidates
    for (int n : mesh.tets[static_cast<size_t>(e)]) ring[static_cast<size_t>(n)] = 1;
  const std::vector<int> prepared = elements_at(mesh, ring);  // E2 candidates
  if (prepared.empty()) return;

  V0_node_.assign(n_nodes, 0.0);
  lambda_node_.assign(n_nodes, 0.0);
  for (int e : prepared) {
    const Tet& t = mesh.tets[static_cast<size_t>(e)];
    elements_.push_back(t);
    Vec3 X[4], unused[4];
    for (int c = 0; c < 4; ++c) X[c] = mesh.X[static_cast<size_t>(t[c])];
    const double V0 = volume(X, unused);
    const Body& b = mesh.bodies[static_cast<size_t>(mesh.element_body[static_cast<size_t>(e)])];
    for (int n : t) {
      V0_node_[static_cast<size_t>(n)] += 0.25 * V0;  // eq. NP.1 (exact for the nodes of N1)
      lambda_node_[static_cast<size_t>(n)] = lame_from(b.material).lambda;
    }
  }
  around_ = NodeElements(n_nodes, elements_, [](int) { return true; });
  moves_.assign(elements_.size(), 0);
  stamp_element_.assign(elements_.size(), -1);
  stamp_node_.assign(n_nodes, -1);
  pressure_.assign(n_nodes, {});
  volume_.assign(elements_.size(), {});
}

// V_e = det(Ds) / 6 with the columns e_c = x_{c+1} - x_0; dV_e/dx_{c+1} = e_{c+1} x e_{c+2} / 6
// and node 0 minus their sum (eq. NP.4).
double NodalPressureUpdate::volume(const Vec3 (&x)[4], Vec3 (&dV)[4]) {
  const Vec3 e[3] = {x[1] - x[0], x[2] - x[0], x[3] - x[0]};
  dV[0].setZero();
  for (int c = 0; c < 3; ++c) {
    dV[c + 1] = e[(c + 1) % 3].cross(e[(c + 2) % 3]) / 6.0;
    dV[0] -= dV[c + 1];
  }
  return e[0].dot(dV[1]);
}

// E1 (prepared elements at a moved node, flagged in moves_), N1 (their nodes) and E2 (every
// prepared element at a node of N1), each in first-seen order.
void NodalPressureUpdate::mark_rings(std::span<const int> moved) {
  ++epoch_;
  for (int k : ring_elements_) moves_[static_cast<size_t>(k)] = 0;  // E1 of the last apply()
  ring_nodes_.clear();
  ring_elements_.clear();
  for (int m : moved)
    for (int j = around_.begin(m); j < around_.end(m); ++j) {
      const auto k = static_cast<size_t>(around_.at(j));
      moves_[k] = 1;
      for (int n : elements_[k])
        if (stamp_node_[static_cast<size_t>(n)] != epoch_) {
          stamp_node_[static_cast<size_t>(n)] = epoch_;
          ring_nodes_.push_back(n);
        }
    }
  for (int n : ring_nodes_)
    for (int j = around_.begin(n); j < around_.end(n); ++j) {
      const int k = around_.at(j);
      if (stamp_element_[static_cast<size_t>(k)] == epoch_) continue;
      stamp_element_[static_cast<size_t>(k)] = epoch_;
      ring_elements_.push_back(k);
    }
}

// V_e before and after the move of every element of E2 (equal outside E1).
void NodalPressureUpdate::element_volumes(std::span<const Vec3> before,
                                          std::span<const int> before_index,
                                          const std::vector<Vec3>& x) {
  Vec3 unused[4];
  for (int k : ring_elements_) {
    const Tet& e = elements_[static_cast<size_t>(k)];
    Vec3 x_old[4], x_new[4];
    for (int c = 0; c < 4; ++c) {
      x_new[c] = x[static_cast<size_t>(e[c])];
      x_old[c] = position_before(e[c], before, before_index, x);
    }
    const double V_new = volume(x_new, unused);
    volume_[static_cast<size_t>(k)] = {
        moves_[static_cast<size_t>(k)] ? volume(x_old, unused) : V_new, V_new};
  }
}

// dQ_vol = sum_{n in N1} V0_n [U(J_n(x~)) - U(J_n(x))], and the pressures before and after.
NodalPressureUpdate::Change NodalPressureUpdate::nodal_energy(std::span<const Vec3> before,
                                                              std::span<const int> before_index,
                                                              const std::vector<Vec3>& x) {
  element_volumes(before, before_index, x);
  Change out;
  for (int n : ring_nodes_) {
    const auto i = static_cast<size_t>(n);
    double V_old = 0.0, V_new = 0.0;  // eq. NP.2, over every element at n (all in E2)
    for (int j = around_.begin(n); j < around_.end(n); ++j) {
      const ElementVolume& v = volume_[static_cast<size_t>(around_.at(j))];
      V_old += 0.25 * v.old_value;
      V_new += 0.25 * v.new_value;
    }
    const Volumetric old_value = volumetric(V_old, V0_node_[i], lambda_node_[i]);
    const Volumetric new_value = volumetric(V_new, V0_node_[i], lambda_node_[i]);
    out.stored += V0_node_[i] * (new_value.U - old_value.U);
    pressure_[i] = {old_value.p, new_value.p};
  }
  return out;
}

// df_a = -[pbar_e(x~) dV_e/dx_a(x~) - pbar_e(x) dV_e/dx_a(x)] of prepared element k (eq. NP.4).
void NodalPressureUpdate::add_force_change(int k, std::span<const Vec3> before,
                                           std::span<const int> before_index, State& s,
                                           std::span<const double> inv_m, double dt,
                                           Change& out) const {
  const Tet& e = elements_[static_cast<size_t>(k)];
  Vec3 x_new[4], x_old[4], dV_new[4], dV_old[4];
  double p_old = 0.0, p_new = 0.0;  // 4 pbar_e; nodes outside N1 keep their pressure
  for (int c = 0; c < 4; ++c) {
    const int i = e[c];
    x_new[c] = s.x[static_cast<size_t>(i)];
    x_old[c] = position_before(i, before, before_index, s.x);
    if (stamp_node_[static_cast<size_t>(i)] != epoch_) continue;
    p_old += pressure_[static_cast<size_t>(i)].p_old;
    p_new += pressure_[static_cast<size_t>(i)].p_new;
  }
  volume(x_new, dV_new);
  if (moves_[static_cast<size_t>(k)])
    volume(x_old, dV_old);  // E1: all four nodes are in N1, so p_old and p_new are whole sums
  for (int c = 0; c < 4; ++c) {
    // Outside E1 the gradient is unchanged and only the change of the N1 pressures counts.
    const Vec3 df = moves_[static_cast<size_t>(k)]
                        ? Vec3(-0.25 * (p_new * dV_new[c] - p_old * dV_old[c]))
                        : Vec3(-0.25 * (p_new - p_old) * dV_new[c]);
    const auto i = static_cast<size_t>(e[c]);
    if (inv_m[i] == 0.0) continue;  // fixed: the boundary condition keeps it at rest
    s.a[i] += inv_m[i] * df;
    out.kinetic += 0.5 * dt * s.v[i].dot(df);
  }
}

NodalPressureUpdate::Change NodalPressureUpdate::apply(std::span<const int> moved,
                                                       std::span<const Vec3> before,
                                                       std::span<const int> before_index, State& s,
                                                       std::span<const double> inv_m, double dt) {
  if (empty()) return {};
  mark_rings(moved);
  Change out = nodal_energy(before, before_index, s.x);
  for (int k : ring_elements_) add_force_change(k, before, before_index, s, inv_m, dt, out);
  return out;
}

}  // namespace ccm::dcr
