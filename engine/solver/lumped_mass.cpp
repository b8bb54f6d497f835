#include "engine/solver/lumped_mass.hpp"

namespace ccm {

std::vector<double> lumped_mass(const ModelMesh& mesh, const ElementSet& elements) {
  std::vector<double> m(static_cast<size_t>(mesh.n_nodes()), 0.0);
  for (int e = 0; e < elements.n_elements(); ++e) {
    const Body& body = mesh.bodies[static_cast<size_t>(mesh.element_body[static_cast<size_t>(e)])];
    if (body.rigid) continue;  // its mass is the rigid body's (engine/body/)
    const double share = body.material.rho * elements.reference[static_cast<size_t>(e)].V0 / 4.0;
    for (int n : elements.tets[static_cast<size_t>(e)]) m[static_cast<size_t>(n)] += share;
  }
  return m;
}

}  // namespace ccm
