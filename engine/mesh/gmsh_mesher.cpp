#include "engine/mesh/gmsh_mesher.hpp"

#include <fmt/format.h>
#include <stdlib.h>  // mkdtemp

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <numbers>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/mesh/child_reader.hpp"
#include "engine/mesh/face_table.hpp"
#include "engine/mesh/gmsh_api.hpp"
#include "engine/mesh/mesh_cache.hpp"
#include "engine/mesh/mesh_defects.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

constexpr int kGmshTet4 = 4;       // Gmsh element type: 4-node tetrahedron
constexpr int kGmshTriangle3 = 2;  // Gmsh element type: 3-node triangle
constexpr double kMaxEstimatedTets = 5e6;
// Delaunay with a uniform size h fills a volume V with about 4.6 V/h^3 tets (measured on boxes,
// cylinders and spheres); 6 leaves some margin.
constexpr double kTetsPerCubedSize = 6.0;

// ---------------------------------------------------------------------------------------------
// Gmsh session and error translation

// Gmsh is one global state per process and not thread-safe.
std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

// One Gmsh session: takes the lock, initializes Gmsh without argv or configuration files, and
// finalizes it again. gmsh::initialize sets LC_NUMERIC to "C" for good; the caller's is restored.
class GmshSession {
 public:
  GmshSession() : lock_(gmsh_mutex()), numeric_locale_(current_numeric_locale()) {
    gmsh::initialize(0, nullptr, false);
    try {
      gmsh::option::setNumber("General.Terminal", 0);  // errors still arrive as exceptions
      gmsh::option::setNumber("General.Verbosity", 1);
      gmsh::option::setNumber("General.NumThreads", 1);
    } catch (...) {
      finalize();
      throw;
    }
  }
  ~GmshSession() { finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  static std::string current_numeric_locale() {
    const char* name = std::setlocale(LC_NUMERIC, nullptr);
    return name ? name : "C";
  }
  void finalize() noexcept {
    try {
      gmsh::finalize();
    } catch (...) {  // nothing useful to do: the next initialize starts afresh
    }
    std::setlocale(LC_NUMERIC, numeric_locale_.c_str());
  }

  std::lock_guard<std::mutex> lock_;
  std::string numeric_locale_;
};

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
}

// Runs body() in a Gmsh session. Gmsh's errors, and any other exception, become a MeshError
// prefixed with `context`. Occurrences of `alias` in Gmsh's messages
// are replaced by `context` (read_msh_file hands Gmsh a link to the file, not its real path).
template <class Body>
auto with_gmsh(const std::string& context, Body&& body, const std::string& alias = {}) {
  try {
    GmshSession session;
    return body();
  } catch (const MeshError&) {
    throw;
  } catch (const gmsh::GmshError& e) {
    std::string message = e.what();
    replace_all(message, alias, context);
    throw MeshError(fmt::format("{}: Gmsh: {}", context, message));
  } catch (const std::exception& e) {
    throw MeshError(fmt::format("{}: {}", context, e.what()));
  }
}

// ---------------------------------------------------------------------------------------------
// Conversion of Gmsh's mesh into a compact TetMesh

// Sorted, unique Gmsh tags; a tag's compact index is its position.
class TagIndex {
 public:
  explicit TagIndex(std::vector<size_t> tags) : tags_(std::move(tags)) {
    std::sort(tags_.begin(), tags_.end());
    tags_.erase(std::unique(tags_.begin(), tags_.end()), tags_.end());
  }
  int find(size_t tag) const {  // -1 if absent
    const auto it = std::lower_bound(tags_.begin(), tags_.end(), tag);
    return it != tags_.end() && *it == tag ? static_cast<int>(it - tags_.begin()) : -1;
  }
  const std::vector<size_t>& tags() const { return tags_; }

 private:
  std::vector<size_t> tags_;
};

std::vector<size_t> sorted_order(const std::vector<size_t>& keys) {
  std::vector<size_t> order(keys.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return keys[a] < keys[b]; });
  return order;
}

