#include "engine/mesh/readers/mesh_file.hpp"

#include <fmt/format.h>

#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/mesh/readers/fields.hpp"
#include "engine/mesh/readers/geo_mesher.hpp"
#include "engine/mesh/readers/inp_reader.hpp"
#include "engine/mesh/readers/unv_reader.hpp"

namespace ccm {

std::string known_mesh_extensions() { return ".msh, .unv, .inp, .geo"; }

MeshFile read_mesh_file_with_report(const std::filesystem::path& path) {
  const std::string extension = upper(path.extension().string());
  if (extension == ".UNV") return read_unv_file(path);
  if (extension == ".INP") return read_inp_file(path);
  MeshFile out;
  if (extension == ".MSH") {
    out.mesh = read_msh_file(path);
    out.report.format = "Gmsh MSH";
  } else if (extension == ".GEO") {
    out.mesh = mesh_geo_file(path);
    out.report.format = "Gmsh script, meshed by Gmsh";
  } else {
    throw MeshError(fmt::format("{}: unknown mesh file type '{}' (known: {})", path.string(),
                                path.extension().string(), known_mesh_extensions()));
  }
  return out;
}

TetMesh read_mesh_file(const std::filesystem::path& path) {
  return read_mesh_file_with_report(path).mesh;
}

}  // namespace ccm
