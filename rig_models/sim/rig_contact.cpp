#include "rig_models/sim/rig_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "rig_models/sim/rig_scene.hpp"

namespace ccm::rig {

RigContact::RigContact(const RigModel& rig, const ModelMesh& mesh, const RigParameters& table,
                       const RunParameters& parameters, const HistorySource* dcr)
    : sensor_area_(rig.sensor_mesh_area) {
  if (parameters.mat_stiffness > 0.0) {
    mat_ = std::make_unique<SensorMat>(
        mesh, rig.tip_face, rig.mat_footprint, rig.track,
        SensorMatLaw{parameters.mat_stiffness, table.mat_exponent.value, parameters.mat_damping});
    return;
  }
  if (!dcr) throw std::logic_error("rig contact: the exact contact needs the scene's DCR pair");
  dcr_ = dcr;
  const std::vector<std::string> columns = dcr_->history_columns();
  const std::string pressure = fmt::format("contact.{}.pressure", kSensorSurface);
  const auto it = std::find(columns.begin(), columns.end(), pressure);
  if (it == columns.end()) throw std::logic_error("rig contact: no column " + pressure);
  pressure_at_ = static_cast<size_t>(it - columns.begin());
}

void RigContact::attach(RunOptions& options) {
  if (mat_) options.loads.push_back(mat_.get());
}

double RigContact::sensor_pressure(const State& s) {
  if (mat_) return mat_->mean_force_since_last() / sensor_area_;
  row_.clear();
  dcr_->append_history(s, row_);  // closes the output interval of the contact output
  return row_.at(pressure_at_);
}

}  // namespace ccm::rig
