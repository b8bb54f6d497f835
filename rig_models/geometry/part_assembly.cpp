#include "rig_models/geometry/part_assembly.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "engine/mesh/boundary_surface.hpp"

namespace ccm::rig {

AssembledParts add_parts(ModelMesh& model, const TetMesh& mesh,
                         const std::map<std::string, MaterialParams>& materials) {
  const size_t n_regions = mesh.region_names.size();
  if (n_regions == 0 || mesh.tet_region.size() != mesh.tets.size())
    throw std::invalid_argument("add_parts: the mesh has no named regions");
  for (const std::string& name : mesh.region_names)
    if (!materials.count(name))
      throw std::invalid_argument(fmt::format("add_parts: no material for part '{}'", name));
  // Owner of each node: the first region whose tets use it.
  std::vector<int> owner(mesh.nodes.size(), static_cast<int>(n_regions));
  for (size_t e = 0; e < mesh.tets.size(); ++e)
    for (int n : mesh.tets[e])
      owner[static_cast<size_t>(n)] = std::min(owner[n], mesh.tet_region[e]);
  AssembledParts out;
  out.node.assign(mesh.nodes.size(), -1);
  for (size_t r = 0; r < n_regions; ++r) {
    const int body_id = static_cast<int>(model.bodies.size());
    const std::string& name = mesh.region_names[r];
    Body body{name, materials.at(name), model.n_nodes(), 0, model.n_elements(), 0, {}};
    for (size_t n = 0; n < mesh.nodes.size(); ++n)
      if (owner[n] == static_cast<int>(r)) {
        out.node[n] = model.n_nodes();
        model.X.push_back(mesh.nodes[n]);
        ++body.n_nodes;
      }
    std::vector<Tet> tets;
    for (size_t e = 0; e < mesh.tets.size(); ++e)
      if (mesh.tet_region[e] == static_cast<int>(r)) tets.push_back(mesh.tets[e]);
    // Interface nodes of an earlier part are numbered already; later ones are not used here.
    for (Tet& t : tets)
      for (int& n : t) n = out.node[static_cast<size_t>(n)];
    for (const Tet& t : tets) {
      model.tets.push_back(t);
      model.element_body.push_back(body_id);
    }
    body.n_elements = static_cast<int>(tets.size());
    body.boundary = extract_boundary(tets);
    std::vector<int> used;
    for (const Tet& t : tets) used.insert(used.end(), t.begin(), t.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    model.node_sets[name] = used;
    model.node_sets[name + "/boundary"] = nodes_of(body.boundary);
    model.surfaces[name + "/boundary"] = {body_id, body.boundary};
    out.nodes_of[name] = std::move(used);
    out.body.push_back(body_id);
    model.bodies.push_back(std::move(body));
  }
  return out;
}

}  // namespace ccm::rig
