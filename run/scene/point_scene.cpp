#include "run/scene/point_scene.hpp"

#include <fmt/format.h>

#include "run/scene/scene_file.hpp"
#include "study/grid/point_parameters.hpp"

namespace ccm::study {
namespace {

// Shortest round-trip form, always a TOML float (never read back as an integer).
std::string num(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string vec(double x, double y, double z) {
  return fmt::format("[{}, {}, {}]", num(x), num(y), num(z));
}

// Names only the axis values that change the model's physics: the rigid model has no ER (its
// sphere is analytic), and further axes (damping, penalty, restitution, mesh_scale, ...) show in
// the scene's own keys. So two points that differ only in what a model does not read give
// byte-identical scene texts for that model, and the study runs that scene once (run reuse,
// docs/grid-file.md).
std::string point_title(const GridPoint& point, ImpactModel model) {
  if (model == ImpactModel::rigid)
    return fmt::format("grid point (rigid): RLS = {}, KE = {} J", num(point.length_ratio),
                       num(point.kinetic_energy));
  return fmt::format("grid point (ccm): ER = {}, RLS = {}, KE = {} J", num(point.modulus_ratio),
                     num(point.length_ratio), num(point.kinetic_energy));
}

std::string time_section(const GridTime& time) {
  std::string s = fmt::format("[time]\nend = {}\noutput_interval = {}\ndt_safety = {}\n",
                              num(time.end), num(time.output_interval), num(time.dt_safety));
  if (time.max_steps > 0) s += fmt::format("max_steps = {}\n", time.max_steps);
  if (time.end_after_separation)
    s += fmt::format("end_after_separation = {}\n", num(*time.end_after_separation));
  return s;
}

std::string material(double E, double nu, double rho) {
  return fmt::format("[bodies.material]\nmodel = \"neo_hookean\"\nE = {}\nnu = {}\nrho = {}\n",
                     num(E), num(nu), num(rho));
}

// `refine = {...}` of a geometry table (local coordinates), or nothing when mesh_size is 0.
std::string refinement(double x, double y, double z, double radius, double mesh_size) {
  if (!(mesh_size > 0.0)) return {};
  return fmt::format("refine = {{ center = {}, radius = {}, mesh_size = {} }}\n", vec(x, y, z),
                     num(radius), num(mesh_size));
}

std::string artifact_body(const ArtifactSpec& a) {
  return fmt::format(
      "\n[[bodies]]\nname = \"{}\"\n\n{}\n[bodies.geometry]\nshape = \"box\"\n"
      "size = {}\nmesh_size = {}\n{}",
      kArtifactBody, material(a.E, a.nu, a.rho), vec(a.length, a.length, a.thickness),
      num(a.mesh_size),
      refinement(0.5 * a.length, 0.5 * a.length, a.thickness, a.contact_radius,
                 a.contact_mesh_size));
}

// Centre of the sphere at t = 0: above the middle of the top face, its lowest point `gap` up.
std::string sphere_center(const PointParameters& p) {
  const ArtifactSpec& a = p.artifact;
  return vec(0.5 * a.length, 0.5 * a.length, a.thickness + 0.5 * p.impactor_diameter + p.gap);
}

// mass = m_I: the meshed sphere (an inscribed polyhedron, 6 % light at D/5) weighs what the
// analytic one does, so that both models start with the same momentum and KE_I.
std::string impactor_body(const PointParameters& p) {
  const double r = 0.5 * p.impactor_diameter;
  return fmt::format(
      "\n[[bodies]]\nname = \"{}\"\ninitial_velocity = {}\nmass = {}\n\n{}\n"
      "[bodies.geometry]\nshape = \"sphere\"\nradius = {}\nmesh_size = {}\n{}\n"
      "[bodies.placement]\ntranslate = {}\n",
      kImpactorName, vec(0.0, 0.0, -p.impact_speed), num(p.impactor_mass),
      material(p.impactor_E, p.impactor_nu, p.impactor_rho), num(r), num(p.impactor_mesh_size),
      refinement(0.0, 0.0, -r, p.impactor_contact_radius, p.impactor_contact_mesh_size),
      sphere_center(p));
}

std::string fixed_plane(double px, double py, double pz, double nx, double ny, double nz) {
  return fmt::format("\n[[fixed]]\nbody = \"{}\"\nplane = {{ point = {}, normal = {} }}\n",
                     kArtifactBody, vec(px, py, pz), vec(nx, ny, nz));
}

std::string support(const ArtifactSpec& a) {
  if (a.support == ArtifactSupport::base) return fixed_plane(0, 0, 0, 0, 0, 1);
  return fixed_plane(0, 0, 0, 1, 0, 0) + fixed_plane(a.length, 0, 0, 1, 0, 0);
}

std::string dcr_contact(const PointParameters& p) {
  return fmt::format(
      "\n[contact]\nmodel = \"dcr\"\nsurfaces = [\"{}\", \"{}\"]\nrestitution = {}\n"
      "friction = {}\n",
      kImpactorName, kArtifactBody, num(p.contact.restitution), num(p.contact.friction));
}

// The springs' keys: `penalty` per point (the text every per-point scene always had), or the
// element mode and its scale.
std::string penalty_keys(const GridContact& c) {
  if (c.penalty_mode == PenaltyMode::per_point)
    return fmt::format("penalty = {}\n", num(c.penalty));
  return fmt::format("penalty_mode = \"{}\"\npenalty_scale = {}\n", to_string(c.penalty_mode),
                     num(c.penalty_scale));
}

// The rigid model with the meshed impactor: the ccm model's sphere body (the same mesh, mass and
// speed) made rigid, its unused modulus written as the artifact's so that the scene text does not
// depend on ER (one rigid run serves every ER, as with the analytic sphere).
std::string meshed_rigid_impactor(PointParameters p) {
  p.impactor_E = p.artifact.E;
  std::string body = impactor_body(p);
  const std::string name_line = fmt::format("name = \"{}\"\n", kImpactorName);
  body.insert(body.find(name_line) + name_line.size(), "kind = \"rigid\"\n");
  return body;
}

std::string meshed_rigid_contact(const PointParameters& p) {
  return fmt::format(
      "\n[contact]\nmodel = \"rigid_penalty\"\nbody = \"{}\"\nrigid = \"{}\"\n"
      "crease_angle = {}\n{}damping = {}\n",
      kArtifactBody, kImpactorName, num(p.contact.crease_angle), penalty_keys(p.contact),
      num(p.contact.damping));
}

std::string rigid_contact(const PointParameters& p) {
  return fmt::format(
      "\n[contact]\nmodel = \"rigid_penalty\"\nbody = \"{}\"\n{}damping = {}\n\n"
      "[contact.sphere]\nname = \"{}\"\nradius = {}\ndensity = {}\ncenter = {}\nvelocity = {}\n",
      kArtifactBody, penalty_keys(p.contact), num(p.contact.damping), kImpactorName,
      num(0.5 * p.impactor_diameter), num(p.impactor_rho), sphere_center(p),
      vec(0.0, 0.0, -p.impact_speed));
}

// Only what the trade-study metrics read (eq. 2.34-2.39): artifact energy and displacements.
constexpr const char* kOutput =
    "\n[output]\nkinetic_energy = true\ninternal_energy = false\ndisplacement = true\n";

}  // namespace

std::string point_scene_text(const GridSpec& spec, const GridPoint& point, ImpactModel model) {
  const PointParameters p = point_parameters(spec, point);
  std::string text = "# Written by ccm from a trade-study grid file (docs/grid-file.md).\n";
  text += fmt::format("title = \"{}\"\n\n", point_title(point, model));
  text += time_section(spec.time);
  text += artifact_body(p.artifact);
  const bool meshed_rigid = model == ImpactModel::rigid && p.contact.meshed_rigid_impactor;
  if (model == ImpactModel::ccm) text += impactor_body(p);
  if (meshed_rigid) text += meshed_rigid_impactor(p);
  text += support(p.artifact);
  if (model == ImpactModel::ccm)
    text += dcr_contact(p);
  else
    text += meshed_rigid ? meshed_rigid_contact(p) : rigid_contact(p);
  return text + kOutput;
}

std::filesystem::path point_scene_name(const GridSpec& spec, const GridPoint& point,
                                       ImpactModel model) {
  const std::string name =
      fmt::format("{}.point{}.{}.toml", spec.source.stem().string(), point.index, to_string(model));
  return spec.source.parent_path() / name;
}

Scene point_scene(const GridSpec& spec, const GridPoint& point, ImpactModel model) {
  return parse_scene(point_scene_text(spec, point, model), point_scene_name(spec, point, model));
}

}  // namespace ccm::study
