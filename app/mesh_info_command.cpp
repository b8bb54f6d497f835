#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "app/mesh_commands.hpp"
#include "app/run_command.hpp"  // exit codes
#include "engine/element/mesh_quality.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/mesh/model_mesh.hpp"
#include "engine/mesh/readers/mesh_file.hpp"

namespace ccm {
namespace {

// The file label of tet i (1-based position when the format has no labels).
long tet_label(const MeshFileReport& r, int i) {
  return r.tet_labels.empty() ? i + 1 : r.tet_labels[static_cast<size_t>(i)];
}

int n_nodes_of(const std::vector<Triangle>& triangles) {
  return static_cast<int>(nodes_of(triangles).size());
}

nlohmann::json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json info_json(const std::filesystem::path& file, const MeshFile& m,
                         const MeshQuality& q) {
  const MeshFileReport& r = m.report;
  nlohmann::json surfaces = nlohmann::json::object(), node_sets = nlohmann::json::object();
  for (const auto& [name, tris] : m.mesh.named_surfaces)
    surfaces[name] = {{"triangles", tris.size()}, {"nodes", n_nodes_of(tris)}};
  for (const auto& [name, nodes] : m.mesh.named_node_sets) node_sets[name] = nodes.size();
  nlohmann::json out = {
      {"file", file.string()},
      {"format", r.format},
      {"nodes", m.mesh.n_nodes()},
      {"file_nodes", r.file_nodes ? nlohmann::json(*r.file_nodes) : nlohmann::json()},
      {"tets", m.mesh.n_elements()},
      {"inverted_tets", r.inverted_tets ? nlohmann::json(*r.inverted_tets) : nlohmann::json()},
      {"inverted_tet_labels", r.inverted_labels},
      {"volume", q.volume},
      {"bounding_box", {{"min", vec_json(q.box_min)}, {"max", vec_json(q.box_max)}}},
      {"dihedral_angle_deg",
       {{"min", q.min_dihedral_deg},
        {"min_tet", tet_label(r, q.min_dihedral_tet)},
        {"max", q.max_dihedral_deg},
        {"max_tet", tet_label(r, q.max_dihedral_tet)}}},
      {"smallest_h_e", {{"value", q.min_h}, {"tet", tet_label(r, q.min_h_tet)}}},
      {"surfaces", surfaces},
      {"node_sets", node_sets},
      {"regions", m.mesh.region_names},
      {"ignored_elements", r.ignored},
      {"notes", r.notes}};
  return out;
}

void print_text(const std::filesystem::path& file, const MeshFile& m, const MeshQuality& q) {
  const MeshFileReport& r = m.report;
  fmt::print("{}\n", file.string());
  fmt::print("  format          {}\n", r.format);
  fmt::print("  nodes           {}", m.mesh.n_nodes());
  if (r.file_nodes && *r.file_nodes != m.mesh.n_nodes())
    fmt::print(" on tets ({} in the file)", *r.file_nodes);
  fmt::print("\n  tets            {}\n", m.mesh.n_elements());
  if (r.inverted_tets)
    fmt::print("  inverted tets   {}{}\n", *r.inverted_tets,
               *r.inverted_tets > 0
                   ? fmt::format(" (negative volume as given, read with two nodes swapped; "
                                 "labels {})",
                                 fmt::join(r.inverted_labels, ", "))
                   : "");
  fmt::print("  volume          {:.6g}\n", q.volume);
  fmt::print("  bounding box    x [{:.6g}, {:.6g}]  y [{:.6g}, {:.6g}]  z [{:.6g}, {:.6g}]\n",
             q.box_min.x(), q.box_max.x(), q.box_min.y(), q.box_max.y(), q.box_min.z(),
             q.box_max.z());
  fmt::print("  dihedral angle  min {:.4g} deg (tet {}), max {:.4g} deg (tet {})\n",
             q.min_dihedral_deg, tet_label(r, q.min_dihedral_tet), q.max_dihedral_deg,
             tet_label(r, q.max_dihedral_tet));
  fmt::print("  smallest h_e    {:.6g} (tet {}; stable step = h_e / wave speed)\n", q.min_h,
             tet_label(r, q.min_h_tet));
  for (const auto& [name, tris] : m.mesh.named_surfaces)
    fmt::print("  surface         {}: {} triangles, {} nodes\n", name, tris.size(),
               n_nodes_of(tris));
  for (const auto& [name, nodes] : m.mesh.named_node_sets)
    fmt::print("  node set        {}: {} nodes\n", name, nodes.size());
  for (const auto& name : m.mesh.region_names) fmt::print("  region          {}\n", name);
  for (const auto& [kind, count] : r.ignored)
    fmt::print("  ignored         {} x {}\n", count, kind);
  for (const auto& note : r.notes) fmt::print("  note            {}\n", note);
}

}  // namespace

int mesh_info_command(const MeshInfoArgs& args) {
  try {
    const MeshFile m = read_mesh_file_with_report(args.file);
    const MeshQuality q = mesh_quality(m.mesh);
    if (args.json)
      fmt::print("{}\n", info_json(args.file, m, q).dump(2));
    else
      print_text(args.file, m, q);
    return exit_code::completed;
  } catch (const MeshError& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::internal_error;
  }
}

}  // namespace ccm
