#include "rig_models/geometry/rig_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "engine/mesh/boundary_surface.hpp"
#include "engine/solver/lumped_mass.hpp"
#include "rig_models/geometry/geometry_file.hpp"
#include "rig_models/geometry/mass_properties.hpp"
#include "rig_models/geometry/part_assembly.hpp"
#include "rig_models/geometry/rig_mesher.hpp"

namespace ccm::rig {
namespace {

// Where the parts are, from the geometry and the case file (frame of rig_geometry.hpp).
struct Layout {
  double Ro, Ri;        // envelope radii
  double zc;            // height of the track axis and of the sensor centre
  double tip_y;         // the rod's tip at t = 0
  double y_front;       // the carriage's front face
  double rod_back;      // where the rod starts (flexible: the spring's front)
  double joint_radius;  // radius of the rod (rigid) or spring (flexible) on the front face
};

Layout layout_of(const RigGeometry& g, const RigParameters& rig, const RigModelRequest& req) {
  Layout l;
  l.Ro = g.artifact.envelope_outer_diameter.value / 2;
  l.Ri = l.Ro - g.artifact.envelope_wall.value;
  l.zc = -rig.pivot_to_sensor.value;
  l.tip_y = -l.Ro - req.gap;
  l.y_front = l.tip_y - g.impactor.rod_length.value - rig.spring_length.value;
  const bool flexible = req.impactor == ImpactorKind::flexible;
  l.rod_back = flexible ? l.tip_y - g.impactor.rod_length.value : l.y_front;
  l.joint_radius =
      flexible ? rig.spring_cylinder_diameter.value / 2 : g.impactor.rod_diameter.value / 2;
  return l;
}

MaterialParams material(const PartMaterial& m, double rho, MaterialModel model) {
  return {model, m.E ? m.E->value : 0.0, m.nu->value, rho};
}

int region_index(const TetMesh& mesh, const std::string& name) {
  const auto it = std::find(mesh.region_names.begin(), mesh.region_names.end(), name);
  if (it == mesh.region_names.end())
    throw std::logic_error(fmt::format("rig mesh has no region '{}'", name));
  return static_cast<int>(it - mesh.region_names.begin());
}

double spring_length_of(const RigParameters& rig) { return rig.spring_length.value; }

// Impactor materials: rod as given, spring from eq. 3.1, carriage tuned to the impactor mass.
std::map<std::string, MaterialParams> impactor_materials(const RigGeometry& g,
                                                         const RigParameters& rig,
                                                         const TetMesh& mesh, double stiffness,
                                                         std::vector<RigPart>& parts,
                                                         RigModel& out) {
  const std::vector<UnitMass> unit = unit_mass_properties(mesh, Vec3::Zero(), Vec3::UnitX());
  const RigMaterials& m = g.materials;
  std::map<std::string, MaterialParams> mats;
  const UnitMass& rod = unit[static_cast<size_t>(region_index(mesh, "rod"))];
  mats["rod"] = material(m.rod, m.rod.rho->value, MaterialModel::neo_hookean);
  parts.push_back({"rod", mats["rod"], m.rod.rho->value * rod.volume, m.rod.rho->source, 0});
  double fixed_mass = parts.back().mass;
  if (std::count(mesh.region_names.begin(), mesh.region_names.end(), "spring")) {
    const UnitMass& spring = unit[static_cast<size_t>(region_index(mesh, "spring"))];
    out.spring_area = spring.volume / spring_length_of(rig);
    out.spring_modulus = spring_modulus_for(stiffness, spring_length_of(rig), spring.volume);
    const double rho = g.impactor.spring_mass.value / spring.volume;
    // Linear: a coil spring's force is linear in its compression up to coil bind; the
    // small-strain law gives exactly that for the uniaxial compression it sees (nu = 0).
    mats["spring"] = {MaterialModel::linear_elastic, out.spring_modulus, m.spring.nu->value, rho};
    parts.push_back({"spring", mats["spring"], g.impactor.spring_mass.value,
                     "impactor.spring_mass over the meshed volume; E from eq. 3.1", 0});
    fixed_mass += parts.back().mass;
  }
  const UnitMass& carriage = unit[static_cast<size_t>(region_index(mesh, "carriage"))];
  const double rho_c = (rig.impactor_mass.value - fixed_mass) / carriage.volume;
  if (!(rho_c > 0.0))
    throw std::invalid_argument(fmt::format(
        "density tuning: the rod and spring ({:.4g} kg) outweigh cases.toml impactor_mass "
        "({:.4g} kg)",
        fixed_mass, rig.impactor_mass.value));
  mats["carriage"] = material(m.carriage, rho_c, MaterialModel::neo_hookean);
  parts.push_back({"carriage", mats["carriage"], rho_c * carriage.volume,
                   "tuned: cases.toml impactor_mass", 0});
  return mats;
}

// Artifact materials: envelope as given, the two core parts tuned to mass and J about the pin.
std::map<std::string, MaterialParams> artifact_materials(const RigGeometry& g,
                                                         const RigParameters& rig,
                                                         const TetMesh& mesh,
                                                         std::vector<RigPart>& parts) {
  const std::vector<UnitMass> unit = unit_mass_properties(mesh, Vec3::Zero(), Vec3::UnitX());
  const RigMaterials& m = g.materials;
  const UnitMass& env = unit[static_cast<size_t>(region_index(mesh, "envelope"))];
  const UnitMass& up = unit[static_cast<size_t>(region_index(mesh, "core_upper"))];
  const UnitMass& low = unit[static_cast<size_t>(region_index(mesh, "core_lower"))];
  const double rho_e = m.envelope.rho->value;
  const DensityPair d =
      densities_for(up, low, rig.artifact_mass.value, rig.artifact_inertia_pivot.value,
                    rho_e * env.volume, rho_e * env.inertia);
  std::map<std::string, MaterialParams> mats;
  mats["envelope"] = material(m.envelope, rho_e, MaterialModel::neo_hookean);
  mats["core_upper"] = material(m.core, d.rho_a, MaterialModel::neo_hookean);
  mats["core_lower"] = material(m.core, d.rho_b, MaterialModel::neo_hookean);
  parts.push_back({"envelope", mats["envelope"], rho_e * env.volume, m.envelope.rho->source, 0});
  const std::string tuned = "tuned: cases.toml artifact_mass and artifact_inertia_pivot";
  parts.push_back({"core_upper", mats["core_upper"], d.rho_a * up.volume, tuned, 0});
  parts.push_back({"core_lower", mats["core_lower"], d.rho_b * low.volume, tuned, 0});
  return mats;
}

Vec3 centroid(const Triangle& t, const std::vector<Vec3>& X) {
  return (X[t[0]] + X[t[1]] + X[t[2]]) / 3.0;
}

const Body& body_named(const ModelMesh& mesh, const std::string& name) {
  return mesh.bodies[static_cast<size_t>(mesh.body_index(name))];
}

void name_surface(ModelMesh& mesh, const std::string& body, const std::string& surface,
                  std::vector<Triangle> triangles) {
  if (triangles.empty())
    throw std::logic_error(fmt::format("rig model: surface {}/{} is empty", body, surface));
  const std::string name = body + "/" + surface;
  mesh.node_sets[name] = nodes_of(triangles);
  mesh.surfaces[name] = {mesh.body_index(body), std::move(triangles)};
}

int nearest(const std::vector<int>& nodes, const std::vector<Vec3>& X, const Vec3& p) {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int n : nodes)
    if (const double d = (X[static_cast<size_t>(n)] - p).squaredNorm(); d < best_d) {
      best_d = d;
      best = n;
    }
  return best;
}

std::vector<int> sorted_union(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

// Contact surfaces, the sensor patch and the drive surface (named by geometry).
void name_surfaces(const RigGeometry& g, const Layout& l, RigModel& r) {
  ModelMesh& mesh = r.model.mesh;
  const std::vector<Vec3>& X = mesh.X;
  const ArtifactGeometry& a = g.artifact;
  const double zone = a.contact_zone.value / 2, tol = 1e-9;
  std::vector<Triangle> zone_tris, sensor;
  for (const Triangle& t : body_named(mesh, "envelope").boundary) {
    const Vec3 c = centroid(t, X);
    if (std::hypot(c.x(), c.y()) < 0.5 * (l.Ro + l.Ri) || c.y() >= 0.0)
      continue;  // outer, struck side
    if (std::abs(c.x()) <= zone && std::abs(c.z() - l.zc) <= zone) zone_tris.push_back(t);
    const double arc = l.Ro * std::atan2(c.x(), -c.y());
    if (std::abs(arc) <= a.sensor_width.value / 2 &&
        std::abs(c.z() - l.zc) <= a.sensor_height.value / 2)
      sensor.push_back(t);
  }
  // The rod's tip face and its side within one radius of the tip.
  const double rr = g.impactor.rod_diameter.value / 2;
  std::vector<Triangle> tip;
  for (const Triangle& t : body_named(mesh, "rod").boundary) {
    bool near_tip = true, on_face = true;
    for (int n : t) {
      near_tip = near_tip && X[static_cast<size_t>(n)].y() >= l.tip_y - rr - tol;
      on_face = on_face && std::abs(X[static_cast<size_t>(n)].y() - l.tip_y) <= tol;
    }
    if (near_tip) tip.push_back(t);
    if (on_face) r.tip_face.push_back(t);
  }
  for (const Triangle& t : sensor) {
    const Vec3 c = centroid(t, X);
    if (std::hypot(c.x(), c.z() - l.zc) <= rr) r.mat_footprint.push_back(t);
  }
  std::vector<Triangle> drive;
  for (const Triangle& t : body_named(mesh, "carriage").boundary) {
    bool on_front = true;
    for (int n : t)
      on_front = on_front && std::abs(X[static_cast<size_t>(n)].y() - l.y_front) < tol;
    const Vec3 c = centroid(t, X);
    if (on_front && std::hypot(c.x(), c.z() - l.zc) > l.joint_radius + tol) drive.push_back(t);
  }
  for (const Triangle& t : sensor) r.sensor_mesh_area += triangle_area(t, X);
  r.sensor_nodes = nodes_of(sensor);
  name_surface(mesh, "envelope", "sensor", std::move(sensor));
  name_surface(mesh, "envelope", "contact_zone", std::move(zone_tris));
  name_surface(mesh, "rod", "tip", std::move(tip));
  r.drive_surface = drive;
  name_surface(mesh, "carriage", "drive", std::move(drive));
  r.contact_surfaces = {"rod/tip", "envelope/contact_zone"};
}

// The pin's bore, the track guide and the tracked nodes.
void name_nodes(const RigGeometry& g, const RigParameters& rig, const Layout& l,
                const std::map<std::string, std::vector<int>>& parts, RigModel& r) {
  const std::vector<Vec3>& X = r.model.mesh.X;
  const ImpactorGeometry& ig = g.impactor;
  const double r_pin = g.artifact.pin_diameter.value / 2;
  for (int n : parts.at("core_upper")) {
    const Vec3& x = X[static_cast<size_t>(n)];
    if (std::abs(std::hypot(x.y(), x.z()) - r_pin) < 1e-6 * r_pin) r.pin_nodes.push_back(n);
  }
  const double half_h = ig.carriage_height.value / 2, tol = 1e-9;
  for (int n : parts.at("carriage"))
    if (std::abs(std::abs(X[static_cast<size_t>(n)].z() - l.zc) - half_h) < tol)
      r.guide_nodes.push_back(n);
  if (r.impactor == ImpactorKind::flexible) {
    const double rr = ig.rod_diameter.value / 2;
    for (int n : parts.at("rod")) {
      const Vec3& x = X[static_cast<size_t>(n)];
      if (x.y() <= l.rod_back + ig.guide_length.value + tol &&
          std::abs(std::hypot(x.x(), x.z() - l.zc) - rr) < 1e-6 * rr)
        r.guide_nodes.push_back(n);
    }
  }
  std::sort(r.guide_nodes.begin(), r.guide_nodes.end());
  r.guide_nodes.erase(std::unique(r.guide_nodes.begin(), r.guide_nodes.end()), r.guide_nodes.end());
  const double top = l.zc + half_h, inset = ig.pearl_inset.value;
  r.pearl_front = nearest(parts.at("carriage"), X, Vec3(0.0, l.y_front - inset, top));
  r.pearl_back = nearest(parts.at("carriage"), X,
                         Vec3(0.0, l.y_front - ig.carriage_length.value + inset, top));
  r.angle_node =
      nearest(parts.at("core_lower"), X, Vec3(0.0, 0.0, -g.artifact.angle_node_depth.value));
  (void)rig;
}

// Mass, inertia about the pin and centre of mass of the artifact, from the integrator's masses.
void measure_masses(RigModel& r) {
  const std::vector<double> m = lumped_mass(r.model.mesh, r.model.elements);
  const std::vector<Vec3>& X = r.model.mesh.X;
  double cm_z = 0.0;
  for (int n : r.impactor_nodes) r.impactor_mass += m[static_cast<size_t>(n)];
  for (int n : r.artifact_nodes) {
    const Vec3& x = X[static_cast<size_t>(n)];
    const double mn = m[static_cast<size_t>(n)];
    r.artifact_mass += mn;
    r.artifact_inertia += mn * (x.y() * x.y() + x.z() * x.z());
    cm_z += mn * x.z();
  }
  r.artifact_cm_depth = -cm_z / r.artifact_mass;
  for (RigPart& p : r.parts) p.elements = body_named(r.model.mesh, p.name).n_elements;
}

}  // namespace

double spring_modulus_for(double stiffness, double length, double meshed_volume) {
  const double area = meshed_volume / length;
  return stiffness * length / area;  // (3.1)
}

RigModel build_rig_model(const RigGeometry& geometry, const RigParameters& rig,
                         const RigModelRequest& request) {
  check_against_cases(geometry, rig);
  if (!(request.gap > 0.0) || !std::isfinite(request.gap))
    throw std::invalid_argument(
        fmt::format("rig model: the gap must be > 0 (got {} m)", request.gap));
  const Layout l = layout_of(geometry, rig, request);
  RigModel r;
  r.impactor = request.impactor;
  r.artifact = request.artifact;
  r.rod_tip_y = l.tip_y;
  r.spring_stiffness = request.spring_stiffness.value_or(rig.spring_stiffness.value);
  const TetMesh impactor =
      mesh_impactor(geometry, rig, request.impactor, l.tip_y, request.mesh_scale);
  const TetMesh artifact = mesh_artifact(geometry, rig, request.mesh_scale);
  ModelMesh mesh;
  const auto imp = add_parts(
      mesh, impactor, impactor_materials(geometry, rig, impactor, r.spring_stiffness, r.parts, r));
  const auto art = add_parts(mesh, artifact, artifact_materials(geometry, rig, artifact, r.parts));
  for (const auto& [name, nodes] : imp.nodes_of)
    r.impactor_nodes = sorted_union(r.impactor_nodes, nodes);
  for (const auto& [name, nodes] : art.nodes_of)
    r.artifact_nodes = sorted_union(r.artifact_nodes, nodes);
  r.model.mesh = std::move(mesh);
  name_surfaces(geometry, l, r);
  std::map<std::string, std::vector<int>> part_nodes = imp.nodes_of;
  part_nodes.insert(art.nodes_of.begin(), art.nodes_of.end());
  name_nodes(geometry, rig, l, part_nodes, r);
  r.model.mesh.node_sets[kPinBoreSet] = r.pin_nodes;
  r.model.mesh.node_sets[kGuideSet] = r.guide_nodes;
  r.model.mesh.node_sets[kImpactorSet] = r.impactor_nodes;
  r.model = make_model(std::move(r.model.mesh));
  r.model.bcs.gravity = Vec3(0.0, 0.0, -geometry.gravity.value);
  if (request.artifact == ArtifactKind::fixed) r.model.bcs.fix(r.pin_nodes);  // thesis 3.3.2
  measure_masses(r);
  return r;
}

}  // namespace ccm::rig
