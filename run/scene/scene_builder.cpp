#include "run/scene/scene_builder.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/bc/node_selection.hpp"
#include "engine/bc/pin_joint.hpp"
#include "engine/bc/slide_constraint.hpp"
#include "engine/bc/track_friction.hpp"
#include "engine/contact/contact_set.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/contact/penalty/rigid_surface_penalty.hpp"
#include "engine/contact/rigid_sphere_penalty.hpp"
#include "engine/core/time_table.hpp"
#include "engine/mesh/locality_order.hpp"
#include "engine/mesh/readers/mesh_file.hpp"

namespace ccm {
namespace {

[[noreturn]] void fail(const Scene& scene, const SourceRef& where, std::string_view key,
                       std::string_view problem) {
  throw config_error(scene.source, where.line_of(key), where.key_path(key), problem);
}

// Rotation about the origin, then translation: the convention mesh_primitive applies.
void place(TetMesh& mesh, const Placement& p) {
  const double angle = p.rotation_deg * std::numbers::pi / 180.0;
  const Mat3 R = Eigen::AngleAxisd(angle, p.rotation_axis.normalized()).toRotationMatrix();
  for (Vec3& x : mesh.nodes) x = R * x + p.translation;
}

TetMesh mesh_body(const Scene& scene, const BodySpec& body) {
  const GeometrySpec& g = body.geometry;
  const bool from_file = g.shape == Shape::mesh;
  try {
    if (!from_file) return mesh_primitive(g.primitive, body.placement);
    TetMesh mesh = read_mesh_file(g.file);
    for (Vec3& x : mesh.nodes) x *= g.scale;
    place(mesh, body.placement);
    return mesh;
  } catch (const MeshError& e) {
    const std::string what = from_file ? "cannot read its mesh file" : "cannot be meshed";
    fail(scene, body.geometry_where, from_file ? "file" : "",
         fmt::format("body '{}' {}: {}", body.name, what, e.what()));
  }
}

// The body's material; with `mass` set, its density is mass / meshed volume, so that a faceted
// primitive (a sphere's inscribed polyhedron) weighs what the solid it stands for weighs.
MaterialParams material_of(const BodySpec& body, const TetMesh& geometry) {
  MaterialParams m = body.material;
  if (body.mass) m.rho = *body.mass / mesh_volume(geometry);
  return m;
}

int body_index(const Scene& scene, const ModelMesh& mesh, const SourceRef& where,
               std::string_view key, const std::string& name) {
  const int b = mesh.body_index(name);
  if (b >= 0) return b;
  std::vector<std::string> names;
  for (const Body& body : mesh.bodies) names.push_back(body.name);
  fail(scene, where, key,
       fmt::format("no body named '{}' (bodies: {})", name, fmt::join(names, ", ")));
}

int optional_body(const Scene& scene, const ModelMesh& mesh, const SourceRef& where,
                  const std::optional<std::string>& name) {
  return name ? body_index(scene, mesh, where, "body", *name) : -1;
}

// "<body>/<name>" when the spec names a body and the name has no body part.
std::string qualified(const std::optional<std::string>& body, const std::string& name) {
  if (!body || name.find('/') != std::string::npos) return name;
  return *body + "/" + name;
}

std::vector<int> in_body(const ModelMesh& mesh, int body, std::vector<int> nodes) {
  if (body < 0) return nodes;
  const Body& b = mesh.bodies[static_cast<size_t>(body)];
  std::erase_if(nodes, [&](int n) { return n < b.first_node || n >= b.first_node + b.n_nodes; });
  return nodes;
}

template <typename Map>
std::string known_names(const Map& map) {
  std::vector<std::string> names;
  for (const auto& [name, value] : map) names.push_back(name);
  return fmt::format("{}", fmt::join(names, ", "));
}

// The nodes a selection (of one body, when given) picks; where: the table, for errors.
std::vector<int> select_nodes(const Scene& scene, const ModelMesh& mesh,
                              const std::optional<std::string>& body_name,
                              const NodeSelection& selection, const SourceRef& where) {
  const int body = optional_body(scene, mesh, where, body_name);
  if (const auto* set = std::get_if<NodeSetRef>(&selection)) {
    const std::string name = qualified(body_name, set->name);
    const auto it = mesh.node_sets.find(name);
    if (it == mesh.node_sets.end())
      fail(
          scene, where, "node_set",
          fmt::format("no node set named '{}' (node sets: {})", name, known_names(mesh.node_sets)));
    return in_body(mesh, body, it->second);
  }
  if (const auto* box = std::get_if<BoxSpec>(&selection))
    return nodes_in_box(mesh, body, box->min, box->max);
  const auto& plane = std::get<PlaneSpec>(selection);
  return nodes_on_plane(mesh, body, plane.point, plane.normal, plane.tolerance);
}

std::string_view selection_key(const NodeSelection& selection) {
  static constexpr std::string_view keys[] = {"node_set", "box", "plane"};
  return keys[selection.index()];
}

// The rigid body holding node n, or nullptr.
const Body* rigid_body_of(const ModelMesh& mesh, int n) {
  for (const Body& b : mesh.bodies)
    if (b.rigid && n >= b.first_node && n < b.first_node + b.n_nodes) return &b;
  return nullptr;
}

void apply_fixed(const Scene& scene, Model& model) {
  for (const FixedSpec& f : scene.fixed) {
    const std::vector<int> nodes = select_nodes(scene, model.mesh, f.body, f.selection, f.where);
    if (nodes.empty()) fail(scene, f.where, selection_key(f.selection), "selects no node");
    for (int n : nodes)
      if (const Body* b = rigid_body_of(model.mesh, n))
        fail(scene, f.where, selection_key(f.selection),
             fmt::format("selects nodes of the rigid body '{}': a rigid body is held by its "
                         "motion (motion = \"fixed\" or \"prescribed\"), not by nodes",
                         b->name));
    model.bcs.fix(nodes);
  }
}

std::vector<Triangle> named_surface(const Scene& scene, const ModelMesh& mesh,
                                    const SurfaceLoadSpec& s, const SurfaceRef& ref, int body) {
  const std::string name = qualified(s.body, ref.name);
  const auto it = mesh.surfaces.find(name);
  if (it == mesh.surfaces.end())
    fail(scene, s.where, "surface",
         fmt::format("no surface named '{}' (surfaces: {})", name, known_names(mesh.surfaces)));
  if (body >= 0 && it->second.body != body)
    fail(scene, s.where, "surface", fmt::format("surface '{}' is not on body '{}'", name, *s.body));
  return it->second.triangles;
}

std::vector<Triangle> select_surface(const Scene& scene, const ModelMesh& mesh,
                                     const SurfaceLoadSpec& s) {
  const int body = optional_body(scene, mesh, s.where, s.body);
  if (const auto* ref = std::get_if<SurfaceRef>(&s.surface))
    return named_surface(scene, mesh, s, *ref, body);
  const auto& plane = std::get<PlaneSpec>(s.surface);
  std::vector<Triangle> out;
  for (int b = 0; b < static_cast<int>(mesh.bodies.size()); ++b) {
    if (body >= 0 && b != body) continue;
    const auto tris = boundary_on_plane(mesh, b, plane.point, plane.normal, plane.tolerance);
    out.insert(out.end(), tris.begin(), tris.end());
  }
  return out;
}

void apply_loads_of(const Scene& scene, Model& model) {
  for (const SurfaceLoadSpec& s : scene.surface_loads) {
    const std::vector<Triangle> surface = select_surface(scene, model.mesh, s);
    const std::string_view key = s.surface.index() == 0 ? "surface" : "plane";
    if (surface.empty()) fail(scene, s.where, key, "selects no boundary triangle");
    for (const RigidBodyModel& r : model.rigid_bodies) {
      const Body& b = model.mesh.bodies[static_cast<size_t>(r.body)];
      if (r.kinematic() && rigid_body_of(model.mesh, surface.front()[0]) == &b)
        fail(scene, s.where, key,
             fmt::format("loads the rigid body '{}', whose motion is \"{}\": a load cannot move "
                         "it (make it free)",
                         b.name, to_string(r.motion)));
    }
    try {
      model.bcs.loads.push_back(
          make_surface_load(s.name, model.mesh, surface, s.direction, TimeTable(s.force)));
    } catch (const std::invalid_argument& e) {
      fail(scene, s.where, key, e.what());
    }
  }
}

std::array<TimeTable, 3> vector_history(const std::vector<std::array<double, 4>>& points) {
  std::array<TimeTable, 3> tables{TimeTable({{0.0, 0.0}}), TimeTable({{0.0, 0.0}}),
                                  TimeTable({{0.0, 0.0}})};
  if (points.empty()) return tables;
  for (size_t c = 0; c < 3; ++c) {
    std::vector<std::pair<double, double>> component;
    for (const auto& p : points) component.emplace_back(p[0], p[c + 1]);
    tables[c] = TimeTable(std::move(component));
  }
  return tables;
}

// Marks the scene's rigid bodies in the mesh (before the element set is made) and returns their
// models, in body order.
std::vector<RigidBodyModel> make_rigid_bodies(const Scene& scene, ModelMesh& mesh) {
  std::vector<RigidBodyModel> out;
  for (size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& spec = scene.bodies[b];
    if (!spec.rigid) continue;
    try {
      out.push_back(make_rigid(mesh, static_cast<int>(b), spec.motion));
    } catch (const std::invalid_argument& e) {
      fail(scene, spec.where, "kind", fmt::format("body '{}': {}", spec.name, e.what()));
    }
    RigidBodyModel& r = out.back();
    r.velocity = spec.initial_velocity;
    r.angular_velocity = spec.initial_angular_velocity;
    r.pin = spec.pin;
    if (spec.inertia) r.mass.inertia = *spec.inertia;
    if (spec.center_of_mass) r.mass.center = *spec.center_of_mass;
    r.prescribed_velocity = vector_history(spec.prescribed_velocity);
    r.prescribed_angular_velocity = vector_history(spec.prescribed_angular_velocity);
  }
  return out;
}

void apply_initial_velocities(const Scene& scene, Model& model) {
  for (size_t b = 0; b < scene.bodies.size(); ++b) {
    const Body& body = model.mesh.bodies[b];
    for (int n = body.first_node; n < body.first_node + body.n_nodes; ++n)
      model.initial_velocity[static_cast<size_t>(n)] = scene.bodies[b].initial_velocity;
  }
}

}  // namespace

void apply_surface_loads(const Scene& scene, Model& model) { apply_loads_of(scene, model); }

Model build_model(const Scene& scene) {
  ModelMesh mesh;
  for (const BodySpec& body : scene.bodies) {
    TetMesh geometry = in_locality_order(mesh_body(scene, body));
    add_body(mesh, body.name, material_of(body, geometry), std::move(geometry));
    mesh.bodies.back().element = body.element;
  }
  std::vector<RigidBodyModel> rigid = make_rigid_bodies(scene, mesh);
  Model model = make_model(std::move(mesh));
  model.rigid_bodies = std::move(rigid);
  apply_fixed(scene, model);
  apply_surface_loads(scene, model);
  apply_initial_velocities(scene, model);
  model.bcs.gravity = scene.gravity;
  return model;
}

OutputRequest build_output_request(const Scene& scene, const ModelMesh& mesh) {
  OutputRequest r;
  r.kinetic_energy = scene.output.kinetic_energy;
  r.internal_energy = scene.output.internal_energy;
  r.displacement = scene.output.displacement;
  for (const TrackSpec& t : scene.output.track) {
    const int body = body_index(scene, mesh, t.where, "body", t.body);
    r.tracked.push_back({t.name, nearest_node(mesh, body, t.point)});
  }
  return r;
}

namespace {

// The nodes a constraint-type contact holds without moving them: fixed nodes and every rigid
// body's (sorted, unique).
std::vector<int> held_nodes(const Model& model) {
  std::vector<int> held = model.bcs.fixed_nodes;
  for (const RigidBodyModel& r : model.rigid_bodies) {
    const Body& b = model.mesh.bodies[static_cast<size_t>(r.body)];
    for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n) held.push_back(n);
  }
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());
  return held;
}

