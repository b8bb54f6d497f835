#include "engine/mesh/model_mesh.hpp"

#include <algorithm>

#include "engine/mesh/boundary_surface.hpp"

namespace ccm {
namespace {

std::vector<Triangle> offset(const std::vector<Triangle>& tris, int by) {
  std::vector<Triangle> out(tris);
  for (auto& t : out)
    for (int& n : t) n += by;
  return out;
}

}  // namespace

int ModelMesh::body_index(const std::string& name) const {
  for (size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].name == name) return static_cast<int>(b);
  return -1;
}

std::vector<int> nodes_of(const std::vector<Triangle>& triangles) {
  std::vector<int> nodes;
  nodes.reserve(triangles.size() * 3);
  for (const auto& t : triangles) nodes.insert(nodes.end(), t.begin(), t.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

void add_body(ModelMesh& mesh, const std::string& name, const MaterialParams& material,
              const TetMesh& geometry) {
  const int node_offset = mesh.n_nodes();
  const int body_id = static_cast<int>(mesh.bodies.size());

  Body body{
      name, material, node_offset, geometry.n_nodes(), mesh.n_elements(), geometry.n_elements(),
      {}};
  mesh.X.insert(mesh.X.end(), geometry.nodes.begin(), geometry.nodes.end());
  for (Tet t : geometry.tets) {
    for (int& n : t) n += node_offset;
    mesh.tets.push_back(t);
    mesh.element_body.push_back(body_id);
  }
  body.boundary = offset(extract_boundary(geometry.tets), node_offset);

  std::vector<int> all(static_cast<size_t>(body.n_nodes));
  for (int i = 0; i < body.n_nodes; ++i) all[static_cast<size_t>(i)] = node_offset + i;
  mesh.node_sets[name] = std::move(all);
  mesh.node_sets[name + "/boundary"] = nodes_of(body.boundary);
  mesh.surfaces[name + "/boundary"] = {body_id, body.boundary};
  for (const auto& [surface_name, tris] : geometry.named_surfaces) {
    NamedSurface s{body_id, offset(tris, node_offset)};
    mesh.node_sets[name + "/" + surface_name] = nodes_of(s.triangles);
    mesh.surfaces[name + "/" + surface_name] = std::move(s);
  }
  for (const auto& [set_name, nodes] : geometry.named_node_sets) {
    std::vector<int>& set = mesh.node_sets[name + "/" + set_name];  // a surface's: the union
    for (int n : nodes) set.push_back(n + node_offset);
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  }
  mesh.bodies.push_back(std::move(body));
}

}  // namespace ccm
