#include "rig_models/geometry/rig_mesher.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/mesh/gmsh_api.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/mesh/mesh_cache.hpp"

namespace ccm::rig {
namespace {

namespace occ = gmsh::model::occ;
using Tags = std::vector<int>;

// The volume tags `boolean` left in `out`.
Tags volumes_of(const gmsh::vectorpair& out) {
  Tags tags;
  for (const auto& [dim, tag] : out)
    if (dim == 3) tags.push_back(tag);
  return tags;
}

// object minus tool (both removed); the volumes left.
Tags cut(int object, int tool) {
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  occ::cut({{3, object}}, {{3, tool}}, out, map);
  return volumes_of(out);
}

// Fragments the parts into one conforming model; returns, per part, the volumes it became.
std::vector<Tags> fragment(const std::vector<Tags>& parts) {
  gmsh::vectorpair all;
  for (const Tags& p : parts)
    for (int tag : p) all.push_back({3, tag});
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  const gmsh::vectorpair object{all.front()};
  const gmsh::vectorpair tools(all.begin() + 1, all.end());
  occ::fragment(object, tools, out, map);
  std::vector<Tags> result;
  size_t k = 0;
  for (const Tags& p : parts) {
    Tags tags;
    for (size_t i = 0; i < p.size(); ++i, ++k) {
      const Tags v = volumes_of(map[k]);
      tags.insert(tags.end(), v.begin(), v.end());
    }
    result.push_back(tags);
  }
  return result;
}

void name_region(const Tags& volumes, const std::string& name) {
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, volumes), name);
}

// A Box size field: `size` inside [lo, hi] (padded by `pad`), `outside` elsewhere.
int box_field(const Vec3& lo, const Vec3& hi, double pad, double size, double outside) {
  const int f = gmsh::model::mesh::field::add("Box");
  gmsh::model::mesh::field::setNumber(f, "VIn", size);
  gmsh::model::mesh::field::setNumber(f, "VOut", outside);
  gmsh::model::mesh::field::setNumber(f, "XMin", lo.x() - pad);
  gmsh::model::mesh::field::setNumber(f, "YMin", lo.y() - pad);
  gmsh::model::mesh::field::setNumber(f, "ZMin", lo.z() - pad);
  gmsh::model::mesh::field::setNumber(f, "XMax", hi.x() + pad);
  gmsh::model::mesh::field::setNumber(f, "YMax", hi.y() + pad);
  gmsh::model::mesh::field::setNumber(f, "ZMax", hi.z() + pad);
  return f;
}

// The background size: the smallest of the fields; `largest` everywhere else.
void use_fields(const std::vector<int>& fields, double largest) {
  const int f = gmsh::model::mesh::field::add("Min");
  std::vector<double> list(fields.begin(), fields.end());
  gmsh::model::mesh::field::setNumbers(f, "FieldsList", list);
  gmsh::model::mesh::field::setAsBackgroundMesh(f);
  gmsh::option::setNumber("Mesh.MeshSizeMax", largest);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
}

// Deterministic Delaunay volumes (HXT is not) on MeshAdapt surfaces, tets of quality below 0.6
// optimised: one sliver sets the stable time step of the whole run. Measured on the rig's parts
// (scale 1): MeshAdapt surfaces and threshold 0.5 raised the smallest h_e / c_d from 1.6e-7 s
// (Frontal-Delaunay, threshold 0.3; a sliver in the rigid rod) to 5.2e-7 s (the pin's bore);
// the geometry as it is now left one sliver in the lower core at 0.5 (4.2e-7 s), gone at 0.6
// (5.2e-7 s, the bore again: 25 % fewer steps per run; 0.7 gives the same).
void generate() {
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::option::setNumber("Mesh.Algorithm", 1);    // MeshAdapt surfaces
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay
  gmsh::option::setNumber("Mesh.Optimize", 1);
  gmsh::option::setNumber("Mesh.OptimizeThreshold", 0.6);
  gmsh::model::mesh::generate(3);
}

void require_scale(double mesh_scale) {
  if (!(mesh_scale > 0.0) || !std::isfinite(mesh_scale))
    throw std::invalid_argument(fmt::format("mesh scale must be > 0 (got {})", mesh_scale));
}

// Gmsh cannot mesh a curved face with elements wider than its radius (it fails or loops, see
// engine/mesh/gmsh_mesher.cpp): a coarsened size stops there.
double curved(double size, double radius) { return std::min(size, radius); }

// On a pipe of wall w, chords of length h sag h^2 / (8 R) inside the curved faces: beyond
// about w / 2 the surface meshes of the two faces come close enough to cross (Gmsh: "PLC Error:
// a segment and a facet intersect"; seen at h = 26 mm, R = 26 mm, w = 3.9 mm). A coarsened size
// stops at h = sqrt(4 R w) (20 mm for the 2 in. pipe).
double wall_limited(double size, double radius, double wall) {
  return std::min(curved(size, radius), std::sqrt(4.0 * radius * wall));
}