// model = "dcr": every listed surface must exist and have triangles.
ContactSetup build_dcr(const Scene& scene, const ContactSpec& c, const Model& model) {
  const ModelMesh& mesh = model.mesh;
  dcr::DcrSettings settings;
  size_t triangles = 0;
  for (const std::string& given : c.surfaces) {
    const std::string name = given.find('/') == std::string::npos ? given + "/boundary" : given;
    const auto it = mesh.surfaces.find(name);
    if (it == mesh.surfaces.end())
      fail(scene, c.where, "surfaces",
           fmt::format("no surface named '{}' (surfaces: {})", name, known_names(mesh.surfaces)));
    if (it->second.triangles.empty())
      fail(scene, c.where, "surfaces", fmt::format("surface '{}' has no triangle", name));
    if (std::find(settings.surfaces.begin(), settings.surfaces.end(), name) !=
        settings.surfaces.end())
      fail(scene, c.where, "surfaces", fmt::format("surface '{}' is listed twice", name));
    settings.surfaces.push_back(name);
    triangles += it->second.triangles.size();
  }
  settings.self_contact = c.self_contact;
  settings.restitution = c.restitution;
  settings.friction = c.friction;
  settings.output.force_axis = c.force_axis;
  settings.history_prefix = c.name;
  for (const std::string& name : c.sensors) {
    if (!mesh.surfaces.contains(name))
      fail(scene, c.where, "sensors",
           fmt::format("no surface named '{}' (surfaces: {})", name, known_names(mesh.surfaces)));
    settings.output.sensors.push_back(name);
  }
  std::unique_ptr<dcr::DcrContact> dcr;
  try {
    dcr = std::make_unique<dcr::DcrContact>(mesh, settings, held_nodes(model));
  } catch (const std::invalid_argument& e) {
    fail(scene, c.where, "", e.what());
  }
  ContactSetup setup;
  setup.model_name = "dcr";
  setup.description = fmt::format(
      "dcr: {} ({} triangles), self_contact {}, restitution {:.4g}, friction {:.4g}",
      fmt::join(settings.surfaces, ", "), triangles, c.self_contact, c.restitution, c.friction);
  setup.histories = {dcr.get()};
  setup.solve_warning = [model = dcr.get()] {
    const long v = model->unconverged_velocity_solves(), p = model->unconverged_projections();
    if (v == 0 && p == 0) return std::string();
    return fmt::format(
        "dcr: {} velocity solves and {} position projections stopped at their sweep cap without "
        "converging",
        v, p);
  };
  setup.search_summary = [model = dcr.get()] {
    const dcr::BroadPhaseStats& s = model->broad_phase_stats();
    return fmt::format(
        "dcr: broad phase on {} steps, {} pair-cache rebuilds, {} cached pairs at the last",
        s.calls, s.rebuilds, s.cached_pairs);
  };
  setup.model = std::move(dcr);
  return setup;
}