// Coordinates of the given node tags, in that order. Refuses a model with nodes on no tet.
std::vector<Vec3> node_coordinates(const std::vector<size_t>& wanted, const std::string& context) {
  std::vector<size_t> tags;
  std::vector<double> xyz, unused_param;
  gmsh::model::mesh::getNodes(tags, xyz, unused_param, -1, -1, false, false);
  const std::vector<size_t> order = sorted_order(tags);
  std::vector<Vec3> nodes;
  nodes.reserve(wanted.size());
  auto it = order.begin();
  for (size_t tag : wanted) {  // both ascending: one merge pass
    it = std::lower_bound(it, order.end(), tag, [&](size_t i, size_t t) { return tags[i] < t; });
    if (it == order.end() || tags[*it] != tag)
      throw MeshError(
          fmt::format("{}: a tet uses node {}, which has no coordinates", context, tag));
    nodes.emplace_back(xyz[3 * *it], xyz[3 * *it + 1], xyz[3 * *it + 2]);
  }
  std::vector<long> unused;
  for (size_t i : order)
    if (!std::binary_search(wanted.begin(), wanted.end(), tags[i]))
      unused.push_back(static_cast<long>(tags[i]));
  unused.erase(std::unique(unused.begin(), unused.end()), unused.end());
  if (!unused.empty())
    throw MeshError(fmt::format("{}: {}", context, unused_nodes_problem(unused, tags.size())));
  return nodes;
}

// A model with volume elements other than linear tets (bricks, wedges, pyramids, quadratic tets)
// is refused: dropping them would lose their mass silently.
void refuse_other_volume_elements(const std::string& context) {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3);
  for (int type : types) {
    if (type == kGmshTet4) continue;
    std::vector<size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(type, tags, nodes);
    std::string name;
    int dim = 0, order = 0, n_nodes = 0, n_primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, n_nodes, local, n_primary);
    throw MeshError(fmt::format(
        "{}: element {} is a {} (Gmsh type {}, {} nodes; {} of them in the file): ccm simulates "
        "linear tetrahedra (type 4) only, and dropping the others would lose their mass",
        context, tags.empty() ? 0 : *std::min_element(tags.begin(), tags.end()), name, type,
        n_nodes, tags.size()));
  }
}

// Zero volume is refused; so is a mixture of orientations (the minority is inverted). A model
// whose tets are all negative is read in that convention: two nodes of each swapped.
void orient_tets(std::vector<Tet>& tets, const std::vector<Vec3>& x,
                 const std::vector<size_t>& gmsh_tags, const std::string& context) {
  std::vector<double> v6(tets.size());
  for (size_t e = 0; e < tets.size(); ++e) {
    const Tet& t = tets[e];
    v6[e] = six_volume(t, x);
    const double edge = std::max(
        {(x[t[1]] - x[t[0]]).norm(), (x[t[2]] - x[t[0]]).norm(), (x[t[3]] - x[t[0]]).norm()});
    if (!(std::abs(v6[e]) > 1e-12 * edge * edge * edge))
      throw MeshError(fmt::format("{}: tetrahedron {} has zero volume", context, gmsh_tags[e]));
  }
  if (const auto minority = inverted_minority(v6); !minority.empty()) {
    std::vector<long> labels;
    for (size_t e : minority) labels.push_back(static_cast<long>(gmsh_tags[e]));
    throw MeshError(
        fmt::format("{}: {}", context, inverted_problem(labels, tets.size(), "tetrahedron")));
  }
  for (size_t e = 0; e < tets.size(); ++e)
    if (v6[e] < 0) std::swap(tets[e][2], tets[e][3]);
}

struct Extracted {
  TetMesh mesh;
  TagIndex node_tags;            // compact node i has Gmsh tag node_tags.tags()[i]
  std::vector<size_t> tet_tags;  // Gmsh tag of mesh.tets[i], ascending
};

