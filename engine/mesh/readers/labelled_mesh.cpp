#include "engine/mesh/readers/labelled_mesh.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "engine/mesh/face_table.hpp"
#include "engine/mesh/gmsh_mesher.hpp"  // MeshError
#include "engine/mesh/readers/text_file.hpp"

namespace ccm {
namespace {

constexpr size_t kInvertedLabelsListed = 20;

[[noreturn]] void fail(const LabelledMesh& m, Place at, const std::string& section,
                       std::string_view problem) {
  fail_at(m.files[static_cast<size_t>(at.file)], at.line, section, problem);
}

// File label -> index into LabelledMesh::nodes.
std::unordered_map<long, size_t> node_index(const LabelledMesh& m) {
  std::unordered_map<long, size_t> index;
  index.reserve(m.nodes.size());
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    const auto [it, inserted] = index.emplace(m.nodes[i].label, i);
    if (!inserted)
      fail(m, m.nodes[i].at, m.node_section,
           fmt::format("node {} is defined twice (first at line {})", m.nodes[i].label,
                       m.nodes[it->second].at.line));
  }
  return index;
}

// Compact numbering of the nodes the tets use, ascending by label.
std::unordered_map<long, int> compact_nodes(const LabelledMesh& m,
                                            const std::unordered_map<long, size_t>& all) {
  std::vector<long> used;
  used.reserve(4 * m.tets.size());
  for (const auto& t : m.tets)
    for (long n : t.nodes) {
      if (!all.count(n))
        fail(m, t.at, m.tet_section,
             fmt::format("element {} uses node {}, which is not defined", t.label, n));
      used.push_back(n);
    }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<long, int> compact;
  compact.reserve(used.size());
  for (size_t i = 0; i < used.size(); ++i) compact.emplace(used[i], static_cast<int>(i));
  return compact;
}

void add_tets(const LabelledMesh& m, const std::unordered_map<long, int>& compact, MeshFile& out) {
  int inverted = 0;
  for (const auto& lt : m.tets) {
    Tet t;
    for (size_t k = 0; k < 4; ++k) t[k] = compact.at(lt.nodes[k]);
    const auto& x = out.mesh.nodes;
    const double edge = std::max(
        {(x[t[1]] - x[t[0]]).norm(), (x[t[2]] - x[t[0]]).norm(), (x[t[3]] - x[t[0]]).norm()});
    const double v6 = six_volume(t, x);
    if (!(std::abs(v6) > 1e-12 * edge * edge * edge))
      fail(
          m, lt.at, m.tet_section,
          fmt::format("element {} has zero volume (its nodes are repeated or coplanar)", lt.label));
    if (v6 < 0) {
      std::swap(t[2], t[3]);
      if (out.report.inverted_labels.size() < kInvertedLabelsListed)
        out.report.inverted_labels.push_back(lt.label);
      ++inverted;
    }
    out.mesh.tets.push_back(t);
    out.report.tet_labels.push_back(lt.label);
  }
  out.report.inverted_tets = inverted;
}

void add_node_sets(const LabelledMesh& m, const std::unordered_map<long, size_t>& all,
                   const std::unordered_map<long, int>& compact, MeshFile& out) {
  for (const auto& [name, set] : m.node_sets) {
    std::vector<int> nodes;
    int off_mesh = 0;
    for (long label : set.labels) {
      if (!all.count(label))
        fail(m, set.at, m.set_section,
             fmt::format("set '{}' names node {}, which is not defined", name, label));
      const auto it = compact.find(label);
      if (it == compact.end())
        ++off_mesh;
      else
        nodes.push_back(it->second);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    if (off_mesh > 0)
      out.report.notes.push_back(
          fmt::format("node set '{}': {} of its nodes belong to no tetrahedron and are left out",
                      name, off_mesh));
    out.mesh.named_node_sets[name] = std::move(nodes);
  }
}

// Index of every tet by label (for faces that name their tet).
std::unordered_map<long, int> tet_index(const LabelledMesh& m) {
  std::unordered_map<long, int> index;
  for (size_t i = 0; i < m.tets.size(); ++i) index.emplace(m.tets[i].label, static_cast<int>(i));
  return index;
}

void add_surfaces(const LabelledMesh& m, const std::unordered_map<long, int>& compact,
                  MeshFile& out) {
  if (m.surfaces.empty()) return;
  const auto tets = tet_index(m);
  std::vector<char> on_surface(out.mesh.nodes.size(), 0);
  for (const auto& [name, faces] : m.surfaces)
    for (const auto& f : faces)
      for (long n : f.nodes)
        if (const auto it = compact.find(n); it != compact.end()) on_surface[it->second] = 1;
  const FaceTable table(out.mesh.tets, on_surface);
  for (const auto& [name, faces] : m.surfaces) {
    auto& triangles = out.mesh.named_surfaces[name];
    for (const auto& f : faces) {
      Triangle t;
      int opposite = -1;
      for (size_t k = 0; k < 3; ++k) {
        const auto it = compact.find(f.nodes[k]);
        t[k] = it == compact.end() ? -1 : it->second;
      }
      if (t[0] >= 0 && t[1] >= 0 && t[2] >= 0) {
        if (f.owner == 0) {
          opposite = table.opposite_node(t);
        } else if (const auto it = tets.find(f.owner); it != tets.end()) {
          for (int n : out.mesh.tets[static_cast<size_t>(it->second)])
            if (n != t[0] && n != t[1] && n != t[2]) opposite = n;
        }
      }
      if (opposite < 0)
        fail(m, f.at, m.surface_section,
             fmt::format("surface '{}': the triangle of nodes {} {} {} is not a face of any "
                         "tetrahedron",
                         name, f.nodes[0], f.nodes[1], f.nodes[2]));
      triangles.push_back(oriented_away_from(t, opposite, out.mesh.nodes));
    }
  }
}

// Nodes at exactly the same position under different labels: the tets on either side do not share
// them, so the mesh is cut there (an export that duplicated an interface). Reported, not refused:
// a cut may be meant (two parts that touch).
void note_coincident_nodes(const std::unordered_map<long, int>& compact, MeshFile& out) {
  const std::vector<Vec3>& x = out.mesh.nodes;
  std::vector<long> label(x.size());
  for (const auto& [l, i] : compact) label[static_cast<size_t>(i)] = l;
  std::vector<int> order(x.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const auto at = [&](int i) {
    const Vec3& p = x[static_cast<size_t>(i)];
    return std::array<double, 3>{p.x(), p.y(), p.z()};
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return at(a) < at(b); });
  int shared = 0;
  std::pair<int, int> first{-1, -1};
  for (size_t k = 1; k < order.size(); ++k)
    if (at(order[k]) == at(order[k - 1])) {
      if (shared == 0) first = {order[k - 1], order[k]};
      ++shared;
    }
  if (shared == 0) return;
  const Vec3& p = x[static_cast<size_t>(first.first)];
  out.report.notes.push_back(fmt::format(
      "{} node(s) share their position with another node (the first: nodes {} and {} at ({:g}, "
      "{:g}, {:g})): the tets on either side are not connected there",
      shared, label[static_cast<size_t>(first.first)], label[static_cast<size_t>(first.second)],
      p.x(), p.y(), p.z()));
}

}  // namespace

MeshFile assemble(LabelledMesh&& m) {
  if (m.tets.empty())
    throw MeshError(fmt::format("{}: holds no linear tetrahedra", m.files.front()));
  MeshFile out;
  out.report = std::move(m.report);
  out.report.file_nodes = static_cast<int>(m.nodes.size());
  const auto all = node_index(m);
  const auto compact = compact_nodes(m, all);
  out.mesh.nodes.resize(compact.size());
  for (const auto& [label, i] : compact)
    out.mesh.nodes[static_cast<size_t>(i)] = m.length_scale * m.nodes[all.at(label)].x;
  add_tets(m, compact, out);
  note_coincident_nodes(compact, out);
  add_node_sets(m, all, compact, out);
  add_surfaces(m, compact, out);
  return out;
}

}  // namespace ccm