// "K_P 1e+06 N/m per point" (the thesis's) or the element mode's scale and range of k_q.
std::string penalty_description(const RigidSpherePenalty& model) {
  const RigidSpherePenaltyParams& p = model.params();
  if (p.penalty_mode == PenaltyMode::per_point)
    return fmt::format("K_P {:.4g} N/m per point", p.penalty);
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (size_t tri = 0; tri < model.surface_triangles(); ++tri) {
    lo = std::min(lo, model.point_stiffness(tri));
    hi = std::max(hi, model.point_stiffness(tri));
  }
  return fmt::format("element penalty s {:.4g} (k = s K A^2 / V, {:.4g} .. {:.4g} N/m per point)",
                     p.penalty_scale, lo, hi);
}

// model = "rigid_penalty" with rigid = "<body>": the penalty against a meshed rigid body.
ContactSetup build_rigid_surface_penalty(const Scene& scene, const ContactSpec& c,
                                         const Model& model, const std::vector<Triangle>& surface,
                                         const std::string& surface_name) {
  const int rigid = body_index(scene, model.mesh, c.where, "rigid", *c.rigid);
  if (!model.mesh.bodies[static_cast<size_t>(rigid)].rigid)
    fail(scene, c.where, "rigid",
         fmt::format("body '{}' is not rigid (give it kind = \"rigid\")", *c.rigid));
  RigidSurfacePenaltyParams p;
  p.name = c.name;
  p.penalty = c.penalty;
  p.damping = c.damping;
  p.crease_angle = c.crease_angle;
  std::unique_ptr<RigidSurfacePenalty> penalty;
  try {
    penalty = std::make_unique<RigidSurfacePenalty>(model.mesh, surface, rigid, p);
  } catch (const std::invalid_argument& e) {
    fail(scene, c.where, "rigid", e.what());
  }
  ContactSetup setup;
  setup.model_name = "rigid_penalty";
  setup.description = fmt::format(
      "rigid_penalty: rigid body '{}' ({} triangles, smoothed where its edges turn by less than "
      "{:.4g} degrees) on '{}' ({} triangles), K_P {:.4g} N/m per point, damping {:.4g} of "
      "critical",
      *c.rigid, model.mesh.bodies[static_cast<size_t>(rigid)].boundary.size(), p.crease_angle,
      surface_name, surface.size(), p.penalty, p.damping);
  setup.histories = {penalty.get()};
  setup.model = std::move(penalty);
  return setup;
}