// All linear tets of the current model, ordered by Gmsh element tag, on a compact node numbering
// (ascending Gmsh node tag). Refuses other volume elements and nodes on no tet.
Extracted extract_tets(const std::string& context) {
  refuse_other_volume_elements(context);
  std::vector<size_t> elem_tags, elem_nodes;
  gmsh::model::mesh::getElementsByType(kGmshTet4, elem_tags, elem_nodes);
  if (elem_tags.empty())
    throw MeshError(fmt::format("{}: no linear tetrahedra (element type 4) found", context));

  Extracted out{{}, TagIndex(elem_nodes), {}};
  out.mesh.nodes = node_coordinates(out.node_tags.tags(), context);
  out.mesh.tets.reserve(elem_tags.size());
  for (size_t e : sorted_order(elem_tags)) {
    Tet t;
    for (size_t k = 0; k < 4; ++k) t[k] = out.node_tags.find(elem_nodes[4 * e + k]);
    out.mesh.tets.push_back(t);
    out.tet_tags.push_back(elem_tags[e]);
  }
  orient_tets(out.mesh.tets, out.mesh.nodes, out.tet_tags, context);
  return out;
}

// Nodes at one position inside one region (a cut) are refused, naming their Gmsh tags.
void refuse_coincident_nodes(const Extracted& ex, const std::string& context) {
  const CoincidentNodes c = coincident_nodes(ex.mesh);
  if (c.count == 0) return;
  const auto& tags = ex.node_tags.tags();
  throw MeshError(
      fmt::format("{}: {}", context,
                  coincident_problem(static_cast<long>(tags[static_cast<size_t>(c.first)]),
                                     static_cast<long>(tags[static_cast<size_t>(c.second)]),
                                     ex.mesh.nodes[static_cast<size_t>(c.first)], c.count)));
}

// ---------------------------------------------------------------------------------------------
// Named surfaces (physical groups of dimension 2) of a mesh file

struct GmshTriangle {
  size_t tag;
  std::array<size_t, 3> nodes;
};

// The triangles of every named 2D physical group, by name (groups sharing a name are merged),
// each list ordered by element tag and free of duplicates.
std::map<std::string, std::vector<GmshTriangle>> named_gmsh_triangles() {
  std::map<std::string, std::vector<GmshTriangle>> by_name;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto& [dim, group] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, group, name);
    if (name.empty()) continue;
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
    auto& list = by_name[name];
    for (int entity : entities) {
      std::vector<size_t> tags, nodes;
      gmsh::model::mesh::getElementsByType(kGmshTriangle3, tags, nodes, entity);
      for (size_t i = 0; i < tags.size(); ++i)
        list.push_back({tags[i], {nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2]}});
    }
  }
  for (auto& [name, list] : by_name) {
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.tag < b.tag; });
    list.erase(std::unique(list.begin(), list.end(),
                           [](const auto& a, const auto& b) { return a.tag == b.tag; }),
               list.end());
  }
  return by_name;
}

// The triangle on the compact numbering, oriented with its normal away from the tet it bounds.
Triangle outward_triangle(const GmshTriangle& g, const Extracted& ex, const FaceTable& table,
                          const std::string& where) {
  Triangle t;
  for (size_t k = 0; k < 3; ++k) t[k] = ex.node_tags.find(g.nodes[k]);
  const int opposite = t[0] < 0 || t[1] < 0 || t[2] < 0 ? -1 : table.opposite_node(t);
  if (opposite < 0)
    throw MeshError(fmt::format("{}: triangle {} is not a face of any tetrahedron", where, g.tag));
  return oriented_away_from(t, opposite, ex.mesh.nodes);
}

