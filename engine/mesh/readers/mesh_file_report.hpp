// What reading a mesh file found besides the mesh itself: `ccm mesh info` prints it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

struct MeshFileReport {
  std::string format;                  // e.g. "I-DEAS universal"
  std::optional<int> file_nodes;       // nodes the file defines (also those of no tet)
  std::optional<int> inverted_tets;    // tets given with a negative volume, read with two
                                       // nodes swapped; nullopt: not counted (Gmsh files)
  std::vector<long> inverted_labels;   // the first of them (file labels)
  std::map<std::string, int> ignored;  // elements that are not linear tets, by kind
  std::vector<std::string> notes;      // e.g. nodes of a set that belong to no tet
  std::vector<long> tet_labels;        // file label of every tet; empty: tet i is i + 1
};

struct MeshFile {
  TetMesh mesh;
  MeshFileReport report;
};

}  // namespace ccm
