// `ccm mesh info FILE [--json]`: what ccm reads from a mesh file (.msh, .unv, .inp, .geo).
#pragma once

#include <filesystem>
#include <vector>

namespace ccm {

struct MeshInfoArgs {
  std::filesystem::path file;
  bool json = false;
  std::vector<double> material;  // empty, or E [Pa], nu, rho [kg/m^3]: the stable steps in s
};

// Prints node and tet counts, the bounding box, the volume, the named surfaces and node sets with
// their sizes and the element quality (dihedral angles, h_e, the tets of smallest h_e, and with a
// material the stable steps they imply) to stdout. Returns 0, or 2
// with "ccm: error: <file>:<line>: <dataset or keyword>: <problem>" on stderr for a file it cannot
// read, 1 for an internal error.
int mesh_info_command(const MeshInfoArgs& args);

}  // namespace ccm
