// The whole model's mesh: every body's nodes and tets in one numbering, plus the named node
// sets and surfaces the boundary conditions, observers and contact models refer to.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "engine/core/element_kind.hpp"
#include "engine/material/material.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

struct Body {
  std::string name;
  MaterialParams material;
  int first_node = 0;
  int n_nodes = 0;
  int first_element = 0;
  int n_elements = 0;
  std::vector<Triangle> boundary;  // outward-oriented boundary triangles (global node ids)
  ElementKind element = kDefaultElementKind;  // the formulation of its tets (docs/elements.md)
  // A rigid body's elements are left out of the step: no internal forces, no mass on its nodes,
  // no stable-step limit (engine/body/rigid_bodies.hpp moves its nodes).
  bool rigid = false;
};

struct NamedSurface {
  int body = 0;
  std::vector<Triangle> triangles;  // global node ids, outward oriented
};

struct ModelMesh {
  std::vector<Vec3> X;            // reference positions
  std::vector<Tet> tets;          // global node ids
  std::vector<int> element_body;  // body index per element
  std::vector<Body> bodies;
  std::map<std::string, std::vector<int>> node_sets;  // "<body>" and "<body>/<surface>"
  std::map<std::string, NamedSurface> surfaces;       // "<body>/boundary" and "<body>/<surface>"

  int n_nodes() const { return static_cast<int>(X.size()); }
  int n_elements() const { return static_cast<int>(tets.size()); }
  int body_index(const std::string& name) const;  // -1 when absent
};

// Appends a body: its nodes and tets are renumbered after the existing ones, its boundary
// surface extracted, and node sets "<name>", "<name>/boundary" and one per named surface and named
// node set made (a named node set with a surface's name adds its nodes to the surface's set).
void add_body(ModelMesh& mesh, const std::string& name, const MaterialParams& material,
              const TetMesh& geometry);

// Sorted unique node ids of a set of triangles.
std::vector<int> nodes_of(const std::vector<Triangle>& triangles);

}  // namespace ccm