// model = "rigid_penalty": the deformable surface against the analytic sphere or a rigid body.
ContactSetup build_rigid_penalty(const Scene& scene, const ContactSpec& c, const Model& model) {
  const ModelMesh& mesh = model.mesh;
  const int body = body_index(scene, mesh, c.where, "body", c.body);
  const std::string_view key = c.surface ? "surface" : "body";
  const std::string name = qualified(c.body, c.surface.value_or("boundary"));
  const auto it = mesh.surfaces.find(name);
  if (it == mesh.surfaces.end())
    fail(scene, c.where, key,
         fmt::format("no surface named '{}' (surfaces: {})", name, known_names(mesh.surfaces)));
  if (it->second.body != body)
    fail(scene, c.where, key, fmt::format("surface '{}' is not on body '{}'", name, c.body));
  if (it->second.triangles.empty()) fail(scene, c.where, key, "the surface has no triangle");
  if (mesh.bodies[static_cast<size_t>(body)].rigid)
    fail(scene, c.where, key,
         fmt::format("body '{}' is rigid: the analytic sphere's penalty contact acts on a "
                     "deformable surface (use model = \"dcr\" between rigid and deformable bodies)",
                     c.body));

  if (c.rigid) return build_rigid_surface_penalty(scene, c, model, it->second.triangles, name);
  ContactSetup setup;

  RigidSpherePenaltyParams p;
  p.name = c.sphere.name;
  p.sphere = {c.sphere.radius, c.sphere.mass, c.sphere.center, c.sphere.velocity};
  p.penalty_mode = c.penalty_mode;
  p.penalty = c.penalty;
  p.penalty_scale = c.penalty_scale;
  p.damping = c.damping;
  p.gravity = scene.gravity;
  p.force_axis = c.force_axis;
  std::unique_ptr<RigidSpherePenalty> penalty;
  try {
    penalty = std::make_unique<RigidSpherePenalty>(mesh, it->second.triangles, p);
  } catch (const std::invalid_argument& e) {
    fail(scene, c.where, "", e.what());
  }
  setup.model_name = "rigid_penalty";
  setup.description = fmt::format(
      "rigid_penalty: sphere '{}' (R {:.4g} m, {:.4g} kg) on '{}' ({} triangles), {}, damping "
      "{:.4g} of critical",
      p.name, p.sphere.radius, p.sphere.mass, name, it->second.triangles.size(),
      penalty_description(*penalty), p.damping);
  setup.histories = {penalty.get()};
  setup.model = std::move(penalty);
  return setup;
}

