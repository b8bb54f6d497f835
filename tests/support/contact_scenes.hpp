// Building blocks for the DCR contact evidence tests: meshed shapes, per-body measures, and
// mesh edits (carving, random renumbering).
#pragma once

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "engine/bc/node_selection.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "tests/support/two_bodies.hpp"

namespace ccm::test {

// A Gmsh sphere of the given radius and characteristic length, centred at `centre`.
inline TetMesh gmsh_sphere(double radius, double mesh_size, const Vec3& centre) {
  PrimitiveSpec spec{};
  spec.kind = PrimitiveKind::sphere;
  spec.radius = radius;
  spec.mesh_size = mesh_size;
  Placement placement;
  placement.translation = centre;
  return mesh_primitive(spec, placement);
}

// Kinetic energy 1/2 sum m v^2 of one body.
inline double kinetic_energy(const State& s, const Body& b) {
  double e = 0.0;
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n)
    e += 0.5 * s.m_lumped[static_cast<size_t>(n)] * s.v[static_cast<size_t>(n)].squaredNorm();
  return e;
}

// Total lumped mass of one body.
inline double body_mass(const State& s, const Body& b) {
  double m = 0.0;
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n)
    m += s.m_lumped[static_cast<size_t>(n)];
  return m;
}

// Gives every node of body `body` the initial velocity v.
inline void set_body_velocity(Model& model, int body, const Vec3& v) {
  const Body& b = model.mesh.bodies[static_cast<size_t>(body)];
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n)
    model.initial_velocity[static_cast<size_t>(n)] = v;
}

// Removes the tets whose centroid lies inside the box [lo, hi], then the nodes no tet uses
// (the remaining nodes keep their relative order).
inline TetMesh carved(const TetMesh& m, const Vec3& lo, const Vec3& hi) {
  TetMesh out;
  std::vector<int> new_id(m.nodes.size(), -1);
  std::vector<Tet> kept;
  for (const Tet& t : m.tets) {
    Vec3 c = Vec3::Zero();
    for (int n : t) c += m.nodes[static_cast<size_t>(n)];
    c /= 4.0;
    const bool inside = (c.array() >= lo.array()).all() && (c.array() <= hi.array()).all();
    if (!inside) kept.push_back(t);
  }
  for (const Tet& t : kept)
    for (int n : t) new_id[static_cast<size_t>(n)] = 0;
  int next = 0;
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (new_id[i] == 0) {
      new_id[i] = next++;
      out.nodes.push_back(m.nodes[i]);
    }
  for (Tet t : kept) {
    for (int& n : t) n = new_id[static_cast<size_t>(n)];
    out.tets.push_back(t);
  }
  return out;
}

// The same mesh with its nodes renumbered by a random permutation and its tets listed in a
// random order (each tet keeps its vertex order, hence its orientation). Named surfaces follow.
inline TetMesh permuted(const TetMesh& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<int> perm(m.nodes.size());  // perm[old] = new
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  TetMesh out;
  out.nodes.resize(m.nodes.size());
  for (size_t i = 0; i < m.nodes.size(); ++i) out.nodes[static_cast<size_t>(perm[i])] = m.nodes[i];
  out.tets = m.tets;
  for (Tet& t : out.tets)
    for (int& n : t) n = perm[static_cast<size_t>(n)];
  std::shuffle(out.tets.begin(), out.tets.end(), rng);
  for (const auto& [name, tris] : m.named_surfaces) {
    std::vector<Triangle> renamed = tris;
    for (Triangle& tr : renamed)
      for (int& n : tr) n = perm[static_cast<size_t>(n)];
    out.named_surfaces[name] = std::move(renamed);
  }
  return out;
}

// Shortest edge of any tet of the model, in the reference configuration.
inline double shortest_tet_edge(const ModelMesh& mesh) {
  double h = std::numeric_limits<double>::infinity();
  for (const Tet& t : mesh.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        h = std::min(
            h, (mesh.X[static_cast<size_t>(t[i])] - mesh.X[static_cast<size_t>(t[j])]).norm());
  return h;
}

}  // namespace ccm::test