std::map<std::string, std::vector<Triangle>> named_surfaces(const Extracted& ex,
                                                            const std::string& context) {
  const auto gmsh_surfaces = named_gmsh_triangles();
  std::vector<char> on_surface(ex.mesh.nodes.size(), 0);
  for (const auto& [name, list] : gmsh_surfaces)
    for (const GmshTriangle& g : list)
      for (size_t tag : g.nodes)
        if (const int i = ex.node_tags.find(tag); i >= 0) on_surface[i] = 1;
  const FaceTable table(ex.mesh.tets, on_surface);

  std::map<std::string, std::vector<Triangle>> out;
  for (const auto& [name, list] : gmsh_surfaces) {
    const std::string where = fmt::format("{}: surface '{}'", context, name);
    if (list.empty())
      throw MeshError(
          fmt::format("{}: the physical group names no triangle (no face of a "
                      "tetrahedron; quadrangles are not read)",
                      where));
    auto& triangles = out[name];
    for (const GmshTriangle& g : list) triangles.push_back(outward_triangle(g, ex, table, where));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Regions (physical groups of dimension 3)

// The region of every tet of `ex` from the named 3D physical groups; both lists stay empty when
// there is none.
void named_regions(const std::vector<size_t>& tet_tags, TetMesh& mesh, const std::string& context) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 3);
  std::map<std::string, std::vector<int>> entities_by_name;  // groups sharing a name are merged
  for (const auto& [dim, group] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, group, name);
    if (name.empty()) continue;
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
    auto& list = entities_by_name[name];
    list.insert(list.end(), entities.begin(), entities.end());
  }
  if (entities_by_name.empty()) return;
  const TagIndex tets(tet_tags);  // tet_tags[i] is the Gmsh tag of mesh.tets[i], ascending
  mesh.tet_region.assign(mesh.tets.size(), -1);
  for (const auto& [name, entities] : entities_by_name) {
    const int region = static_cast<int>(mesh.region_names.size());
    mesh.region_names.push_back(name);
    for (int entity : entities) {
      std::vector<size_t> tags, nodes;
      gmsh::model::mesh::getElementsByType(kGmshTet4, tags, nodes, entity);
      for (size_t tag : tags) {
        const int i = tets.find(tag);
        if (i < 0) continue;
        int& r = mesh.tet_region[static_cast<size_t>(i)];
        if (r >= 0 && r != region)
          throw MeshError(fmt::format("{}: tetrahedron {} is in regions '{}' and '{}'", context,
                                      tag, mesh.region_names[static_cast<size_t>(r)], name));
        r = region;
      }
    }
  }
  for (size_t i = 0; i < mesh.tet_region.size(); ++i)
    if (mesh.tet_region[i] < 0)
      throw MeshError(
          fmt::format("{}: tetrahedron {} is in no named region", context, tets.tags()[i]));
}

// ---------------------------------------------------------------------------------------------
// Primitives

const char* kind_name(PrimitiveKind kind) {
  switch (kind) {
    case PrimitiveKind::sphere:
      return "sphere";
    case PrimitiveKind::box:
      return "box";
    case PrimitiveKind::cylinder:
      return "cylinder";
    case PrimitiveKind::pipe:
      return "pipe";
  }
  throw MeshError(fmt::format("mesh_primitive: unknown PrimitiveKind {}", static_cast<int>(kind)));
}

void require_positive(const char* kind, const char* field, double value) {
  if (!(std::isfinite(value) && value > 0))
    throw MeshError(fmt::format("mesh_primitive({}): {} must be positive and finite, got {}", kind,
                                field, value));
}

constexpr const char* kSizeNames[3] = {"size.x", "size.y", "size.z"};

// Validates the fields the kind uses and returns the analytic volume.
double validated_volume(const PrimitiveSpec& s) {
  const char* kind = kind_name(s.kind);
  const double pi = std::numbers::pi;
  switch (s.kind) {
    case PrimitiveKind::sphere:
      require_positive(kind, "radius", s.radius);
      return 4.0 / 3.0 * pi * s.radius * s.radius * s.radius;
    case PrimitiveKind::box:
      for (int i = 0; i < 3; ++i) require_positive(kind, kSizeNames[i], s.size[i]);
      return s.size.prod();
    case PrimitiveKind::cylinder:
      require_positive(kind, "radius", s.radius);
      require_positive(kind, "length", s.length);
      return pi * s.radius * s.radius * s.length;
    case PrimitiveKind::pipe:
      require_positive(kind, "radius", s.radius);
      require_positive(kind, "inner_radius", s.inner_radius);
      require_positive(kind, "length", s.length);
      if (!(s.inner_radius < s.radius))
        throw MeshError(
            fmt::format("mesh_primitive(pipe): inner_radius ({}) must be less than radius ({})",
                        s.inner_radius, s.radius));
      return pi * (s.radius * s.radius - s.inner_radius * s.inner_radius) * s.length;
  }
  return 0;  // unreachable: kind_name threw
}

