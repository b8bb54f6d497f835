#include "engine/mesh/boundary_surface.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace ccm {
namespace {

// Local faces of a positively oriented tet (0,1,2,3), each ordered so its normal points
// away from the opposite vertex.
constexpr int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

struct FaceKey {
  std::array<int, 3> sorted;
  bool operator==(const FaceKey&) const = default;
};

struct FaceKeyHash {
  size_t operator()(const FaceKey& k) const {
    size_t h = static_cast<size_t>(k.sorted[0]);
    h = h * 1000003u ^ static_cast<size_t>(k.sorted[1]);
    h = h * 1000003u ^ static_cast<size_t>(k.sorted[2]);
    return h;
  }
};

FaceKey key_of(const Triangle& t) {
  FaceKey k{t};
  std::sort(k.sorted.begin(), k.sorted.end());
  return k;
}

}  // namespace

// Faces met once are on the boundary. The faces are sorted by their sorted nodes (not counted in
// a hash map: a sort of 4 n small entries is several times faster at 200k tets) and the boundary
// is emitted in tet order, face order, as before.
std::vector<Triangle> extract_boundary(std::span<const Tet> tets) {
  struct Face {
    std::array<int, 3> key;
    int index;  // 4 tet + face
  };
  std::vector<Face> faces;
  faces.reserve(tets.size() * 4);
  for (size_t e = 0; e < tets.size(); ++e)
    for (int f = 0; f < 4; ++f) {
      const Tet& tet = tets[e];
      const int* n = kFaces[f];
      faces.push_back(
          {key_of({tet[n[0]], tet[n[1]], tet[n[2]]}).sorted, static_cast<int>(4 * e) + f});
    }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  std::vector<char> once(faces.size(), 0);
  for (size_t i = 0; i < faces.size();) {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j == i + 1) once[static_cast<size_t>(faces[i].index)] = 1;
    i = j;
  }
  std::vector<Triangle> boundary;
  for (size_t e = 0; e < tets.size(); ++e)
    for (int f = 0; f < 4; ++f)
      if (once[4 * e + static_cast<size_t>(f)]) {
        const Tet& tet = tets[e];
        boundary.push_back({tet[kFaces[f][0]], tet[kFaces[f][1]], tet[kFaces[f][2]]});
      }
  return boundary;
}

std::vector<int> owning_tets(std::span<const Tet> tets, std::span<const Triangle> triangles) {
  std::unordered_map<FaceKey, int, FaceKeyHash> wanted;  // triangle face -> owning tet
  wanted.reserve(triangles.size());
  for (const Triangle& t : triangles) wanted.emplace(key_of(t), -1);
  for (size_t e = 0; e < tets.size(); ++e) {
    const Tet& tet = tets[e];
    for (const auto& f : kFaces) {
      const auto it = wanted.find(key_of({tet[f[0]], tet[f[1]], tet[f[2]]}));
      if (it != wanted.end() && it->second < 0) it->second = static_cast<int>(e);
    }
  }
  std::vector<int> owner;
  owner.reserve(triangles.size());
  for (const Triangle& t : triangles) owner.push_back(wanted.at(key_of(t)));
  return owner;
}

Vec3 triangle_normal(const Triangle& t, std::span<const Vec3> x) {
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).normalized();
}

double triangle_area(const Triangle& t, std::span<const Vec3> x) {
  return 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
}

AreaShares area_shares(const std::vector<Triangle>& surface, const std::vector<Vec3>& X) {
  std::map<int, double> share;
  AreaShares out;
  for (const Triangle& t : surface) {
    const double A = triangle_area(t, X);
    out.area += A;
    for (int n : t) share[n] += A / 3.0;
  }
  if (!(out.area > 0.0)) return out;
  for (const auto& [node, a] : share) {
    out.nodes.push_back(node);
    out.share.push_back(a / out.area);
  }
  return out;
}

}  // namespace ccm
