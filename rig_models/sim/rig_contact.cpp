#include "rig_models/sim/rig_contact.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ccm::rig {
namespace {

// The DCR's sensor pressure column (engine/contact/dcr/contact_output.hpp, thesis eq. 3.8).
constexpr const char* kSensorSurface = "envelope/sensor";

}  // namespace

RigContact::RigContact(const RigModel& rig, const RigGeometry& geometry, const RigParameters& table,
                       const RunParameters& parameters)
    : sensor_area_(rig.sensor_mesh_area) {
  if (parameters.mat_stiffness > 0.0) {
    mat_ = std::make_unique<SensorMat>(
        rig.model.mesh, rig.tip_face, rig.mat_footprint, rig.track,
        SensorMatLaw{parameters.mat_stiffness, table.mat_exponent.value, parameters.mat_damping});
    return;
  }
  dcr::DcrSettings contact;
  contact.surfaces = rig.contact_surfaces;
  contact.friction = geometry.contact.friction.value;
  contact.restitution = geometry.contact.restitution.value;
  contact.output.force_axis = rig.track;
  contact.output.sensors = {kSensorSurface};
  dcr_ = std::make_unique<dcr::DcrContact>(rig.model.mesh, contact, rig.model.bcs.fixed_nodes);
  const std::vector<std::string> columns = dcr_->history_columns();
  const std::string pressure = fmt::format("contact.{}.pressure", kSensorSurface);
  pressure_at_ =
      static_cast<size_t>(std::find(columns.begin(), columns.end(), pressure) - columns.begin());
}

void RigContact::attach(RunOptions& options) {
  if (dcr_)
    options.contact = dcr_.get();
  else
    options.loads.push_back(mat_.get());
}

double RigContact::sensor_pressure(const State& s) {
  if (mat_) return mat_->mean_force_since_last() / sensor_area_;
  row_.clear();
  dcr_->append_history(s, row_);  // closes the output interval of the contact output
  return row_.at(pressure_at_);
}

}  // namespace ccm::rig
