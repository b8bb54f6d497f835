// The physical drive the thesis recommends as future work (3.3.2, 3.5): the 0.5 kg weight hangs
// from a string over a pulley and pulls the impactor along its track, and the track resists with
// friction (engine/bc/track_friction.hpp, beside this drive). A state load
// (engine/bc/state_load.hpp) on the impactor:
//
//   string stretch  e = e_0 + s_w - u      (u: the impactor's mass-weighted mean displacement
//                                            along the track; s_w: the weight's descent;
//                                            e_0 = m_w g / k, the string taut at rest at t = 0)
//   tension         T = max(0, k e + c de/dt) while e > 0, else 0   (the string goes slack)
//   weight          m_w d^2 s_w / dt^2 = m_w g - T                   (its own explicit step)
//
// T acts on the drive surface (the bracket, thesis Fig. 3-16) shared by area along the track.
// The pulley is massless and frictionless, the string massless. The work of T on the impactor
// is booked for the energy balance.
#pragma once

#include <vector>

#include "engine/bc/state_load.hpp"
#include "engine/bc/track_friction.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm::rig {

struct HangingWeightSettings {
  double weight_mass = 0.5;       // kg
  double gravity = 9.81;          // m/s^2
  double string_stiffness = 5e3;  // N/m
  double string_damping = 5.0;    // N s/m
};

class HangingWeightDrive : public StateLoad {
 public:
  // Throws std::invalid_argument for an empty or areal-less drive surface, no impactor node, a
  // zero track direction or a non-positive weight or stiffness.
  HangingWeightDrive(const ModelMesh& mesh, const std::vector<Triangle>& drive_surface,
                     std::vector<int> impactor_nodes, const Vec3& track,
                     HangingWeightSettings settings);

  std::string_view name() const override { return "hanging_weight"; }
  void add_forces(const State& s, std::span<Vec3> f) override;
  void end_step(const State& s, double dt) override;
  double work() const override { return work_; }

  double tension() const { return T_; }  // N, at the last evaluation
  bool slack() const { return !(T_ > 0.0); }
  double weight_descent() const { return s_w_; }  // m
  double weight_velocity() const { return w_; }   // m/s, downward

 private:
  void first_call(const State& s);

  std::vector<int> drive_nodes_;
  std::vector<double> drive_share_;  // area shares, sum 1
  std::vector<int> nodes_;           // impactor
  std::vector<double> mass_share_;   // m_j / M, filled at the first call
  Vec3 d_;
  HangingWeightSettings set_;
  bool started_ = false;
  double s_w_ = 0.0, w_ = 0.0;  // the weight
  double T_ = 0.0;              // at the last evaluation
  double u_drive_ = 0.0;        // the drive surface's displacement at the last evaluation
  double work_ = 0.0;
};

// The distance over which the weight, from rest, brings the impactor (and itself, string taut) to
// `speed` against the track's friction (its coefficients, damping and normal force; the nodes
// are not read): the gap that gives a target impact speed when no measured trial says what it
// was. Throws std::invalid_argument when the friction holds the impactor or keeps it below that
// speed.
double run_up_distance(const HangingWeightSettings& settings, const TrackFrictionSpec& track,
                       double impactor_mass, double speed);

}  // namespace ccm::rig
