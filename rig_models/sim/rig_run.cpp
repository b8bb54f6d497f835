#include "rig_models/sim/rig_run.hpp"

#include <fmt/format.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/bc/pin_joint.hpp"
#include "engine/bc/track_friction.hpp"
#include "rig_models/drive/hanging_weight_drive.hpp"
#include "rig_models/drive/open_loop_drive.hpp"
#include "rig_models/geometry/rig_model.hpp"
#include "rig_models/post/rig_channels.hpp"
#include "rig_models/signal/resample.hpp"
#include "rig_models/sim/rig_contact.hpp"
#include "rig_models/sim/rig_scene.hpp"
#include "run/scene/scene_run.hpp"

namespace ccm::rig {
namespace {

HangingWeightSettings weight_settings(const RigCaseTable& t, double gravity) {
  HangingWeightSettings s;
  s.weight_mass = t.rig.hanging_mass.value;
  s.gravity = gravity;
  s.string_stiffness = t.drive.string_stiffness.value;
  s.string_damping = t.drive.string_damping.value;
  return s;
}

// F_in of the open-loop drive on the simulation's clock (t = 0 at the window's start).
std::vector<std::pair<double, double>> shifted_force(const OpenLoopDrive& d, double start) {
  std::vector<std::pair<double, double>> points;
  for (size_t k = 0; k < d.force_n.t.size(); ++k)
    points.emplace_back(d.force_n.t[k] - start, d.force_n.value[k]);
  return points;
}

// What the sampler keeps at every output sample.
struct Samples {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> v_front, v_back;
  std::vector<double> u_y, x_z, pressure_pa, pin_angle;
};

RigModelFacts facts_of(const RigModel& rig, const Model& model, const RigCaseTable& table,
                       const JointSpec& pin) {
  RigModelFacts f;
  f.n_nodes = model.mesh.n_nodes();
  f.n_elements = model.mesh.n_elements();
  f.impactor_mass = rig.impactor_mass;
  f.artifact_mass = rig.artifact_mass;
  f.artifact_inertia = rig.artifact_inertia;
  f.artifact_cm_depth = rig.artifact_cm_depth;
  f.sensor_mesh_area = rig.sensor_mesh_area;
  f.sensor_area = table.rig.sensor_area.value;
  f.spring_modulus = rig.spring_modulus;
  f.spring_stiffness = rig.spring_stiffness;
  f.pin_nodes = static_cast<int>(rig.pin_nodes.size());
  f.guide_nodes = static_cast<int>(rig.guide_nodes.size());
  f.frictional_pin = pin.mu_s > 0.0 || pin.mu_k > 0.0;
  f.clamp_stiffness = pin.stiffness;
  f.clamp_damping = pin.damping;
  f.parts = rig.parts;
  return f;
}

// Where the rig's scene (rig_scene.hpp) put its joint `name`: run.scene.joints and run.joints.
size_t joint_index(const SceneRun& run, std::string_view name) {
  for (size_t i = 0; i < run.scene.joints.size(); ++i)
    if (run.scene.joints[i].name == name) return i;
  throw std::logic_error("the rig's scene has no joint " + std::string(name));
}

// The raw channels (3.3.3): V_i of the two pearls, theta_a (3.7), and the DCR's sensor pressure
// P_raw = |F_c . d| / A_p (3.8, one implementation: the engine's contact output, its F_c the
// mean over each output interval of the momentum the contact gave the sensor's nodes, A_p the
// patch's mesh area, the area F_c is gathered over); the contact
// force column is F_c . d = P_raw A_p.
RawHistories raw_histories(const Samples& s, const Vec3& track, double sensor_mesh_area) {
  RawHistories r;
  r.t = s.t;
  r.impactor_velocity = impactor_velocity(s.t, s.v_front, s.v_back, track).value;
  r.angle_deg = artifact_angle_deg(s.t, s.u_y, s.x_z).value;
  r.pressure_kpa.resize(s.t.size());
  r.contact_force.resize(s.t.size());
  for (size_t k = 0; k < s.t.size(); ++k) {
    r.pressure_kpa[k] = 1e-3 * s.pressure_pa[k];
    r.contact_force[k] = s.pressure_pa[k] * sensor_mesh_area;
  }
  r.pin_angle = s.pin_angle;
  return r;
}

// The channels as the sensors read them; at the trial's timestamps when a trial drives the run.
RigChannels sensed_channels(const RawHistories& raw, const RigCaseTable& table,
                            const MeasuredTrial* trial) {
  RigChannels c;
  if (raw.t.size() < 2) return c;
  const TimeSeries V{raw.t, raw.impactor_velocity}, theta{raw.t, raw.angle_deg};
  const TimeSeries P_raw{raw.t, raw.pressure_kpa};
  const PressureSensor sensor{table.rig.sensor_deadband.value, table.rig.low_pass_cutoff.value};
  const double t0 = raw.t.front(), t1 = raw.t.back();
  if (!trial) {
    c.impactor_velocity_mps = V;
    c.artifact_angle_deg = theta;
    c.pressure_kpa = sensed_pressure_kpa(P_raw, sensor, raw.t);
    return c;
  }
  c.impactor_velocity_mps = sample_at(V, times_within(trial->impactor_velocity_mps, t0, t1));
  c.artifact_angle_deg = sample_at(theta, times_within(trial->artifact_angle_deg, t0, t1));
  c.pressure_kpa = sensed_pressure_kpa(P_raw, sensor, times_within(trial->pressure_kpa, t0, t1));
  return c;
}

}  // namespace

std::vector<double> times_within(const TimeSeries& series, double t0, double t1) {
  std::vector<double> out;
  for (double t : series.t)
    if (t >= t0 && t <= t1) out.push_back(t);
  return out;
}

RigRunResult run_rig(const RigSetup& setup, const RigCase& c, const RigRunRequest& req) {
  const RigCaseTable& table = setup.cases;
  const RunParameters& par = req.parameters;
  const double gravity = setup.geometry.gravity.value;
  RigRunResult out;
  out.window = run_window(table, c, {req.drive, req.trial, req.start, req.end},
                          weight_settings(table, gravity), track_friction_of(table, par, gravity));
  const RunWindow& w = out.window;
  RigModelRequest mr;
  mr.impactor = c.impactor;
  mr.artifact = ArtifactKind::free;  // on the pin joint: free, or Fixed on its clamp
  mr.gap = w.gap;
  mr.mesh_scale = req.mesh_scale;
  mr.spring_stiffness = par.spring_stiffness;
  RigModel rig = build_rig_model(setup.geometry, table.rig, mr);
  for (int n : rig.impactor_nodes)
    rig.model.initial_velocity[static_cast<size_t>(n)] = w.initial_velocity * rig.track;

  // The run, by the scene path (run/scene/scene_run.hpp): joints and the DCR pair.
  RigSceneRequest sr;
  sr.end_time = w.end - w.start;
  sr.output_interval = table.simulation.output_interval.value;
  sr.gravity = gravity;
  sr.friction_from =
      req.drive == DriveKind::open_loop && w.measured_onset ? *w.measured_onset - w.start : 0.0;
  sr.contact = !(par.mat_stiffness > 0.0);
  if (req.drive == DriveKind::open_loop) {
    const OpenLoopDrive d =
        open_loop_drive(*req.trial, rig.impactor_mass, table.drive.velocity_smoothing.value);
    out.open_loop_masked = d.masked_samples;
    sr.drive_force = shifted_force(d, w.start);
  }
  Scene scene = rig_scene(rig, setup.geometry, table, c, par, sr, setup.geometry.source);
  SceneRun run = assemble_scene_run(std::move(scene), std::move(rig.model));
  Model& model = run.model;

  std::unique_ptr<HangingWeightDrive> weight;
  if (req.drive == DriveKind::physical) {
    weight = std::make_unique<HangingWeightDrive>(model.mesh, rig.drive_surface, rig.impactor_nodes,
                                                  rig.track, weight_settings(table, gravity));
  }
  const size_t pin = joint_index(run, kPinJoint);
  const auto& pin_joint = dynamic_cast<const PinJoint&>(*run.joints[pin]);
  RigContact contact(rig, model.mesh, table.rig, par,
                     run.contact.histories.empty() ? nullptr : run.contact.histories.front());

  Samples s;
  RunOptions opt = scene_run_options(run, nullptr);
  contact.attach(opt);
  if (weight) opt.loads.push_back(weight.get());
  opt.progress = req.progress;
  const auto angle = static_cast<size_t>(rig.angle_node);
  opt.on_sample = [&](const State& st) {
    s.t.push_back(st.t + w.start);
    s.v_front.push_back(st.v[static_cast<size_t>(rig.pearl_front)]);
    s.v_back.push_back(st.v[static_cast<size_t>(rig.pearl_back)]);
    s.u_y.push_back(st.x[angle].y() - st.X[angle].y());
    s.x_z.push_back(rig.pin_point.z() - st.x[angle].z());  // current distance below the pin
    s.pressure_pa.push_back(contact.sensor_pressure(st));
    s.pin_angle.push_back(pin_joint.angle());
  };
  if (req.instrument) req.instrument(model, opt);
  out.summary = run_explicit(model, opt);
  out.model = facts_of(rig, model, table, run.scene.joints[pin]);
  out.raw = raw_histories(s, rig.track, rig.sensor_mesh_area);
  out.channels = sensed_channels(out.raw, table, req.trial);
  return out;
}

}  // namespace ccm::rig