ContactSetup build_one_contact(const Scene& scene, const ContactSpec& c, const Model& model) {
  return c.kind == ContactKind::dcr ? build_dcr(scene, c, model)
                                    : build_rigid_penalty(scene, c, model);
}

// The bodies a DCR entry's surfaces lie on.
std::vector<int> dcr_bodies(const ContactSpec& c, const ModelMesh& mesh) {
  std::vector<int> bodies;
  for (const std::string& given : c.surfaces) {
    const std::string name = given.find('/') == std::string::npos ? given + "/boundary" : given;
    const auto it = mesh.surfaces.find(name);
    if (it != mesh.surfaces.end()) bodies.push_back(it->second.body);
  }
  return bodies;
}

// Two DCR entries must not share a body: their solves, one after the other, would each undo
// the other's corrections on it. One entry listing all the surfaces is one solve over all of
// their contacts (docs/scene-file.md, "Contact pairs").
void check_dcr_entries_apart(const Scene& scene, const ModelMesh& mesh) {
  std::vector<std::pair<int, const ContactSpec*>> seen;  // body, the entry that has it
  for (const ContactSpec& c : scene.contacts) {
    if (c.kind != ContactKind::dcr) continue;
    for (int b : dcr_bodies(c, mesh))
      for (const auto& [body, other] : seen)
        if (body == b && other != &c)
          fail(scene, c.where, "surfaces",
               fmt::format("body '{}' is also in DCR pair '{}': two DCR pairs cannot share a "
                           "body (list all of their surfaces in one DCR pair: one solve holds "
                           "every contact among them)",
                           mesh.bodies[static_cast<size_t>(b)].name, other->name));
    for (int b : dcr_bodies(c, mesh)) seen.emplace_back(b, &c);
  }
}

