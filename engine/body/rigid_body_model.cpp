#include "engine/body/rigid_body_model.hpp"

#include <vector>

#include "engine/mesh/model_mesh.hpp"

namespace ccm {

RigidBodyModel make_rigid(ModelMesh& mesh, int body, RigidMotion motion) {
  Body& b = mesh.bodies[static_cast<size_t>(body)];
  b.rigid = true;
  b.element = ElementKind::tet4;  // no element of it is ever evaluated
  const std::vector<Tet> tets(mesh.tets.begin() + b.first_element,
                              mesh.tets.begin() + b.first_element + b.n_elements);
  RigidBodyModel m;
  m.body = body;
  m.motion = motion;
  m.mass = tet_mass_properties(tets, mesh.X, b.material.rho);
  return m;
}

}  // namespace ccm
