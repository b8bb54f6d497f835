// The physical drive the thesis recommends as future work (3.3.2, 3.5): the 0.5 kg weight hangs
// from a string over a pulley and pulls the impactor along its track, and the track resists with
// friction. A state load (engine/bc/state_load.hpp) on the impactor:
//
//   string stretch  e = e_0 + s_w - u      (u: the impactor's mass-weighted mean displacement
//                                            along the track; s_w: the weight's descent;
//                                            e_0 = m_w g / k, the string taut at rest at t = 0)
//   tension         T = max(0, k e + c de/dt) while e > 0, else 0   (the string goes slack)
//   weight          m_w d^2 s_w / dt^2 = m_w g - T                   (its own explicit step)
//   track friction  F_f = -(mu N tanh(u' / v_reg) + c_t u'),  N = M_i g (the impactor's weight)
//
// T acts on the drive surface (the bracket, thesis Fig. 3-16) shared by area, F_f on every
// impactor node by its mass, both along the track. The pulley is massless and frictionless, the
// string massless. The work of T and F_f on the impactor is booked for the energy balance.
#pragma once

#include <vector>

#include "engine/bc/state_load.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm::rig {

struct HangingWeightSettings {
  double weight_mass = 0.5;         // kg
  double gravity = 9.81;            // m/s^2
  double string_stiffness = 5e3;    // N/m
  double string_damping = 5.0;      // N s/m
  double track_friction = 0.0;      // Coulomb mu
  double track_normal_force = 0.0;  // N, the impactor's weight on the track
  double track_damping = 0.0;       // N s/m
  double regularisation = 1e-3;     // m/s
};

class HangingWeightDrive : public StateLoad {
 public:
  // Throws std::invalid_argument for an empty or areal-less drive surface, no impactor node, a
  // zero track direction or a non-positive weight, stiffness or regularisation.
  HangingWeightDrive(const ModelMesh& mesh, const std::vector<Triangle>& drive_surface,
                     std::vector<int> impactor_nodes, const Vec3& track,
                     HangingWeightSettings settings);

  std::string_view name() const override { return "hanging_weight"; }
  void add_forces(const State& s, std::span<Vec3> f) override;
  void end_step(const State& s, double dt) override;
  double work() const override { return work_; }

  double tension() const { return T_; }     // N, at the last evaluation
  double friction() const { return F_f_; }  // N, along the track (negative: resisting)
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
  double s_w_ = 0.0, w_ = 0.0;      // the weight
  double T_ = 0.0, F_f_ = 0.0;      // at the last evaluation
  double u_ = 0.0, u_drive_ = 0.0;  // mean displacements at the last evaluation
  double work_ = 0.0;
};

// The distance over which the weight, from rest, brings the impactor (and itself, string taut) to
// `speed` on its track with the settings' friction: the gap that gives a target impact speed
// when no measured trial says what it was. Throws std::invalid_argument when the friction keeps
// the impactor below that speed.
double run_up_distance(const HangingWeightSettings& settings, double impactor_mass, double speed);

}  // namespace ccm::rig
