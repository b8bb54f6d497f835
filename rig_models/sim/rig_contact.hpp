// The contact between the rod's tip and the envelope, and the sensor pressure it reads (eq. 3.8,
// P_raw = |F_c . d| / A_p, F_c the mean over each output interval, A_p the patch's mesh area):
//   exact (the thesis's): the DCR between "rod/tip" and "envelope/contact_zone", F_c from its
//     contact output on the sensor patch (engine/contact/dcr/contact_output.hpp);
//   through the sensor mat (mat_stiffness > 0): the mat's Hunt-Crossley law between the tip's
//     face and the sensor's footprint under it (sensor_mat.hpp), F_c its force.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "rig_models/geometry/rig_geometry.hpp"
#include "rig_models/geometry/rig_model.hpp"
#include "rig_models/sim/run_parameters.hpp"
#include "rig_models/sim/sensor_mat.hpp"

namespace ccm::rig {

class RigContact {
 public:
  RigContact(const RigModel& rig, const RigGeometry& geometry, const RigParameters& table,
             const RunParameters& parameters);

  void attach(RunOptions& options);  // the contact model, or the mat among the loads
  // The sensor's raw pressure over the output interval that ends at `s` [Pa]; closes it.
  double sensor_pressure(const State& s);
  bool exact() const { return dcr_ != nullptr; }

 private:
  std::unique_ptr<dcr::DcrContact> dcr_;
  std::unique_ptr<SensorMat> mat_;
  size_t pressure_at_ = 0;
  std::vector<double> row_;
  double sensor_area_ = 0.0;
};

}  // namespace ccm::rig
