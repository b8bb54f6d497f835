#include "engine/distributed/partition.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <stdexcept>

namespace ccm::distributed {

int element_cost(MaterialModel model) {
  // Thread CPU time of `ccm run`'s step loop on one ~20k-tet block, the two materials
  // interleaved three times (docs/parallel.md): neo-Hookean 0.357, 0.376, 0.407 s, linear
  // elastic 0.471, 0.529, 0.407 s (medians 0.376 and 0.471 s: ratio 1.25 = 5/4).
  switch (model) {
    case MaterialModel::neo_hookean:
      return 4;
    case MaterialModel::linear_elastic:
      return 5;
  }
  return 5;
}

namespace {

// A rigid body's elements are not stepped: they cost nothing.
idx_t cost_of(const ModelMesh& mesh, size_t e) {
  const Body& body = mesh.bodies[static_cast<size_t>(mesh.element_body[e])];
  return body.rigid ? 0 : element_cost(body.material.model);
}

using Face = std::array<int, 3>;

Face sorted_face(const Tet& t, int skip) {
  Face f{};
  int k = 0;
  for (int c = 0; c < 4; ++c)
    if (c != skip) f[static_cast<size_t>(k++)] = t[static_cast<size_t>(c)];
  std::sort(f.begin(), f.end());
  return f;
}

}  // namespace

std::vector<int> partition_elements(const ModelMesh& mesh, int n_parts) {
  std::vector<int> part(mesh.tets.size(), 0);  // a rigid body's elements stay in part 0
  std::vector<size_t> stepped;                 // the elements METIS balances
  for (size_t e = 0; e < mesh.tets.size(); ++e)
    if (cost_of(mesh, e) > 0) stepped.push_back(e);
  auto n_elements = static_cast<idx_t>(stepped.size());
  if (n_parts <= 1 || n_elements == 0) return part;
  std::vector<idx_t> eptr(stepped.size() + 1), eind(4 * stepped.size()), weights(stepped.size());
  for (size_t k = 0; k < stepped.size(); ++k) {
    eptr[k] = static_cast<idx_t>(4 * k);
    for (size_t c = 0; c < 4; ++c) eind[4 * k + c] = mesh.tets[stepped[k]][c];
    weights[k] = cost_of(mesh, stepped[k]);
  }
  eptr.back() = static_cast<idx_t>(eind.size());
  idx_t n_nodes = mesh.n_nodes(), common = 3, parts = n_parts, cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // the same partition on every rank and every run
  options[METIS_OPTION_NUMBERING] = 0;
  std::vector<idx_t> epart(stepped.size()), npart(mesh.X.size());
  const int status =
      METIS_PartMeshDual(&n_elements, &n_nodes, eptr.data(), eind.data(), weights.data(), nullptr,
                         &common, &parts, nullptr, options, &cut, epart.data(), npart.data());
  if (status != METIS_OK)
    throw std::runtime_error(fmt::format("METIS_PartMeshDual failed (status {})", status));
  for (size_t k = 0; k < stepped.size(); ++k) part[stepped[k]] = static_cast<int>(epart[k]);
  return part;
}

PartitionQuality measure_partition(const ModelMesh& mesh, const std::vector<int>& part,
                                   int n_parts) {
  PartitionQuality q;
  q.part_cost.assign(static_cast<size_t>(n_parts), 0);
  for (size_t e = 0; e < part.size(); ++e)
    q.part_cost[static_cast<size_t>(part[e])] += cost_of(mesh, e);
  const long total = std::accumulate(q.part_cost.begin(), q.part_cost.end(), 0L);
  const long largest = *std::max_element(q.part_cost.begin(), q.part_cost.end());
  if (total > 0)
    q.imbalance = static_cast<double>(largest) * n_parts / static_cast<double>(total) - 1.0;
  // Faces: every tet's four, sorted; a face met twice is interior, cut when its parts differ.
  std::vector<std::pair<Face, int>> faces;
  faces.reserve(4 * mesh.tets.size());
  for (size_t e = 0; e < mesh.tets.size(); ++e)
    for (int c = 0; c < 4; ++c) faces.push_back({sorted_face(mesh.tets[e], c), part[e]});
  std::sort(faces.begin(), faces.end());
  for (size_t i = 0; i + 1 < faces.size(); ++i)
    if (faces[i].first == faces[i + 1].first && faces[i].second != faces[i + 1].second)
      ++q.cut_faces;
  return q;
}

}  // namespace ccm::distributed
