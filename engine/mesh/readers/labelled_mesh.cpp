#include "engine/mesh/readers/labelled_mesh.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "engine/mesh/face_table.hpp"
#include "engine/mesh/gmsh_mesher.hpp"  // MeshError
#include "engine/mesh/mesh_defects.hpp"
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

// Compact numbering of every node, ascending by label; a tet naming an undefined node is refused.
std::unordered_map<long, int> compact_nodes(const LabelledMesh& m,
                                            const std::unordered_map<long, size_t>& all) {
  for (const auto& t : m.tets)
    for (long n : t.nodes)
      if (!all.count(n))
        fail(m, t.at, m.tet_section,
             fmt::format("element {} uses node {}, which is not defined", t.label, n));
  std::vector<long> labels;
  labels.reserve(m.nodes.size());
  for (const auto& n : m.nodes) labels.push_back(n.label);
  std::sort(labels.begin(), labels.end());
  std::unordered_map<long, int> compact;
  compact.reserve(labels.size());
  for (size_t i = 0; i < labels.size(); ++i) compact.emplace(labels[i], static_cast<int>(i));
  return compact;
}

// A node on no tet is refused at its line (after the tets' own checks, which say more).
void refuse_unused_nodes(const LabelledMesh& m, const std::unordered_map<long, size_t>& all) {
  std::vector<char> used_node(m.nodes.size(), 0);
  for (const auto& t : m.tets)
    for (long n : t.nodes) used_node[all.at(n)] = 1;
  std::vector<long> unused;
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (!used_node[i]) unused.push_back(m.nodes[i].label);
  if (unused.empty()) return;
  std::sort(unused.begin(), unused.end());
  fail(m, m.nodes[all.at(unused.front())].at, m.node_section,
       unused_nodes_problem(unused, m.nodes.size()));
}

// The tets on the compact numbering. Zero volume and a mixture of orientations are refused at the
// element's line; a file whose tets are all negative is read in that convention (two nodes of
// each swapped, counted as inverted).
void add_tets(const LabelledMesh& m, const std::unordered_map<long, int>& compact, MeshFile& out) {
  const auto& x = out.mesh.nodes;
  std::vector<double> v6(m.tets.size());
  out.mesh.tets.reserve(m.tets.size());
  for (size_t e = 0; e < m.tets.size(); ++e) {
    const auto& lt = m.tets[e];
    Tet t;
    for (size_t k = 0; k < 4; ++k) t[k] = compact.at(lt.nodes[k]);
    const double edge = std::max(
        {(x[t[1]] - x[t[0]]).norm(), (x[t[2]] - x[t[0]]).norm(), (x[t[3]] - x[t[0]]).norm()});
    v6[e] = six_volume(t, x);
    if (!(std::abs(v6[e]) > 1e-12 * edge * edge * edge))
      fail(
          m, lt.at, m.tet_section,
          fmt::format("element {} has zero volume (its nodes are repeated or coplanar)", lt.label));
    out.mesh.tets.push_back(t);
    out.report.tet_labels.push_back(lt.label);
  }
  if (const auto minority = inverted_minority(v6); !minority.empty()) {
    std::vector<long> labels;
    for (size_t e : minority) labels.push_back(m.tets[e].label);
    fail(m, m.tets[minority.front()].at, m.tet_section,
         inverted_problem(labels, m.tets.size(), "element"));
  }
  int inverted = 0;
  for (size_t e = 0; e < m.tets.size(); ++e) {
    if (v6[e] > 0) continue;
    std::swap(out.mesh.tets[e][2], out.mesh.tets[e][3]);
    if (out.report.inverted_labels.size() < kInvertedLabelsListed)
      out.report.inverted_labels.push_back(m.tets[e].label);
    ++inverted;
  }
  out.report.inverted_tets = inverted;
}

void add_node_sets(const LabelledMesh& m, const std::unordered_map<long, size_t>& all,
                   const std::unordered_map<long, int>& compact, MeshFile& out) {
  for (const auto& [name, set] : m.node_sets) {
    std::vector<int> nodes;
    for (long label : set.labels) {
      if (!all.count(label))
        fail(m, set.at, m.set_section,
             fmt::format("set '{}' names node {}, which is not defined", name, label));
      nodes.push_back(compact.at(label));  // every defined node is on a tet (compact_nodes)
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
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

// The file's parts as regions, when every tet belongs to one.
void add_regions(const LabelledMesh& m, TetMesh& mesh) {
  if (m.region_names.empty()) return;
  for (const auto& t : m.tets)
    if (t.region < 0) return;
  mesh.region_names = m.region_names;
  for (const auto& t : m.tets) mesh.tet_region.push_back(t.region);
}

// Nodes at exactly one position under two labels: the tets on either side do not share them, so
// the body would open along them (an export that duplicated an interface). Refused at the line of
// the later node.
void refuse_coincident_nodes(const LabelledMesh& m, const std::unordered_map<long, size_t>& all,
                             const std::unordered_map<long, int>& compact, const MeshFile& out) {
  const CoincidentNodes c = coincident_nodes(out.mesh);
  if (c.count == 0) return;
  std::vector<long> label(out.mesh.nodes.size());
  for (const auto& [l, i] : compact) label[static_cast<size_t>(i)] = l;
  const long a = label[static_cast<size_t>(c.first)], b = label[static_cast<size_t>(c.second)];
  fail(m, m.nodes[all.at(b)].at, m.node_section,
       coincident_problem(a, b, out.mesh.nodes[static_cast<size_t>(c.first)], c.count));
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
  refuse_unused_nodes(m, all);
  add_regions(m, out.mesh);
  refuse_coincident_nodes(m, all, compact, out);
  add_node_sets(m, all, compact, out);
  add_surfaces(m, compact, out);
  return out;
}

}  // namespace ccm
