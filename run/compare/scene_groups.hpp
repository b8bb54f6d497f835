// A scene's own dimensionless groups, where a study's grid meets it (docs/compare.md, "What a
// study predicts"): the impactor I is the body `ccm compare` makes rigid, the artifact A the
// deformable body it strikes.
//   ER  = E_I / E_A                                   (eq. 2.32)
//   RLS = D_I / L_A                                   (eq. 2.33)
//   KE* = KE / (E_A L_A^3),   KE = m_I |v_I - v_A|^2 / 2
//   density ratio rho_I / rho_A,   window (t_f - t_c) c_A / L_A,   c_A^2 = E_A / rho_A
// with D_I the diameter of the sphere of the impactor's mass at its density as written
// ((6 m / (pi rho))^(1/3): the sphere's own diameter for the thesis's impactor, whose `mass` is
// the solid's), L_A the largest extent of the artifact's
// bounding box (the plate's side for the thesis's), and t_c the first sample at which the
// artifact moves in the deformable run.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/solver/model.hpp"
#include "run/scene/scene.hpp"

namespace ccm {

struct SceneGroups {
  std::string impactor, artifact;  // body names
  double E_I = 0.0, E_A = 0.0, rho_I = 0.0, rho_A = 0.0;
  double D_I = 0.0, L_A = 0.0, m_I = 0.0, relative_speed = 0.0;
  double modulus_ratio = 0.0;        // ER
  double length_ratio = 0.0;         // RLS
  double kinetic_energy = 0.0;       // KE [J]
  double kinetic_energy_star = 0.0;  // KE*
  double density_ratio = 0.0;
  std::optional<double> window;  // (t_f - t_c) c_A / L_A, when the artifact moved
};

// The groups, or why they cannot be formed: `rigid` must name one body and one other body must
// stay deformable (the artifact). `contact_time`: t_c, when known.
struct GroupsOrReason {
  std::optional<SceneGroups> groups;
  std::string reason;
};
GroupsOrReason scene_groups(const Scene& scene, const Model& model,
                            const std::vector<std::string>& rigid,
                            std::optional<double> contact_time);

// The window (t_f - t_c) c_A / L_A of groups formed without t_c, once it is known.
double contact_window(const SceneGroups& groups, const Scene& scene, double contact_time);

}  // namespace ccm