// The non-empty texts of the parts, joined by "; "; none when there is no part.
std::function<std::string()> joined_texts(std::vector<std::function<std::string()>> parts) {
  if (parts.empty()) return {};
  return [parts = std::move(parts)] {
    std::string all;
    for (const auto& part : parts) {
      const std::string one = part();
      if (!one.empty()) all += (all.empty() ? "" : "; ") + one;
    }
    return all;
  };
}

// Several entries: one ContactSet of their models, in order (engine/contact/contact_set.hpp).
ContactSetup combined(std::vector<ContactSetup> parts) {
  ContactSetup setup;
  setup.model_name.clear();
  std::vector<std::unique_ptr<ContactModel>> models;
  std::vector<std::function<std::string()>> warnings, searches;
  for (ContactSetup& part : parts) {
    setup.model_name += (models.empty() ? "" : " + ") + part.model_name;
    setup.description += (models.empty() ? "" : "; ") + part.description;
    setup.histories.insert(setup.histories.end(), part.histories.begin(), part.histories.end());
    if (part.solve_warning) warnings.push_back(std::move(part.solve_warning));
    if (part.search_summary) searches.push_back(std::move(part.search_summary));
    models.push_back(std::move(part.model));
  }
  setup.model = std::make_unique<ContactSet>(std::move(models));
  setup.solve_warning = joined_texts(std::move(warnings));
  setup.search_summary = joined_texts(std::move(searches));
  return setup;
}

}  // namespace

std::vector<std::unique_ptr<KinematicConstraint>> build_joints(const Scene& scene,
                                                               const Model& model) {
  std::vector<std::unique_ptr<KinematicConstraint>> joints;
  for (const JointSpec& j : scene.joints) {
    const std::string_view key = selection_key(j.selection);
    const std::vector<int> nodes = select_nodes(scene, model.mesh, j.body, j.selection, j.where);
    if (nodes.empty()) fail(scene, j.where, key, "selects no node");
    for (int n : nodes)
      if (const Body* b = rigid_body_of(model.mesh, n))
        fail(scene, j.where, key,
             fmt::format("selects nodes of the rigid body '{}': a rigid body turns on a pin by "
                         "its motion (motion = \"pinned\" and [bodies.pin])",
                         b->name));
    try {
      if (j.kind == JointKind::pin)
        joints.push_back(std::make_unique<PinJoint>(
            PinJointSpec{nodes, j.point, j.axis, j.mu_s, j.mu_k, j.stiffness, j.damping},
            model.mesh.X));
      else if (j.kind == JointKind::slide)
        joints.push_back(std::make_unique<SlideConstraint>(nodes, j.axis));
      else
        joints.push_back(std::make_unique<TrackFriction>(TrackFrictionSpec{
            nodes, j.axis, j.normal_force, j.mu_s, j.mu_k, j.damping, j.active_from}));
    } catch (const std::invalid_argument& e) {
      fail(scene, j.where, key, e.what());
    }
  }
  return joints;
}

ContactSetup build_contact(const Scene& scene, const Model& model) {
  if (scene.contacts.empty()) return {};
  if (scene.contacts.size() == 1) return build_one_contact(scene, scene.contacts.front(), model);
  check_dcr_entries_apart(scene, model.mesh);
  std::vector<ContactSetup> parts;
  for (const ContactSpec& c : scene.contacts) {
    parts.push_back(build_one_contact(scene, c, model));
    parts.back().description = c.name + ": " + parts.back().description;
  }
  return combined(std::move(parts));
}

TimeControl time_control(const SceneTime& time) {
  TimeControl c;
  c.end_time = time.end;
  c.output_interval = time.output_interval;
  c.dt_safety = time.dt_safety;
  if (time.max_dt) c.max_dt = *time.max_dt;
  if (time.max_steps) c.max_steps = *time.max_steps;
  if (time.end_after_separation) c.end_after_separation = *time.end_after_separation;
  return c;
}

}  // namespace ccm
