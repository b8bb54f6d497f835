// One entry point for every mesh file a scene or `ccm mesh info` names, chosen by the file's
// extension (case-insensitive): .msh (Gmsh MSH 2 or 4), .unv (I-DEAS universal), .inp
// (Abaqus/CalculiX input), .geo (Gmsh script, meshed on reading).
#pragma once

#include <filesystem>
#include <string>

#include "engine/mesh/readers/mesh_file_report.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// The extensions read_mesh_file knows, for messages: ".msh, .unv, .inp, .geo".
std::string known_mesh_extensions();

// Throws MeshError naming the file (and, for .unv and .inp, the line and the dataset or keyword)
// for an unknown extension or a file that cannot be read.
MeshFile read_mesh_file_with_report(const std::filesystem::path& path);
TetMesh read_mesh_file(const std::filesystem::path& path);

}  // namespace ccm
