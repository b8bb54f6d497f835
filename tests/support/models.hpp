// Small models the engine tests share.
#pragma once

#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"

namespace ccm::test {

inline MaterialParams neo_hookean(double E, double nu, double rho) {
  return {MaterialModel::neo_hookean, E, nu, rho};
}

// One body meshed as a structured box.
inline Model box_model(const Vec3& size, int nx, int ny, int nz, const MaterialParams& material) {
  ModelMesh mesh;
  add_body(mesh, "box", material, structured_box(size, nx, ny, nz));
  return make_model(std::move(mesh));
}

inline Vec3 linear_momentum(const State& s) {
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < s.n_nodes(); ++i) p += s.m_lumped[i] * s.v[i];
  return p;
}

inline Vec3 angular_momentum(const State& s) {
  Vec3 L = Vec3::Zero();
  for (int i = 0; i < s.n_nodes(); ++i) L += s.m_lumped[i] * s.x[i].cross(s.v[i]);
  return L;
}

}  // namespace ccm::test
