// A scene as read from a scene file (docs/scene-file.md): plain typed aggregates, validated by
// the parser, turned into a Model by the scene builder. Every part remembers where it came from
// so that later errors can still name the file, the line and the key.
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "config/config_error.hpp"
#include "engine/body/rigid_body_model.hpp"
#include "engine/core/element_kind.hpp"
#include "engine/core/penalty_mode.hpp"
#include "engine/core/step_safety.hpp"
#include "engine/core/types.hpp"
#include "engine/material/material.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/monitor/stability_monitor.hpp"
#include "engine/observe/field_catalog.hpp"

namespace ccm {

// Where a table of the scene file is.
struct SourceRef {
  std::string path;                                   // key path of the table, e.g. "fixed[0]"
  int line = 0;                                       // line of the table
  std::map<std::string, int, std::less<>> key_lines;  // line of each key set in the table

  int line_of(std::string_view key) const {
    const auto it = key_lines.find(key);
    return it == key_lines.end() ? line : it->second;
  }
  std::string key_path(std::string_view key) const {
    if (key.empty()) return path;
    return path.empty() ? std::string(key) : fmt::format("{}.{}", path, key);
  }
};

struct SceneTime {
  double end = 0.0;                     // [s]
  double output_interval = 0.0;         // [s]; the parser sets end/100 when not given
  double dt_safety = kDefaultDtSafety;  // (0, 2]
  std::optional<double> max_dt;         // [s]
  std::optional<long> max_steps;
  // The run ends once its bodies have separated for this hold [s] (`end` is then the guard).
  std::optional<double> end_after_separation;
};

enum class Shape { sphere, box, cylinder, pipe, mesh };

struct GeometrySpec {
  Shape shape = Shape::box;
  PrimitiveSpec primitive{PrimitiveKind::box};  // sphere, box, cylinder, pipe
  std::filesystem::path file;                   // mesh: resolved against the scene's folder
  double scale = 1.0;  // mesh: the file's coordinates times this, before placement (0.001: mm)
};

struct BodySpec {
  std::string name;
  MaterialParams material;
  ElementKind element = kDefaultElementKind;  // the tets' formulation (docs/elements.md)
  GeometrySpec geometry;
  Placement placement;
  Vec3 initial_velocity = Vec3::Zero();  // [m/s]
  // When set [kg]: the density becomes mass / meshed volume (material.rho is the nominal value).
  std::optional<double> mass;
  // kind = "rigid" (docs/rigid-bodies.md): the body moves as one; its material gives its density.
  bool rigid = false;
  RigidMotion motion = RigidMotion::free;
  Vec3 initial_angular_velocity = Vec3::Zero();  // [rad/s], world axes (free, pinned)
  RigidPin pin;                                  // motion = "pinned": [bodies.pin]
  // Given instead of computed from the meshed volume (rigid only): about the centre of mass,
  // world axes [kg m^2]; the centre [m] (else the meshed volume's).
  std::optional<Mat3> inertia;
  std::optional<Vec3> center_of_mass;
  // motion = "prescribed": [t, x, y, z] points of the centre-of-mass velocity [m/s] and of the
  // angular velocity [rad/s]; a missing one is zero.
  std::vector<std::array<double, 4>> prescribed_velocity, prescribed_angular_velocity;
  SourceRef where;           // the [[bodies]] table
  SourceRef geometry_where;  // its geometry table
};

struct BoxSpec {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();
};

struct PlaneSpec {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitX();  // non-zero, need not be unit
  double tolerance = 1e-6;      // [m]
};

struct NodeSetRef {
  std::string name;  // "<body>/<set>", or "<set>" when the spec names the body
};
struct SurfaceRef {
  std::string name;  // "<body>/<surface>", or "<surface>" when the spec names the body
};

using NodeSelection = std::variant<NodeSetRef, BoxSpec, PlaneSpec>;
using SurfaceSelection = std::variant<SurfaceRef, PlaneSpec>;

struct FixedSpec {
  std::optional<std::string> body;  // restricts the selection to one body
  NodeSelection selection;
  SourceRef where;
};

// [[joints]] (docs/scene-file.md): a kinematic constraint on nodes of deformable bodies, applied
// after the fixed nodes in file order (engine/bc/kinematic_constraint.hpp).
enum class JointKind {
  pin,    // the nodes turn as one rigid ring about an axis, with Coulomb friction (pin_joint.hpp)
  slide,  // the nodes move only along one direction (slide_constraint.hpp)
  track,  // Coulomb and viscous friction on the nodes along a track (track_friction.hpp)
};

struct JointSpec {
  std::string name;  // "joint<k>" unless given; a pin's history columns: <name>.angle, ...
  JointKind kind = JointKind::pin;
  std::optional<std::string> body;  // restricts the selection to one body
  NodeSelection selection;
  Vec3 point = Vec3::Zero();      // pin: a point on the axis [m]
  Vec3 axis = Vec3::UnitX();      // pin: the axis; slide, track: the direction (non-zero)
  double mu_s = 0.0, mu_k = 0.0;  // pin, track: static and kinetic friction coefficients
  double stiffness = 0.0;         // pin: the clamp's torsional spring [N m/rad] (pin_joint.hpp)
  double damping = 0.0;           // pin: its damper [N m s/rad]; track: viscous [N s/m]
  double normal_force = 0.0;      // track: N [N] pressing the group on its track
  double active_from = 0.0;       // track: the friction acts from this time on [s]
  SourceRef where;
};

struct SurfaceLoadSpec {
  std::string name;
  std::optional<std::string> body;
  SurfaceSelection surface;
  Vec3 direction = Vec3::UnitX();                // non-zero
  std::vector<std::pair<double, double>> force;  // (t [s], total force [N])
  SourceRef where;
};

struct TrackSpec {
  std::string name;
  std::string body;
  Vec3 point = Vec3::Zero();  // [m]; the body's nearest node is tracked
  SourceRef where;
};

struct OutputSpec {
  bool kinetic_energy = true;
  bool internal_energy = true;
  bool displacement = true;
  std::vector<TrackSpec> track;
  // Field files for ParaView (docs/fields.md): empty writes none. field_interval [s] is a whole
  // multiple of time.output_interval; the parser sets it to output_interval when not given.
  std::vector<FieldKind> fields;
  double field_interval = 0.0;
};

// [contact] (docs/scene-file.md).
enum class ContactKind { none, rigid_penalty, dcr };

struct RigidSphereSpec {
  std::string name = "sphere";   // history column prefix
  double radius = 0.0;           // [m]
  double mass = 0.0;             // [kg] (given, or density * 4/3 pi R^3)
  Vec3 center = Vec3::Zero();    // [m]
  Vec3 velocity = Vec3::Zero();  // [m/s]
};

// One contact model of a scene: the [contact] table, or one entry of [[contact.pairs]].
struct ContactSpec {
  ContactKind kind = ContactKind::none;
  // The pair's name: the prefix of its DCR history columns ("contact" for the [contact] table;
  // a rigid_penalty's columns start with its sphere's or "contact").
  std::string name = "contact";
  // rigid_penalty:
  std::string body;                                   // the deformable body
  std::optional<std::string> surface;                 // default "<body>/boundary"
  PenaltyMode penalty_mode = PenaltyMode::per_point;  // per_point (thesis) or element
  double penalty = kDefaultPointPenalty;  // per_point: K_P [N/m] per quadrature point (thesis 2.8)
  double penalty_scale = kDefaultElementPenaltyScale;  // element: s in k = s K A^2 / V
  double damping = 0.0;                                // zeta >= 0, fraction of critical per point
  std::optional<Vec3> force_axis;  // rigid_penalty: default the sphere's initial velocity
                                   // direction; dcr: pair forces are output along it
  RigidSphereSpec sphere;
  // rigid_penalty against a meshed rigid body (kind = "rigid") instead of the sphere:
  std::optional<std::string> rigid;
  double crease_angle = kDefaultCreaseAngle;  // [degrees] its sharper edges stay sharp
  // dcr:
  std::vector<std::string> surfaces;  // as given; a name without '/' means "<name>/boundary"
  bool self_contact = false;
  double restitution = 0.0;          // e in [0, 1]
  double friction = 0.0;             // Coulomb mu >= 0
  std::vector<std::string> sensors;  // output: named surfaces whose pressure is reported (eq. 3.8)
  SourceRef where;                   // the [contact] table
  SourceRef sphere_where;            // [contact.sphere]
};

struct Scene {
  std::filesystem::path source;  // the scene file, as given
  std::string title;
  SceneTime time;
  MonitorSettings monitor;
  Vec3 gravity = Vec3::Zero();  // [m/s^2]
  std::vector<BodySpec> bodies;
  std::vector<FixedSpec> fixed;
  std::vector<SurfaceLoadSpec> surface_loads;
  std::vector<JointSpec> joints;
  OutputSpec output;
  // The contact models in the order they act: none, the [contact] table's, or one per entry of
  // [[contact.pairs]].
  std::vector<ContactSpec> contacts;
  std::vector<std::string> warnings;  // legal but suspicious settings, each "<file>:<line>: ..."
};

}  // namespace ccm
