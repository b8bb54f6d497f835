#include "run/compare/scene_groups.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/body/mass_properties.hpp"

namespace ccm {
namespace {

std::vector<Tet> tets_of(const ModelMesh& mesh, const Body& b) {
  return {mesh.tets.begin() + b.first_element, mesh.tets.begin() + b.first_element + b.n_elements};
}

double largest_extent(const ModelMesh& mesh, const Body& b) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()),
       hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n) {
    lo = lo.cwiseMin(mesh.X[static_cast<size_t>(n)]);
    hi = hi.cwiseMax(mesh.X[static_cast<size_t>(n)]);
  }
  return (hi - lo).maxCoeff();
}

}  // namespace

GroupsOrReason scene_groups(const Scene& scene, const Model& model,
                            const std::vector<std::string>& rigid,
                            std::optional<double> contact_time) {
  if (rigid.size() != 1)
    return {std::nullopt,
            fmt::format("the groups need one impactor; {} bodies are made rigid", rigid.size())};
  std::vector<size_t> deformable;
  for (size_t b = 0; b < scene.bodies.size(); ++b)
    if (!scene.bodies[b].rigid && scene.bodies[b].name != rigid.front()) deformable.push_back(b);
  if (deformable.size() != 1)
    return {std::nullopt,
            fmt::format("the groups need one artifact (one body that stays deformable); this "
                        "scene has {}",
                        deformable.size())};
  const ModelMesh& mesh = model.mesh;
  const int i = mesh.body_index(rigid.front());
  const auto a = static_cast<int>(deformable.front());
  const Body& I = mesh.bodies[static_cast<size_t>(i)];
  const Body& A = mesh.bodies[static_cast<size_t>(a)];
  SceneGroups g;
  g.impactor = I.name;
  g.artifact = A.name;
  g.E_I = I.material.E;
  g.E_A = A.material.E;
  // The scene's densities as written: with `mass` given, the model's is mass / meshed volume.
  g.rho_I = scene.bodies[static_cast<size_t>(i)].material.rho;
  g.rho_A = scene.bodies[static_cast<size_t>(a)].material.rho;
  g.m_I = tet_mass_properties(tets_of(mesh, I), mesh.X, I.material.rho).mass;
  g.D_I = std::cbrt(6.0 * (g.m_I / g.rho_I) / std::numbers::pi);
  g.L_A = largest_extent(mesh, A);
  g.relative_speed = (scene.bodies[static_cast<size_t>(i)].initial_velocity -
                      scene.bodies[static_cast<size_t>(a)].initial_velocity)
                         .norm();
  g.modulus_ratio = g.E_I / g.E_A;
  g.length_ratio = g.D_I / g.L_A;
  g.kinetic_energy = 0.5 * g.m_I * g.relative_speed * g.relative_speed;
  g.kinetic_energy_star = g.kinetic_energy / (g.E_A * g.L_A * g.L_A * g.L_A);
  g.density_ratio = g.rho_I / g.rho_A;
  if (contact_time) g.window = contact_window(g, scene, *contact_time);
  return {g, {}};
}

double contact_window(const SceneGroups& g, const Scene& scene, double contact_time) {
  return (scene.time.end - contact_time) * std::sqrt(g.E_A / g.rho_A) / g.L_A;
}

}  // namespace ccm
