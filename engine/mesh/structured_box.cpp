#include "engine/mesh/structured_box.hpp"

#include <stdexcept>

namespace ccm {

TetMesh structured_box(const Vec3& size, int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1)
    throw std::invalid_argument("structured_box: cell counts must be >= 1");
  TetMesh mesh;
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.nodes.emplace_back(size.x() * i / nx, size.y() * j / ny, size.z() * k / nz);

  // The six tets of the unit cube sharing the diagonal 0-7, as paths 0 -> 7 along cube
  // edges (corner c has bits x=1, y=2, z=4). Each is positively oriented for even permutations.
  constexpr int kPaths[6][4] = {{0, 1, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7},
                                {0, 3, 2, 7}, {0, 6, 4, 7}, {0, 5, 1, 7}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        auto corner = [&](int c) {
          return id(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        };
        for (const auto& p : kPaths)
          mesh.tets.push_back({corner(p[0]), corner(p[1]), corner(p[2]), corner(p[3])});
      }
  return mesh;
}

}  // namespace ccm