// The smallest radius of curvature of the shape's faces (none for a box). Gmsh cannot mesh a curved
// face with elements wider than its radius: it gives junk, fails or, on a long thin cylinder,
// loops for ever in the 2D mesher (Gmsh 4.8: radius 0.01, length 3, mesh_size 1).
std::pair<const char*, double> smallest_radius(const PrimitiveSpec& s) {
  switch (s.kind) {
    case PrimitiveKind::sphere:
    case PrimitiveKind::cylinder:
      return {"radius", s.radius};
    case PrimitiveKind::pipe:
      return {"inner_radius", s.inner_radius};
    case PrimitiveKind::box:
      break;
  }
  return {nullptr, 0.0};
}

void validate_spec(const PrimitiveSpec& s) {
  const double volume = validated_volume(s);
  const char* kind = kind_name(s.kind);
  require_positive(kind, "mesh_size", s.mesh_size);
  if (const auto [field, radius] = smallest_radius(s); field && s.mesh_size > radius)
    throw MeshError(fmt::format("mesh_primitive({}): mesh_size ({}) must not exceed {} ({})", kind,
                                s.mesh_size, field, radius));
  double estimate = kTetsPerCubedSize * volume / std::pow(s.mesh_size, 3);
  if (s.refinement) {
    const LocalRefinement& r = *s.refinement;
    require_positive(kind, "refinement.radius", r.radius);
    require_positive(kind, "refinement.mesh_size", r.mesh_size);
    if (!r.center.allFinite())
      throw MeshError(fmt::format("mesh_primitive({}): refinement.center must be finite", kind));
    if (r.mesh_size > s.mesh_size)
      throw MeshError(fmt::format(
          "mesh_primitive({}): refinement.mesh_size ({}) must not exceed mesh_size ({})", kind,
          r.mesh_size, s.mesh_size));
    // The ball and its transition shell (radius 2 r) at the fine size, an upper bound.
    const double ball = 4.0 / 3.0 * std::numbers::pi * std::pow(2.0 * r.radius, 3);
    estimate += kTetsPerCubedSize * std::min(ball, volume) / std::pow(r.mesh_size, 3);
  }
  if (estimate > kMaxEstimatedTets)
    throw MeshError(
        fmt::format("mesh_primitive({}): mesh_size {} is too small for this shape: "
                    "about {:.3g} tets estimated, the limit is {:.0g}",
                    kind, s.mesh_size, estimate, kMaxEstimatedTets));
}

void validate_placement(const Placement& p) {
  const double axis = p.rotation_axis.norm();
  if (!p.translation.allFinite())
    throw MeshError("mesh_primitive: placement.translation must be finite");
  if (!std::isfinite(p.rotation_deg))
    throw MeshError("mesh_primitive: placement.rotation_deg must be finite");
  if (!(std::isfinite(axis) && axis > 0))
    throw MeshError("mesh_primitive: placement.rotation_axis must be non-zero and finite");
}

// A pipe is a cylinder minus a coaxial one. The tool overshoots both end caps so the boolean never
// has to deal with coincident faces.
void add_pipe(const PrimitiveSpec& s, double z0) {
  namespace occ = gmsh::model::occ;
  const int outer = occ::addCylinder(0, 0, z0, 0, 0, s.length, s.radius);
  const int inner = occ::addCylinder(0, 0, z0 - s.length, 0, 0, 3 * s.length, s.inner_radius);
  gmsh::vectorpair result;
  std::vector<gmsh::vectorpair> unused_map;
  occ::cut({{3, outer}}, {{3, inner}}, result, unused_map);
  if (result.size() != 1 || result[0].first != 3)
    throw MeshError("mesh_primitive(pipe): the boolean cut did not give exactly one volume");
}

void add_geometry(const PrimitiveSpec& s) {
  namespace occ = gmsh::model::occ;
  const double z0 = s.centered ? -s.length / 2 : 0.0;
  switch (s.kind) {
    case PrimitiveKind::sphere:
      occ::addSphere(0, 0, 0, s.radius);
      break;
    case PrimitiveKind::box: {
      const Vec3 corner = s.centered ? Vec3(-s.size / 2) : Vec3::Zero();
      occ::addBox(corner.x(), corner.y(), corner.z(), s.size.x(), s.size.y(), s.size.z());
      break;
    }
    case PrimitiveKind::cylinder:
      occ::addCylinder(0, 0, z0, 0, 0, s.length, s.radius);
      break;
    case PrimitiveKind::pipe:
      add_pipe(s, z0);
      break;
  }
  occ::synchronize();  // the model (and the mesher) only see OCC entities after this
}

