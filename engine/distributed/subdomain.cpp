#include "engine/distributed/subdomain.hpp"

#include <algorithm>

namespace ccm::distributed {
namespace {

// The ranks touching each global node (CSR: first[n] .. first[n+1]), ascending.
struct NodeRanks {
  std::vector<int> first, ranks;
};

NodeRanks node_ranks(const ModelMesh& mesh, const std::vector<int>& part) {
  std::vector<std::vector<int>> lists(mesh.X.size());
  for (size_t e = 0; e < mesh.tets.size(); ++e)
    for (int n : mesh.tets[e]) {
      std::vector<int>& l = lists[static_cast<size_t>(n)];
      if (std::find(l.begin(), l.end(), part[e]) == l.end()) l.push_back(part[e]);
    }
  NodeRanks r;
  r.first.push_back(0);
  for (std::vector<int>& l : lists) {
    std::sort(l.begin(), l.end());
    r.ranks.insert(r.ranks.end(), l.begin(), l.end());
    r.first.push_back(static_cast<int>(r.ranks.size()));
  }
  return r;
}

ModelMesh local_mesh(const ModelMesh& global, const std::vector<int>& local_elements,
                     const std::vector<int>& local_of) {
  ModelMesh m;
  m.bodies = global.bodies;
  for (Body& b : m.bodies) {  // node ranges, surfaces: global notions, not kept
    b.first_node = b.n_nodes = b.n_elements = 0;
    b.boundary.clear();
  }
  for (size_t b = 0; b < m.bodies.size(); ++b) {  // global elements are body-contiguous
    const auto first = std::lower_bound(local_elements.begin(), local_elements.end(),
                                        global.bodies[b].first_element);
    const auto last =
        std::lower_bound(local_elements.begin(), local_elements.end(),
                         global.bodies[b].first_element + global.bodies[b].n_elements);
    m.bodies[b].first_element = static_cast<int>(first - local_elements.begin());
    m.bodies[b].n_elements = static_cast<int>(last - first);
  }
  for (int e : local_elements) {
    Tet t = global.tets[static_cast<size_t>(e)];
    for (int& n : t) n = local_of[static_cast<size_t>(n)];
    m.tets.push_back(t);
    m.element_body.push_back(global.element_body[static_cast<size_t>(e)]);
  }
  return m;
}

std::vector<char> rigid_elements(const ModelMesh& mesh) {
  std::vector<char> rigid(mesh.tets.size(), 0);
  for (size_t e = 0; e < rigid.size(); ++e)
    rigid[e] = mesh.bodies[static_cast<size_t>(mesh.element_body[e])].rigid ? 1 : 0;
  return rigid;
}

bool on_rigid_body(const ModelMesh& mesh, size_t node) {
  for (const Body& b : mesh.bodies)
    if (b.rigid && static_cast<int>(node) >= b.first_node &&
        static_cast<int>(node) < b.first_node + b.n_nodes)
      return true;
  return false;
}

// A rigid body is whole on every rank, its nodes contiguous in local ids (owned on rank 0, replicas
// elsewhere, each in ascending global id): its node range and surface are kept, in local ids, for
// the rigid-body stepper (engine/body/rigid_bodies.hpp).
void localise_rigid_bodies(const ModelMesh& global, const std::vector<int>& local_of,
                           ModelMesh& local) {
  for (size_t b = 0; b < global.bodies.size(); ++b) {
    const Body& g = global.bodies[b];
    if (!g.rigid) continue;
    Body& l = local.bodies[b];
    l.first_node = local_of[static_cast<size_t>(g.first_node)];
    l.n_nodes = g.n_nodes;
    for (Triangle t : g.boundary) {
      for (int& n : t) n = local_of[static_cast<size_t>(n)];
      l.boundary.push_back(t);
    }
  }
}

void localise_conditions(const Model& global, const std::vector<int>& local_of, int owned,
                         Model& local) {
  auto local_id = [&](int n) { return local_of[static_cast<size_t>(n)]; };
  for (int n : global.bcs.fixed_nodes)
    if (local_id(n) >= 0) local.bcs.fixed_nodes.push_back(local_id(n));
  std::sort(local.bcs.fixed_nodes.begin(), local.bcs.fixed_nodes.end());
  for (const SurfaceLoad& load : global.bcs.loads) {
    SurfaceLoad mine = load;
    mine.nodes.clear();
    mine.area_share.clear();
    for (size_t i = 0; i < load.nodes.size(); ++i) {
      const int l = local_id(load.nodes[i]);
      const bool replicated = on_rigid_body(global.mesh, static_cast<size_t>(load.nodes[i]));
      if (l < 0 || (l >= owned && !replicated)) continue;
      mine.nodes.push_back(l);
      mine.area_share.push_back(load.area_share[i]);
    }
    local.bcs.loads.push_back(std::move(mine));
  }
  local.bcs.gravity = global.bcs.gravity;
}

}  // namespace

std::vector<int> node_owners(const ModelMesh& mesh, const std::vector<int>& element_part,
                             int /*n_ranks*/) {
  const NodeRanks r = node_ranks(mesh, element_part);
  std::vector<int> owner(mesh.X.size(), -1);
  for (size_t n = 0; n < owner.size(); ++n)
    if (r.first[n] < r.first[n + 1]) owner[n] = r.ranks[static_cast<size_t>(r.first[n])];
  return owner;
}

std::vector<HaloSize> halo_sizes(const ModelMesh& mesh, const std::vector<int>& element_part,
                                 int n_ranks) {
  const NodeRanks r = node_ranks(mesh, element_part);
  std::vector<HaloSize> h(static_cast<size_t>(n_ranks));
  std::vector<std::vector<char>> linked(static_cast<size_t>(n_ranks),
                                        std::vector<char>(static_cast<size_t>(n_ranks), 0));
  for (size_t n = 0; n < mesh.X.size(); ++n) {
    const int first = r.first[n], last = r.first[n + 1];
    if (last - first < 2) continue;
    for (int i = first; i < last; ++i) {
      const auto a = static_cast<size_t>(r.ranks[static_cast<size_t>(i)]);
      ++h[a].shared_nodes;
      h[a].neighbour_node_pairs += last - first - 1;
      for (int j = first; j < last; ++j)
        if (j != i) linked[a][static_cast<size_t>(r.ranks[static_cast<size_t>(j)])] = 1;
    }
  }
  for (size_t a = 0; a < h.size(); ++a)
    for (char l : linked[a]) h[a].neighbours += l;
  return h;
}

Subdomain make_subdomain(const Model& global, const std::vector<int>& element_part, int n_ranks,
                         int rank) {
  const ModelMesh& mesh = global.mesh;
  const NodeRanks r = node_ranks(mesh, element_part);
  auto ranks_of = [&](size_t n) {
    return std::span<const int>(r.ranks.data() + r.first[n],
                                static_cast<size_t>(r.first[n + 1] - r.first[n]));
  };
  Subdomain d;
  d.rank = rank;
  d.n_ranks = n_ranks;
  // Local nodes: owned (lowest touching rank is this one) first, then the copies, then (on ranks
  // other than 0) a rigid body's replicas: its elements are all rank 0's (partition.hpp); each
  // group in ascending global id.
  std::vector<int> owned, copies, replicas;
  for (size_t n = 0; n < mesh.X.size(); ++n) {
    const auto rs = ranks_of(n);
    if (std::find(rs.begin(), rs.end(), rank) == rs.end()) {
      if (on_rigid_body(mesh, n)) replicas.push_back(static_cast<int>(n));
      continue;
    }
    (rs.front() == rank ? owned : copies).push_back(static_cast<int>(n));
  }
  d.owned_nodes = static_cast<int>(owned.size());
  d.global_node = owned;
  d.global_node.insert(d.global_node.end(), copies.begin(), copies.end());
  d.global_node.insert(d.global_node.end(), replicas.begin(), replicas.end());
  std::vector<int> local_of(mesh.X.size(), -1);
  for (size_t l = 0; l < d.global_node.size(); ++l)
    local_of[static_cast<size_t>(d.global_node[l])] = static_cast<int>(l);

  const std::vector<char> rigid = rigid_elements(mesh);  // every rank keeps them
  std::vector<int> local_elements;
  for (size_t e = 0; e < element_part.size(); ++e)
    if (element_part[e] == rank || rigid[e]) local_elements.push_back(static_cast<int>(e));
  ModelMesh lm = local_mesh(mesh, local_elements, local_of);
  for (int g : d.global_node) lm.X.push_back(mesh.X[static_cast<size_t>(g)]);
  localise_rigid_bodies(mesh, local_of, lm);
  d.model = make_model(std::move(lm));
  d.model.rigid_bodies = global.rigid_bodies;
  for (size_t l = 0; l < d.global_node.size(); ++l)
    d.model.initial_velocity[l] = global.initial_velocity[static_cast<size_t>(d.global_node[l])];
  localise_conditions(global, local_of, d.owned_nodes, d.model);

  // Shared nodes and neighbours, in ascending global id.
  std::vector<std::vector<int>> with(static_cast<size_t>(n_ranks));
  d.sharer_first.push_back(0);
  std::vector<std::pair<int, int>> shared_by_global;  // (global, local)
  for (size_t l = 0; l < d.global_node.size(); ++l)
    shared_by_global.push_back({d.global_node[l], static_cast<int>(l)});
  std::sort(shared_by_global.begin(), shared_by_global.end());
  for (const auto& [g, l] : shared_by_global) {
    const auto rs = ranks_of(static_cast<size_t>(g));
    if (rs.size() < 2) continue;
    for (int q : rs)
      if (q != rank) with[static_cast<size_t>(q)].push_back(l);
  }
  for (int q = 0; q < n_ranks; ++q)
    if (!with[static_cast<size_t>(q)].empty())
      d.neighbours.push_back({q, std::move(with[static_cast<size_t>(q)])});
  for (size_t l = 0; l < d.global_node.size(); ++l) {
    const auto rs = ranks_of(static_cast<size_t>(d.global_node[l]));
    if (rs.size() < 2) continue;
    d.shared.push_back(static_cast<int>(l));
    d.sharers.insert(d.sharers.end(), rs.begin(), rs.end());
    d.sharer_first.push_back(static_cast<int>(d.sharers.size()));
  }
  return d;
}

}  // namespace ccm::distributed
