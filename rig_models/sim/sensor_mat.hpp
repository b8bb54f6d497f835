// The pressure-sensing mat between the rod's tip and the artifact as a compliant, lossy contact
// law for that pair (thesis 3.4.1 names the Pliance mat among what makes the rig softer than its
// exact-contact model). A thin foam layer pressed by a flat tip: its force follows the tip's
// indentation delta of the mat along the track d, Hunt-Crossley's law (Hunt and Crossley 1975):
//
//   delta = ((x_tip - x_mat) . d) + g_0        (area-weighted mean positions of the two faces;
//                                               g_0 the initial gap, delta > 0 when pressed)
//   F = max(0, k delta^n (1 + lambda delta'))   while delta > 0, else 0                 (SM.1)
//
// F pushes the tip back and the artifact's footprint forward, spread over each by area. The law
// is continuous at touch and release (no tension, no jump), and its loss depends on the speed
// of the blow as a foam's does: a mass m striking it at v_in leaves at v_out with
//   lambda v_in - ln(1 + lambda v_in) = -lambda v_out - ln(1 - lambda v_out)          (SM.2)
// whatever k and n (the first integral of m v dv / (1 + lambda v) = -k delta^n d delta over a
// cycle). Its work on the bodies is booked (trapezoidal in time) for the energy balance, and
// its mean force over each output interval is the sensor's F_c of eq. 3.8.
#pragma once

#include <vector>

#include "engine/bc/state_load.hpp"
#include "engine/mesh/boundary_surface.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm::rig {

struct SensorMatLaw {
  double stiffness = 0.0;  // k [N/m^n]
  double exponent = 1.0;   // n: 1 for a thin layer pressed flat
  double damping = 0.0;    // lambda [s/m]
};

class SensorMat : public StateLoad {
 public:
  // Throws std::invalid_argument when a face has no area, the track is zero, the stiffness is
  // not positive or the exponent or damping is negative (all finite).
  SensorMat(const ModelMesh& mesh, const std::vector<Triangle>& tip,
            const std::vector<Triangle>& footprint, const Vec3& track, SensorMatLaw law);

  std::string_view name() const override { return "sensor_mat"; }
  void add_forces(const State& s, std::span<Vec3> f) override;
  void end_step(const State& s, double dt) override;
  double work() const override { return work_; }

  double force() const { return F_; }            // N, at the last evaluation
  double indentation() const { return delta_; }  // m, at the last evaluation
  // The mean force since the last call (the impulse over the time) [N]; 0 over no time.
  double mean_force_since_last();

 private:
  double along(const AreaShares& face, const std::vector<Vec3>& x) const;

  AreaShares tip_, mat_;
  Vec3 d_;
  SensorMatLaw law_;
  double gap0_ = 0.0;
  double F_ = 0.0, delta_ = 0.0;
  double impulse_ = 0.0, time_ = 0.0;
  double work_ = 0.0;
};

}  // namespace ccm::rig
