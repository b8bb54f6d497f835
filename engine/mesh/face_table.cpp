#include "engine/mesh/face_table.hpp"

#include <Eigen/Geometry>
#include <algorithm>

namespace ccm {

FaceTable::FaceTable(const std::vector<Tet>& tets, const std::vector<char>& keep) {
  for (const Tet& t : tets) {
    for (int opposite = 0; opposite < 4; ++opposite) {
      std::array<int, 3> f;
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != opposite) f[j++] = t[k];
      if (!keep[f[0]] || !keep[f[1]] || !keep[f[2]]) continue;
      std::sort(f.begin(), f.end());
      faces_.push_back({f, t[opposite]});
    }
  }
  std::stable_sort(faces_.begin(), faces_.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
}

int FaceTable::opposite_node(std::array<int, 3> f) const {
  std::sort(f.begin(), f.end());
  const auto it =
      std::lower_bound(faces_.begin(), faces_.end(), f,
                       [](const auto& entry, const auto& key) { return entry.first < key; });
  return it != faces_.end() && it->first == f ? it->second : -1;
}

Triangle oriented_away_from(Triangle t, int opposite, const std::vector<Vec3>& x) {
  const Vec3 normal = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
  if (normal.dot(x[opposite] - x[t[0]]) > 0) std::swap(t[1], t[2]);
  return t;
}

}  // namespace ccm
