// One simulation of a benchtop case (thesis 3.3): the rig model (geometry/rig_model.hpp), its
// drive (open loop or physical), the Fixed or Free artifact, the DCR contact between the rod's
// tip and the envelope, explicit integration with the automatic stable step and the stability
// monitor, and the three channels post-processed as the sensors see them (3.3.3), sampled at
// the measured timestamps when a trial drives the run.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "engine/solver/explicit_integrator.hpp"
#include "rig_models/compare/case_comparison.hpp"
#include "rig_models/geometry/rig_geometry.hpp"
#include "rig_models/geometry/rig_model.hpp"
#include "rig_models/sim/run_parameters.hpp"
#include "rig_models/sim/run_window.hpp"

namespace ccm::rig {

struct RigRunRequest {
  DriveKind drive = DriveKind::open_loop;
  const MeasuredTrial* trial = nullptr;  // drives the run (open loop) or gives its gap
  std::optional<double> start, end;      // s, trial time (run_window.hpp)
  double mesh_scale = 1.0;
  RunParameters parameters;
  ProgressFn progress;  // engine progress, simulation time from the window's start
  // Optional: called once the model is built, just before the run, with the options the run
  // will use (field output wraps the contact model and chains on_sample there).
  std::function<void(const Model& model, RunOptions& options)> instrument;
};

// The model as it was run, for tables and the store.
struct RigModelFacts {
  int n_nodes = 0, n_elements = 0;
  double impactor_mass = 0.0, artifact_mass = 0.0, artifact_inertia = 0.0;
  double artifact_cm_depth = 0.0;
  double sensor_mesh_area = 0.0, sensor_area = 0.0;
  double spring_modulus = 0.0, spring_stiffness = 0.0;
  int pin_nodes = 0, guide_nodes = 0;
  bool frictional_pin = false;   // the artifact's pin has friction
  double clamp_stiffness = 0.0;  // N m/rad, the Fixed artifact's pin clamp (0: free)
  double clamp_damping = 0.0;    // N m s/rad
  std::vector<RigPart> parts;    // material, mass and elements of each part
};

// The raw simulated histories at the output samples (trial time).
struct RawHistories {
  std::vector<double> t;
  std::vector<double> impactor_velocity;  // V_i, m/s
  std::vector<double> angle_deg;          // theta_a, eq. 3.7
  std::vector<double> pressure_kpa;       // P_raw, eq. 3.8 (the DCR's contact output), kPa
  std::vector<double> contact_force;      // F_c . d on the sensor, mean over each interval, N
  std::vector<double> pin_angle;          // rad (free artifact)
};

struct RigRunResult {
  RunSummary summary;
  RunWindow window;
  RigModelFacts model;
  RawHistories raw;
  RigChannels channels;      // as the sensors read them, at the measured timestamps if any
  int open_loop_masked = 0;  // F_in samples the pressure rule set to 0
};

struct RigSetup {
  const RigCaseTable& cases;
  const RigGeometry& geometry;
};

// Throws std::invalid_argument / RigInputError for input a user can fix (see run_window.hpp,
// rig_model.hpp), MeshError when Gmsh fails.
RigRunResult run_rig(const RigSetup& setup, const RigCase& c, const RigRunRequest& request);

// The trial times of `series` inside [t0, t1].
std::vector<double> times_within(const TimeSeries& series, double t0, double t1);

}  // namespace ccm::rig
