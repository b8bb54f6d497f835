// Gmsh scripts (.geo): Gmsh runs the script and meshes the model in 3D with the script's own
// mesh sizes, fields and options, as `gmsh -3 FILE.geo` would.
#pragma once

#include <filesystem>

#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// Named physical surfaces become named surfaces and named physical volumes regions, as for a
// .msh file (mesh_gmsh_model). A .geo file is a program: it may include or merge other files, and
// Gmsh's SystemCall runs shell commands; read only scripts you trust. Throws MeshError naming
// the path when the file is missing, Gmsh fails or the mesh holds no linear tetrahedron.
TetMesh mesh_geo_file(const std::filesystem::path& path);

}  // namespace ccm
