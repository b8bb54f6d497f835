// The three rig channels from sampled simulation histories (thesis 3.3.3), on plain vectors:
// impactor velocity V_i, artifact angle theta_a (3.7) and sensor pressure P, the latter from
// the DCR's contact output (eq. 3.8 is computed once, in engine/contact/dcr/contact_output.hpp)
// passed through the sensor model (deadband, 64 Hz low-pass) and sampled at the measurement's
// timestamps.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "rig_models/signal/time_series.hpp"

namespace ccm::rig {

// V_i(t) = (v_a(t) + v_b(t)) . d / 2: the mean velocity of the two tracked impactor nodes
// (the two Vicon pearls, Fig. 3-6/3-20) along the unit track direction d (normalised here).
TimeSeries impactor_velocity(std::span<const double> t, std::span<const Eigen::Vector3d> v_a,
                             std::span<const Eigen::Vector3d> v_b,
                             const Eigen::Vector3d& track_direction);

// theta_a(t) = (180 / pi) atan(u_y(t) / x_z(t))   (thesis eq. 3.7), degrees: u_y the node's
// displacement along the impactor motion, x_z its distance from the centre of rotation (> 0).
TimeSeries artifact_angle_deg(std::span<const double> t, std::span<const double> u_y,
                              std::span<const double> x_z);

// What the pressure sensor reads (thesis 3.3.3, docs/equations.md "Rig post-processing"): the
// deadband on P_raw, then the first-order Butterworth low-pass at the cutoff (bilinear, at
// the simulation's uniform output rate), then sampled at the measurement times.
struct PressureSensor {
  double deadband_kpa = 0.0;
  double cutoff_hz = 64.0;
};
TimeSeries sensed_pressure_kpa(const TimeSeries& raw_kpa, const PressureSensor& sensor,
                               std::span<const double> measurement_times);

}  // namespace ccm::rig
