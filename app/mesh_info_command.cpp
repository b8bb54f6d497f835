#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "app/mesh_commands.hpp"
#include "app/run_command.hpp"  // exit codes
#include "engine/element/mesh_quality.hpp"
#include "engine/material/material.hpp"
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

// The dilatational wave speed of --material, or none. Throws std::invalid_argument naming the
// option for an invalid material.
std::optional<double> wave_speed_of(const std::vector<double>& material) {
  if (material.empty()) return std::nullopt;
  const MaterialParams m{MaterialModel::neo_hookean, material[0], material[1], material[2]};
  if (const std::string problem = validate(m); !problem.empty())
    throw std::invalid_argument(fmt::format("--material E,NU,RHO: {}", problem));
  return dilatational_wave_speed(m);
}

// A nearly degenerate tet: h_e below kSliverFraction of the median's.
std::vector<std::string> sliver_notes(const MeshFileReport& r, const MeshQuality& q) {
  std::vector<std::string> notes;
  for (const TetQuality& t : q.worst)
    if (t.h < kSliverFraction * q.median_h)
      notes.push_back(fmt::format(
          "tet {} is nearly degenerate (h_e {:.4g}, {:.3g} of the median; dihedral angles {:.3g} "
          "to {:.4g} deg): the stable step of the whole body is {:.3g} times shorter than the "
          "median tet allows; remesh there",
          tet_label(r, t.tet), t.h, t.h / q.median_h, t.min_dihedral_deg, t.max_dihedral_deg,
          q.median_h / t.h));
  return notes;
}

std::vector<std::string> notes_of(const MeshFileReport& r, const MeshQuality& q) {
  std::vector<std::string> notes = r.notes;
  for (std::string& n : sliver_notes(r, q)) notes.push_back(std::move(n));
  return notes;
}

nlohmann::json worst_json(const MeshFileReport& r, const MeshQuality& q,
                          std::optional<double> c_d) {
  nlohmann::json out = nlohmann::json::array();
  for (const TetQuality& t : q.worst) {
    nlohmann::json j = {
        {"tet", tet_label(r, t.tet)},
        {"h_e", t.h},
        {"fraction_of_median", t.h / q.median_h},
        {"dihedral_angle_deg", {{"min", t.min_dihedral_deg}, {"max", t.max_dihedral_deg}}}};
    if (c_d) j["stable_step_s"] = t.h / *c_d;
    out.push_back(j);
  }
  return out;
}

nlohmann::json info_json(const std::filesystem::path& file, const MeshFile& m, const MeshQuality& q,
                         std::optional<double> c_d) {
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
      {"median_h_e", q.median_h},
      {"worst_tets", worst_json(r, q, c_d)},
      {"wave_speed_mps", c_d ? nlohmann::json(*c_d) : nlohmann::json()},
      {"median_stable_step_s", c_d ? nlohmann::json(q.median_h / *c_d) : nlohmann::json()},
      {"surfaces", surfaces},
      {"node_sets", node_sets},
      {"regions", m.mesh.region_names},
      {"ignored_elements", r.ignored},
      {"notes", notes_of(r, q)}};
  return out;
}

void print_text(const std::filesystem::path& file, const MeshFile& m, const MeshQuality& q,
                std::optional<double> c_d) {
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
  fmt::print("  median h_e      {:.6g}\n", q.median_h);
  for (size_t k = 0; k < q.worst.size(); ++k) {
    const TetQuality& t = q.worst[k];
    fmt::print("  {}tet {}: h_e {:.4g} ({:.3g} of the median), dihedral {:.4g} to {:.4g} deg{}\n",
               k == 0 ? "worst tets      " : "                ", tet_label(r, t.tet), t.h,
               t.h / q.median_h, t.min_dihedral_deg, t.max_dihedral_deg,
               c_d ? fmt::format(", stable step {:.4g} s", t.h / *c_d) : "");
  }
  if (c_d)
    fmt::print("  stable step     {:.4g} s (c_d {:.6g} m/s; the median tet's {:.4g} s)\n",
               q.min_h / *c_d, *c_d, q.median_h / *c_d);
  for (const auto& [name, tris] : m.mesh.named_surfaces)
    fmt::print("  surface         {}: {} triangles, {} nodes\n", name, tris.size(),
               n_nodes_of(tris));
  for (const auto& [name, nodes] : m.mesh.named_node_sets)
    fmt::print("  node set        {}: {} nodes\n", name, nodes.size());
  for (const auto& name : m.mesh.region_names) fmt::print("  region          {}\n", name);
  for (const auto& [kind, count] : r.ignored)
    fmt::print("  ignored         {} x {}\n", count, kind);
  for (const auto& note : notes_of(r, q)) fmt::print("  note            {}\n", note);
}

}  // namespace

int mesh_info_command(const MeshInfoArgs& args) {
  try {
    const std::optional<double> c_d = wave_speed_of(args.material);
    const MeshFile m = read_mesh_file_with_report(args.file);
    const MeshQuality q = mesh_quality(m.mesh);
    if (args.json)
      fmt::print("{}\n", info_json(args.file, m, q, c_d).dump(2));
    else
      print_text(args.file, m, q, c_d);
    return exit_code::completed;
  } catch (const std::invalid_argument& e) {  // --material
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  } catch (const MeshError& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::internal_error;
  }
}

}  // namespace ccm
