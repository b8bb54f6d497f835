#include "engine/solver/model.hpp"

namespace ccm {

Model make_model(ModelMesh mesh) {
  Model m;
  m.elements = make_element_set(mesh);
  m.initial_velocity.assign(mesh.X.size(), Vec3::Zero());
  m.mesh = std::move(mesh);
  return m;
}

}  // namespace ccm