// A cylinder along y: base centre (0, y0, z), length `length`, radius r.
int y_cylinder(double y0, double z, double length, double r) {
  return occ::addCylinder(0, y0, z, 0, length, 0, r);
}

// The mesh cache's key of a rig part (engine/mesh/mesh_cache.hpp): every value of the geometry
// file that is a length or a mesh size (more than a part's mesh reads: a key too wide costs a
// miss, one too narrow would serve a wrong mesh), the case values the parts are placed by, the
// part, the scale and `extra`, as exact hexadecimal floats; the Gmsh version and a hash of this
// file and of the Gmsh extraction (rig_models/CMakeLists.txt).
std::string rig_mesh_key(const std::string& part, const RigGeometry& g, const RigParameters& rig,
                         double mesh_scale, const std::string& extra) {
  std::string key = fmt::format("rig {}; gmsh {}; mesher {}; scale {:a}; {}", part,
                                gmsh::api_version(), CCM_RIG_MESHER_SOURCE_HASH, mesh_scale, extra);
  auto add = [&key](const char* name, const SourcedValue& v) {
    key += fmt::format("; {} {:a}", name, v.value);
  };
  // One list, in the key's order: the artifact, the impactor, the mesh sizes.
  for (const auto& [name, v] :
       {std::pair{"envelope_outer_diameter", &g.artifact.envelope_outer_diameter},
        {"envelope_wall", &g.artifact.envelope_wall},
        {"envelope_top", &g.artifact.envelope_top},
        {"envelope_length", &g.artifact.envelope_length},
        {"core_width", &g.artifact.core_width},
        {"core_top", &g.artifact.core_top},
        {"core_bottom", &g.artifact.core_bottom},
        {"core_split", &g.artifact.core_split},
        {"stabilizer_thickness", &g.artifact.stabilizer_thickness},
        {"stabilizer_upper_depth", &g.artifact.stabilizer_upper_depth},
        {"stabilizer_lower_depth", &g.artifact.stabilizer_lower_depth},
        {"pin_diameter", &g.artifact.pin_diameter},
        {"sensor_width", &g.artifact.sensor_width},
        {"sensor_height", &g.artifact.sensor_height},
        {"contact_zone", &g.artifact.contact_zone},
        {"angle_node_depth", &g.artifact.angle_node_depth},
        {"rod_diameter", &g.impactor.rod_diameter},
        {"rod_length", &g.impactor.rod_length},
        {"guide_length", &g.impactor.guide_length},
        {"carriage_width", &g.impactor.carriage_width},
        {"carriage_length", &g.impactor.carriage_length},
        {"carriage_height", &g.impactor.carriage_height},
        {"pearl_inset", &g.impactor.pearl_inset},
        {"mesh.carriage", &g.mesh.carriage},
        {"mesh.rod", &g.mesh.rod},
        {"mesh.spring", &g.mesh.spring},
        {"mesh.envelope", &g.mesh.envelope},
        {"mesh.envelope_contact", &g.mesh.envelope_contact},
        {"mesh.core", &g.mesh.core}})
    add(name, *v);
  add("spring_length", rig.spring_length);
  add("spring_cylinder_diameter", rig.spring_cylinder_diameter);
  add("pivot_to_sensor", rig.pivot_to_sensor);
  return key;
}

}  // namespace