// Gmsh's Ball field: VIn inside the ball, VOut beyond its shell of width Thickness, linear
// between; as the background mesh it replaces the sizes from points and curvature.
void set_refinement(const LocalRefinement& r, double mesh_size) {
  namespace field = gmsh::model::mesh::field;
  const int ball = field::add("Ball");
  field::setNumber(ball, "VIn", r.mesh_size);
  field::setNumber(ball, "VOut", mesh_size);
  field::setNumber(ball, "Radius", r.radius);
  field::setNumber(ball, "Thickness", r.transition > 0.0 ? r.transition : r.radius);
  field::setNumber(ball, "XCenter", r.center.x());
  field::setNumber(ball, "YCenter", r.center.y());
  field::setNumber(ball, "ZCenter", r.center.z());
  field::setAsBackgroundMesh(ball);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

void set_mesh_options(const PrimitiveSpec& spec) {
  const double mesh_size = spec.mesh_size;
  gmsh::option::setNumber("Mesh.MeshSizeMin",
                          spec.refinement ? spec.refinement->mesh_size : mesh_size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", mesh_size);
  if (spec.refinement) set_refinement(*spec.refinement, mesh_size);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay: deterministic (HXT is not)
  gmsh::option::setNumber("Mesh.Optimize", 1);
}

void apply_placement(std::vector<Vec3>& nodes, const Placement& p) {
  const double angle = p.rotation_deg * std::numbers::pi / 180.0;
  const Mat3 rotation = Eigen::AngleAxisd(angle, p.rotation_axis.normalized()).toRotationMatrix();
  for (Vec3& x : nodes) x = rotation * x + p.translation;
}

// ---------------------------------------------------------------------------------------------
// Mesh files

// The file must exist, be readable and start with "$MeshFormat": Gmsh parses any other content as
// a .geo script, which can run shell commands (SystemCall).
void check_msh_file(const fs::path& path, const std::string& where) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw MeshError(fmt::format("{}: no such file", where));
  if (!fs::is_regular_file(path, ec)) throw MeshError(fmt::format("{}: not a file", where));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(fmt::format("{}: cannot be opened for reading", where));
  const std::string magic = "$MeshFormat";
  std::string head(magic.size(), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (head != magic)
    throw MeshError(fmt::format("{}: not a Gmsh MSH file (it must start with $MeshFormat)", where));
}

// The node labels of an ASCII MSH 2 file's $Nodes section (none for another version or a binary
// file). Gmsh keeps no node of an MSH 2 file that no element uses, so they are looked for here.
std::optional<std::vector<long>> msh2_node_labels(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  double version = 0;
  int binary = 0;
  while (std::getline(in, line) && line.rfind("$MeshFormat", 0) != 0) {
  }
  if (!(in >> version >> binary) || version >= 3 || binary != 0) return std::nullopt;
  while (std::getline(in, line) && line.rfind("$Nodes", 0) != 0) {
  }
  long count = 0;
  if (!(in >> count) || count < 0) return std::nullopt;  // Gmsh reports the defect
  std::vector<long> labels;
  for (long k = 0; k < count; ++k) {
    long label = 0;
    double x = 0, y = 0, z = 0;
    if (!(in >> label >> x >> y >> z)) return std::nullopt;
    labels.push_back(label);
  }
  return labels;
}

void refuse_msh2_unused_nodes(const fs::path& path, const Extracted& ex, const std::string& where) {
  const auto labels = msh2_node_labels(path);
  if (!labels) return;
  std::vector<long> unused;
  for (long label : *labels)
    if (label <= 0 || ex.node_tags.find(static_cast<size_t>(label)) < 0) unused.push_back(label);
  std::sort(unused.begin(), unused.end());
  if (!unused.empty())
    throw MeshError(fmt::format("{}: {}", where, unused_nodes_problem(unused, labels->size())));
}

// A private directory holding a symbolic link "mesh.msh" to the file. Gmsh also executes
// "<file>.opt" as a script when one exists next to the file it reads; no such file can exist here.
class PrivateLink {
 public:
  PrivateLink(const fs::path& target, const std::string& where) {
    std::error_code ec;
    std::string pattern = (fs::temp_directory_path(ec) / "ccm-msh-XXXXXX").string();
    if (ec || !mkdtemp(pattern.data()))
      throw MeshError(fmt::format("{}: cannot create a temporary directory", where));
    dir_ = pattern;
    link_ = dir_ / "mesh.msh";
    const fs::path absolute = fs::absolute(target, ec);
    if (!ec) fs::create_symlink(absolute, link_, ec);
    if (ec) {
      const std::string why = ec.message();
      fs::remove_all(dir_, ec);
      throw MeshError(fmt::format("{}: cannot link into {}: {}", where, dir_.string(), why));
    }
  }
  ~PrivateLink() {
    std::error_code ec;
    fs::remove_all(dir_, ec);  // removes the link, never the target
  }
  PrivateLink(const PrivateLink&) = delete;
  PrivateLink& operator=(const PrivateLink&) = delete;
  const fs::path& path() const { return link_; }

 private:
  fs::path dir_, link_;
};

}  // namespace

// Everything a primitive's mesh depends on, exactly (hexadecimal floats): the mesh cache's key.
// The placement is not in it: a mesh is filed before it is placed.
std::string primitive_key(const PrimitiveSpec& s) {
  std::string key = fmt::format(
      "mesh_primitive; gmsh {}; mesher {}; kind {}; radius {:a}; inner_radius {:a}; length {:a}; "
      "size {:a} {:a} {:a}; centered {}; mesh_size {:a}",
      gmsh::api_version(), CCM_MESHER_SOURCE_HASH, kind_name(s.kind), s.radius, s.inner_radius,
      s.length, s.size.x(), s.size.y(), s.size.z(), s.centered, s.mesh_size);
  if (const auto& r = s.refinement)
    key += fmt::format("; refine {:a} {:a} {:a} radius {:a} mesh_size {:a} transition {:a}",
                       r->center.x(), r->center.y(), r->center.z(), r->radius, r->mesh_size,
                       r->transition);
  return key;
}

TetMesh mesh_primitive(const PrimitiveSpec& spec, const Placement& placement) {
  validate_spec(spec);
  validate_placement(placement);
  const std::string context = fmt::format("mesh_primitive({})", kind_name(spec.kind));
  TetMesh mesh = cached_mesh(primitive_key(spec), [&] {
    return with_gmsh(context, [&] {
      add_geometry(spec);
      set_mesh_options(spec);
      gmsh::model::mesh::generate(3);
      return std::move(extract_tets(context).mesh);
    });
  });
  apply_placement(mesh.nodes, placement);
  return mesh;
}

TetMesh read_msh_file(const std::filesystem::path& path) {
  const std::string where = path.string();
  check_msh_file(path, where);
  try {
    gmsh::load();  // here, not in each child: a process reading many files loads Gmsh once
  } catch (const gmsh::GmshError& e) {
    throw MeshError(fmt::format("{}: {}", where, e.what()));
  }
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(path, ec);
  const ChildReadSettings settings{reader_deadline(ec ? 0 : bytes), &gmsh_mutex()};
  return read_in_child(where, settings, [&] {
    const PrivateLink link(path, where);
    return with_gmsh(
        where,
        [&] {
          gmsh::open(link.path().string());
          Extracted ex = extract_tets(where);
          refuse_msh2_unused_nodes(path, ex, where);
          ex.mesh.named_surfaces = named_surfaces(ex, where);
          named_regions(ex.tet_tags, ex.mesh, where);
          refuse_coincident_nodes(ex, where);
          return std::move(ex.mesh);
        },
        link.path().string());
  });
}

TetMesh mesh_gmsh_model(const std::string& context, const std::function<void()>& build) {
  return with_gmsh(context, [&] {
    build();
    Extracted ex = extract_tets(context);
    ex.mesh.named_surfaces = named_surfaces(ex, context);
    named_regions(ex.tet_tags, ex.mesh, context);
    refuse_coincident_nodes(ex, context);
    return std::move(ex.mesh);
  });
}

}  // namespace ccm
