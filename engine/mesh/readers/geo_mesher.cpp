#include "engine/mesh/readers/geo_mesher.hpp"

#include <fmt/format.h>

#include "engine/mesh/gmsh_api.hpp"
#include "engine/mesh/gmsh_mesher.hpp"

namespace ccm {

TetMesh mesh_geo_file(const std::filesystem::path& path) {
  const std::string where = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw MeshError(fmt::format("{}: no such file", where));
  return mesh_gmsh_model(where, [&] {
    gmsh::open(path.string());
    gmsh::model::mesh::generate(3);
  });
}

}  // namespace ccm
