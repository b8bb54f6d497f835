// The contact between the rod's tip and the envelope, and the sensor pressure it reads (eq. 3.8,
// P_raw = |F_c . d| / A_p, F_c the mean over each output interval, A_p the patch's mesh area):
//   exact (the thesis's): the DCR pair of the rig's scene (rig_scene.hpp), built by the scene
//     path, F_c from its contact output on the sensor patch
//     (engine/contact/dcr/contact_output.hpp);
//   through the sensor mat (mat_stiffness > 0): the mat's Hunt-Crossley law between the tip's
//     face and the sensor's footprint under it (sensor_mat.hpp), F_c its force.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/observe/history.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "rig_models/geometry/rig_geometry.hpp"
#include "rig_models/geometry/rig_model.hpp"
#include "rig_models/sim/run_parameters.hpp"
#include "rig_models/sim/sensor_mat.hpp"

namespace ccm::rig {

class RigContact {
 public:
  // The mat when parameters.mat_stiffness > 0, on `mesh` (the run's); else the DCR pair's output
  // (`dcr`, not owned: the scene run's contact model).
  RigContact(const RigModel& rig, const ModelMesh& mesh, const RigParameters& table,
             const RunParameters& parameters, const HistorySource* dcr);

  void attach(RunOptions& options);  // the mat among the loads (the DCR is the run's already)
  // The sensor's raw pressure over the output interval that ends at `s` [Pa]; closes it.
  double sensor_pressure(const State& s);
  bool exact() const { return dcr_ != nullptr; }

 private:
  const HistorySource* dcr_ = nullptr;
  std::unique_ptr<SensorMat> mat_;
  size_t pressure_at_ = 0;
  std::vector<double> row_;
  double sensor_area_ = 0.0;
};

}  // namespace ccm::rig
