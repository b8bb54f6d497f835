#include "rig_models/sim/rig_scene.hpp"

#include <algorithm>
#include <utility>

namespace ccm::rig {
namespace {

JointSpec on_set(std::string name, JointKind kind, const char* node_set) {
  JointSpec j;
  j.name = std::move(name);
  j.kind = kind;
  j.selection = NodeSetRef{node_set};
  return j;
}

// The artifact's pin (3.3.2): a Free artifact turns on it against Coulomb friction (3.2-3.6); a
// Fixed one is held by the screw's clamp, a torsional spring and damper (PJ.1), and has friction
// only when it is given (3.4.1's frictional "fixed" pin).
JointSpec pin_of(const RigModel& rig, const RigCase& c, const RunParameters& par) {
  JointSpec j = on_set(kPinJoint, JointKind::pin, kPinBoreSet);
  j.point = rig.pin_point;
  j.axis = rig.pin_axis;
  j.mu_s = par.mu_s.value_or(0.0);
  j.mu_k = par.mu_k.value_or(0.0);
  if (c.artifact == ArtifactKind::fixed) {
    j.stiffness = par.clamp_stiffness;
    j.damping = par.clamp_damping;
  }
  return j;
}

// The track's friction (track_friction_of) on the impactor's nodes. The open-loop drive's
// measured motion carries the friction until the measured contact onset, so there it acts from
// the onset (thesis 3.4.1: the drive does not carry it once contact starts).
JointSpec track_of(const RigModel& rig, const RigCaseTable& t, const RunParameters& p,
                   const RigSceneRequest& r) {
  const TrackFrictionSpec f = track_friction_of(t, p, r.gravity);
  JointSpec j = on_set(kTrackJoint, JointKind::track, kImpactorSet);
  j.axis = rig.track;
  j.normal_force = f.normal_force;
  j.mu_s = f.mu_s;
  j.mu_k = f.mu_k;
  j.damping = f.damping;
  j.active_from = r.friction_from;
  return j;
}

ContactSpec contact_of(const RigModel& rig, const RigGeometry& g) {
  ContactSpec c;
  c.kind = ContactKind::dcr;
  c.surfaces = rig.contact_surfaces;
  c.friction = g.contact.friction.value;
  c.restitution = g.contact.restitution.value;
  c.force_axis = rig.track;
  c.sensors = {kSensorSurface};
  return c;
}

}  // namespace

TrackFrictionSpec track_friction_of(const RigCaseTable& t, const RunParameters& p, double gravity) {
  return {{},
          Vec3::UnitY(),
          t.rig.impactor_mass.value * gravity,
          std::max(p.track_static_friction, p.track_friction),
          p.track_friction,
          p.track_damping,
          0.0};
}

Scene rig_scene(const RigModel& rig, const RigGeometry& geometry, const RigCaseTable& table,
                const RigCase& c, const RunParameters& parameters, const RigSceneRequest& request,
                const std::filesystem::path& source) {
  Scene s;
  s.source = source;
  s.title = "rig " + c.code;
  s.time.end = request.end_time;
  s.time.output_interval = request.output_interval;
  JointSpec guide = on_set(kGuideJoint, JointKind::slide, kGuideSet);
  guide.axis = rig.track;
  s.joints = {guide, pin_of(rig, c, parameters), track_of(rig, table, parameters, request)};
  if (request.contact) s.contacts.push_back(contact_of(rig, geometry));
  if (!request.drive_force.empty()) {
    SurfaceLoadSpec drive;
    drive.name = "drive";
    drive.surface = SurfaceRef{kDriveSurface};
    drive.direction = rig.track;
    drive.force = request.drive_force;
    s.surface_loads.push_back(std::move(drive));
  }
  return s;
}

}  // namespace ccm::rig
