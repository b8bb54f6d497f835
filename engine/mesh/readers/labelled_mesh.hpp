// A mesh as a text mesh file states it: nodes and elements under the file's own labels, groups
// by label, each item with the file and line it came from. assemble() turns it into a TetMesh
// (compact numbering, positive tets, outward named triangles) and reports problems at the line
// that caused them.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/readers/mesh_file_report.hpp"

namespace ccm {

struct Place {
  int file = 0;  // index into LabelledMesh::files
  int line = 0;  // 1-based
};

struct LabelledMesh {
  struct Node {
    long label;
    Vec3 x;
    Place at;
  };
  struct Tet {
    long label;
    std::array<long, 4> nodes;
    Place at;
    int region = -1;  // index into region_names; -1: none given
  };
  struct Face {
    std::array<long, 3> nodes;
    long owner = 0;  // label of the tet it is a face of; 0: whichever tet has it
    Place at;
  };
  struct NodeSet {
    std::vector<long> labels;
    Place at;
  };

  std::vector<std::string> files;
  std::vector<Node> nodes;
  std::vector<Tet> tets;
  std::map<std::string, std::vector<Face>> surfaces;
  std::map<std::string, NodeSet> node_sets;
  // The parts of the file (Abaqus: the ELSET= of an *ELEMENT keyword). When every tet has one
  // they become the mesh's regions: nodes of two regions may share a position (parts that meet).
  std::vector<std::string> region_names;
  double length_scale = 1.0;  // every coordinate is multiplied by it

  // How the file format names the parts of the file, for messages ("dataset 2411 (nodes)").
  std::string node_section, tet_section, set_section, surface_section;
  MeshFileReport report;
};

// Nodes are numbered 0..n-1 in ascending label order; tets keep the file's order. A file whose
// tets are all negative is read in that convention (two nodes of each swapped, counted in
// report.inverted_tets). Throws MeshError "<file>:<line>: <section>: ..." for a node defined
// twice, a node on no tet, two nodes at one position, a tet or set using an undefined node, a tet
// of zero volume, tets of both orientations (at the first of the minority), a named triangle that
// is not a face of a tet, or no tet at all (engine/mesh/mesh_defects.hpp).
MeshFile assemble(LabelledMesh&& labelled);

}  // namespace ccm
