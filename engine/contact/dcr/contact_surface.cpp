#include "engine/contact/dcr/contact_surface.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

namespace ccm::dcr {
namespace {

// The body whose node range holds node n, or -1.
int body_of_node(const ModelMesh& mesh, int n) {
  for (size_t b = 0; b < mesh.bodies.size(); ++b) {
    const Body& body = mesh.bodies[b];
    if (n >= body.first_node && n < body.first_node + body.n_nodes) return static_cast<int>(b);
  }
  return -1;
}

}  // namespace

SurfaceFeatures make_surface_features(const ModelMesh& mesh,
                                      const std::vector<std::string>& surface_names) {
  SurfaceFeatures f;

  // Faces, in the order given, each distinct node triple once.
  std::vector<std::pair<Triangle, int>> seen;  // (sorted triple, face index)
  for (const std::string& name : surface_names) {
    const auto it = mesh.surfaces.find(name);
    if (it == mesh.surfaces.end())
      throw std::invalid_argument("contact surface \"" + name + "\" does not exist");
    for (const Triangle& t : it->second.triangles) {
      for (int n : t)
        if (n < 0 || n >= mesh.n_nodes())
          throw std::invalid_argument("contact surface \"" + name + "\" references node " +
                                      std::to_string(n) + ", outside the mesh");
      Triangle key = t;
      std::sort(key.begin(), key.end());
      seen.emplace_back(key, f.n_faces());
      f.faces.push_back(t);
      f.face_body.push_back(it->second.body);
    }
  }
  std::sort(seen.begin(), seen.end());
  std::vector<char> keep(f.faces.size(), 1);
  for (size_t i = 1; i < seen.size(); ++i)
    if (seen[i].first == seen[i - 1].first) keep[static_cast<size_t>(seen[i].second)] = 0;
  if (std::find(keep.begin(), keep.end(), 0) != keep.end()) {
    size_t out = 0;
    for (size_t i = 0; i < f.faces.size(); ++i) {
      if (!keep[i]) continue;
      f.faces[out] = f.faces[i];
      f.face_body[out] = f.face_body[i];
      ++out;
    }
    f.faces.resize(out);
    f.face_body.resize(out);
  }

  // Edges: the sides of the faces, each once, owned by the body of the first face with it.
  std::vector<std::tuple<int, int, int>> sides;  // (a, b, face) with a < b
  sides.reserve(f.faces.size() * 3);
  for (size_t i = 0; i < f.faces.size(); ++i) {
    const Triangle& t = f.faces[i];
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<size_t>(k)];
      const int b = t[static_cast<size_t>((k + 1) % 3)];
      sides.emplace_back(std::min(a, b), std::max(a, b), static_cast<int>(i));
    }
  }
  std::sort(sides.begin(), sides.end());
  for (size_t i = 0; i < sides.size(); ++i) {
    const auto [a, b, face] = sides[i];
    if (i > 0 && std::get<0>(sides[i - 1]) == a && std::get<1>(sides[i - 1]) == b) continue;
    f.edges.push_back({a, b});
    f.edge_body.push_back(f.face_body[static_cast<size_t>(face)]);
  }

  // Nodes, owned by the body whose node range holds them (else by their first face's body).
  f.nodes = nodes_of(f.faces);
  f.node_body.assign(f.nodes.size(), -1);
  for (size_t i = 0; i < f.nodes.size(); ++i) f.node_body[i] = body_of_node(mesh, f.nodes[i]);
  if (std::find(f.node_body.begin(), f.node_body.end(), -1) != f.node_body.end()) {
    for (size_t i = 0; i < f.faces.size(); ++i)
      for (int n : f.faces[i]) {
        const auto pos = std::lower_bound(f.nodes.begin(), f.nodes.end(), n) - f.nodes.begin();
        int& body = f.node_body[static_cast<size_t>(pos)];
        if (body == -1) body = f.face_body[i];
      }
  }
  return f;
}

}  // namespace ccm::dcr
