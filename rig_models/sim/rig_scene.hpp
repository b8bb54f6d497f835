// The rig's run as a scene (docs/rig-models.md, "One assembly path"): the joints and the contact
// of a case over the rig model's named node sets and surfaces, which run/'s one assembly path
// (run/scene/scene_run.hpp) builds as it builds any scene's:
//   [[joints]] "guide"  slide   the carriage's (and a flexible rod's) guide nodes along the track
//                                (thesis Fig. 3-18);
//              "pin"    pin     the artifact's bore on its pin (3.3.2): Coulomb friction on a Free
//                                artifact, the screw's clamp (spring, damper) on a Fixed one;
//              "track"  track   the impactor on its rails: Coulomb and viscous friction under its
//                                weight (3.4.1), from the measured onset under the open-loop drive;
//   [[surface_loads]] "drive"  the open-loop drive's measured force on the carriage (3.3.2);
//   [contact]  the DCR between the rod's tip and the envelope's contact zone, its output on the
//              sensor patch (eq. 3.8), unless the sensor mat (a load of its own) takes the pair.
// The model comes meshed and tuned from rig_models/geometry/ (build_rig_model).
#pragma once

#include <filesystem>
#include <utility>
#include <vector>

#include "engine/bc/track_friction.hpp"
#include "rig_models/cases/rig_case.hpp"
#include "rig_models/geometry/rig_geometry.hpp"
#include "rig_models/geometry/rig_model.hpp"
#include "rig_models/sim/run_parameters.hpp"
#include "run/scene/scene.hpp"

namespace ccm::rig {

// The joints' names (their history columns, and how the rig finds them in the assembled run).
inline constexpr const char* kGuideJoint = "guide";
inline constexpr const char* kPinJoint = "pin";
inline constexpr const char* kTrackJoint = "track";
// The sensor patch whose pressure the DCR's output reports (eq. 3.8).
inline constexpr const char* kSensorSurface = "envelope/sensor";

struct RigSceneRequest {
  double end_time = 0.0;         // s, on the simulation's clock (0 at the window's start)
  double output_interval = 0.0;  // s
  double gravity = 9.81;         // m/s^2, the impactor's weight on its track
  double friction_from = 0.0;    // s, the track's friction acts from here (simulation clock)
  bool contact = true;           // the DCR pair (false: the sensor mat takes it)
  // The open-loop drive's force on the carriage's front face ("carriage/drive") along the track,
  // (t [s] on the simulation's clock, F [N]); empty: the physical drive (a load of the rig's own).
  std::vector<std::pair<double, double>> drive_force;
};

// The track's friction on the impactor (engine/bc/track_friction.hpp), without its nodes: its
// weight as the normal force; a kinetic coefficient above the static one raises the static one
// to it. The run's "track" joint and the window's run-up (run_window.hpp) both take it.
TrackFrictionSpec track_friction_of(const RigCaseTable& table, const RunParameters& parameters,
                                    double gravity);

Scene rig_scene(const RigModel& rig, const RigGeometry& geometry, const RigCaseTable& table,
                const RigCase& c, const RunParameters& parameters, const RigSceneRequest& request,
                const std::filesystem::path& source);

}  // namespace ccm::rig