TetMesh mesh_artifact(const RigGeometry& geometry, const RigParameters& rig, double mesh_scale) {
  require_scale(mesh_scale);
  const ArtifactGeometry& a = geometry.artifact;
  const MeshSizes& m = geometry.mesh;
  const std::string key = rig_mesh_key("artifact", geometry, rig, mesh_scale, "");
  return cached_mesh(key, [&] {
    return mesh_gmsh_model("rig artifact", [&] {
      const double Ro = a.envelope_outer_diameter.value / 2, Ri = Ro - a.envelope_wall.value;
      const double zt = a.envelope_top.value, L = a.envelope_length.value;
      const double w = a.core_width.value, t = a.stabilizer_thickness.value;
      const double split = a.core_split.value;
      const int outer = occ::addCylinder(0, 0, zt - L, 0, 0, L, Ro);
      const Tags pipe = cut(outer, occ::addCylinder(0, 0, zt - 2 * L, 0, 0, 3 * L, Ri));
      // The stabilizers are full discs across the bore, the core bar interrupted by them: a disc
      // with a square hole would leave a thin ring that Gmsh's surface meshes cross at coarse
      // sizes.
      auto disc = [&](double depth) { return occ::addCylinder(0, 0, -depth - t / 2, 0, 0, t, Ri); };
      auto disc_tool = [&](double depth) {  // the disc's slab, wide enough to cut the bar through
        return occ::addBox(-w, -w, -depth - t / 2, 2 * w, 2 * w, t);
      };
      const double d_up = a.stabilizer_upper_depth.value, d_low = a.stabilizer_lower_depth.value;
      const int upper = occ::addBox(-w / 2, -w / 2, -split, w, w, split + a.core_top.value);
      const Tags upper_bored =
          cut(upper, occ::addCylinder(-w, 0, 0, 2 * w, 0, 0, a.pin_diameter.value / 2));
      Tags core_upper;
      for (int piece : upper_bored) {
        const Tags cut_pieces = cut(piece, disc_tool(d_up));
        core_upper.insert(core_upper.end(), cut_pieces.begin(), cut_pieces.end());
      }
      const int lower_box =
          occ::addBox(-w / 2, -w / 2, -a.core_bottom.value, w, w, a.core_bottom.value - split);
      const Tags lower = cut(lower_box, disc_tool(d_low));
      const Tags stab_upper{disc(d_up)};
      const Tags stab_lower{disc(d_low)};
      const std::vector<Tags> parts = fragment({pipe, core_upper, lower, stab_upper, stab_lower});
      occ::synchronize();
      name_region(parts[0], "envelope");
      Tags up = parts[1], low = parts[2];
      up.insert(up.end(), parts[3].begin(), parts[3].end());
      low.insert(low.end(), parts[4].begin(), parts[4].end());
      name_region(up, "core_upper");
      name_region(low, "core_lower");
      // Sizes: the core, and the envelope near the contact point (y = -Ro, z = -depth).
      const double zone = a.contact_zone.value / 2, depth = rig.pivot_to_sensor.value;
      const double big = wall_limited(m.envelope.value * mesh_scale, Ri, a.envelope_wall.value);
      const int core =
          box_field(Vec3(-w / 2, -w / 2, -a.core_bottom.value),
                    Vec3(w / 2, w / 2, a.core_top.value), 1e-6, m.core.value * mesh_scale, big);
      const int contact = box_field(Vec3(-zone, -Ro, -depth - zone), Vec3(zone, -Ri, -depth + zone),
                                    1e-6, std::min(m.envelope_contact.value, big), big);
      use_fields({core, contact}, big);
      generate();
    });
  });
}

TetMesh mesh_impactor(const RigGeometry& geometry, const RigParameters& rig, ImpactorKind kind,
                      double tip_y, double mesh_scale) {
  require_scale(mesh_scale);
  const ImpactorGeometry& g = geometry.impactor;
  const MeshSizes& m = geometry.mesh;
  const std::string key =
      rig_mesh_key("impactor", geometry, rig, mesh_scale,
                   fmt::format("kind {}; tip_y {:a}",
                               kind == ImpactorKind::flexible ? "flexible" : "rigid", tip_y));
  return cached_mesh(key, [&] {
    return mesh_gmsh_model("rig impactor", [&] {
      const double zc = -rig.pivot_to_sensor.value;
      const double Ls = rig.spring_length.value, rs = rig.spring_cylinder_diameter.value / 2;
      const double rr = g.rod_diameter.value / 2, lr = g.rod_length.value;
      const bool flexible = kind == ImpactorKind::flexible;
      const double y_front = tip_y - lr - Ls;  // the carriage's front face
      const double W = g.carriage_width.value, C = g.carriage_length.value;
      const double H = g.carriage_height.value;
      const int carriage = occ::addBox(-W / 2, y_front - C, zc - H / 2, W, C, H);
      const int rod =
          flexible ? y_cylinder(tip_y - lr, zc, lr, rr) : y_cylinder(y_front, zc, lr + Ls, rr);
      std::vector<Tags> input{{carriage}, {rod}};
      if (flexible) input.push_back({y_cylinder(y_front, zc, Ls, rs)});
      const std::vector<Tags> parts = fragment(input);
      occ::synchronize();
      name_region(parts[0], "carriage");
      name_region(parts[1], "rod");
      if (flexible) name_region(parts[2], "spring");
      const double big = m.carriage.value * mesh_scale;
      std::vector<int> fields{box_field(Vec3(-rr, y_front, zc - rr), Vec3(rr, tip_y, zc + rr), 1e-6,
                                        curved(m.rod.value, rr), big)};
      if (flexible)
        fields.push_back(box_field(Vec3(-rs, y_front, zc - rs), Vec3(rs, y_front + Ls, zc + rs),
                                   1e-6, curved(m.spring.value * mesh_scale, rs), big));
      use_fields(fields, big);
      generate();
    });
  });
}

TetMesh mesh_spring(const RigGeometry& geometry, const RigParameters& rig, double mesh_scale) {
  require_scale(mesh_scale);
  const std::string key = rig_mesh_key("spring", geometry, rig, mesh_scale, "");
  return cached_mesh(key, [&] {
    return mesh_gmsh_model("rig spring", [&] {
      occ::addCylinder(0, 0, 0, 0, 0, rig.spring_length.value,
                       rig.spring_cylinder_diameter.value / 2);
      occ::synchronize();
      const double size =
          curved(geometry.mesh.spring.value * mesh_scale, rig.spring_cylinder_diameter.value / 2);
      gmsh::option::setNumber("Mesh.MeshSizeMax", size);
      gmsh::option::setNumber("Mesh.MeshSizeMin", size);
      generate();
    });
  });
}

}  // namespace ccm::rig
