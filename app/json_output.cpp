#include "app/json_output.hpp"

#include <fmt/format.h>

#include <map>
#include <utility>

#include "app/stored_grid.hpp"
#include "study/recommend/modelling_choices.hpp"

namespace ccm {
namespace {

nlohmann::json sourced_json(const rig::SourcedValue& v) {
  return {{"value", v.value}, {"unit", v.unit}, {"source", v.source}};
}

using SourcedRows = std::initializer_list<std::pair<const char*, const rig::SourcedValue*>>;

nlohmann::json sourced_rows_json(SourcedRows rows) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, value] : rows) out[key] = sourced_json(*value);
  return out;
}

nlohmann::json rig_parameters_json(const rig::RigParameters& r) {
  return sourced_rows_json({{"hanging_mass", &r.hanging_mass},
                            {"impactor_mass", &r.impactor_mass},
                            {"spring_stiffness", &r.spring_stiffness},
                            {"spring_length", &r.spring_length},
                            {"spring_cylinder_diameter", &r.spring_cylinder_diameter},
                            {"artifact_mass", &r.artifact_mass},
                            {"artifact_inertia_pivot", &r.artifact_inertia_pivot},
                            {"clamp_stiffness", &r.clamp_stiffness},
                            {"clamp_damping", &r.clamp_damping},
                            {"mat_stiffness", &r.mat_stiffness},
                            {"mat_exponent", &r.mat_exponent},
                            {"mat_damping", &r.mat_damping},
                            {"pivot_to_sensor", &r.pivot_to_sensor},
                            {"sensor_area", &r.sensor_area},
                            {"sensor_deadband", &r.sensor_deadband},
                            {"pressure_rate", &r.pressure_rate},
                            {"angle_rate", &r.angle_rate},
                            {"velocity_rate", &r.velocity_rate},
                            {"low_pass_cutoff", &r.low_pass_cutoff},
                            {"trials_per_case", &r.trials_per_case}});
}

nlohmann::json drive_parameters_json(const rig::DriveParameters& d) {
  return sourced_rows_json({{"velocity_smoothing", &d.velocity_smoothing},
                            {"track_static_friction", &d.track_static_friction},
                            {"track_friction", &d.track_friction},
                            {"track_damping", &d.track_damping},
                            {"string_stiffness", &d.string_stiffness},
                            {"string_damping", &d.string_damping}});
}

nlohmann::json simulation_parameters_json(const rig::SimulationParameters& s) {
  return sourced_rows_json({{"lead", &s.lead},
                            {"output_interval", &s.output_interval},
                            {"after_contact", &s.after_contact}});
}

nlohmann::json case_json(const rig::RigCase& c) {
  nlohmann::json out = {{"number", c.number},
                        {"code", c.code},
                        {"target_speed", sourced_json(c.target_speed)},
                        {"impactor", rig::name_of(c.impactor)},
                        {"artifact", rig::name_of(c.artifact)},
                        {"pivot_friction", nullptr},
                        {"source", c.source}};
  if (c.pivot_friction)
    out["pivot_friction"] = {{"mu_s", c.pivot_friction->mu_s},
                             {"mu_k", c.pivot_friction->mu_k},
                             {"source", c.pivot_friction->source}};
  return out;
}

nlohmann::json run_status_json(const std::optional<db::RunStatus>& run) {
  return run ? nlohmann::json(db::to_string(*run)) : nlohmann::json("pending");
}

nlohmann::json point_json(const db::PointStatus& s) {
  const study::GridPoint& p = s.point;
  nlohmann::json axes = nlohmann::json::object();
  for (const auto& [name, value] : p.other_axes) axes[name] = value;
  return {{"index", p.index},
          {"er", p.modulus_ratio},
          {"rls", p.length_ratio},
          {"ke", p.kinetic_energy},
          {"other_axes", axes},
          {"content_hash", s.content_hash},
          {"state", db::to_string(s.state)},
          {"ccm", run_status_json(s.ccm)},
          {"rigid", run_status_json(s.rigid)},
          {"reason", s.reason}};
}

}  // namespace

void print_json(const nlohmann::json& document) { fmt::print("{}\n", document.dump(2)); }

nlohmann::json modelling_choices_json(const std::optional<study::GridSpec>& grid,
                                      const study::AxisLevels& levels_used) {
  if (!grid) return {{"recorded", false}, {"note", kNoStoredGrid}};
  nlohmann::json out = {{"recorded", true}, {"grid_file", grid->source.string()}};
  for (const study::ModellingChoice& c : study::modelling_choices(*grid, levels_used)) {
    nlohmann::json item = {{"label", c.label}, {"unit", c.unit}, {"axis", c.axis}};
    if (c.value)
      item["value"] = *c.value;
    else
      item["levels"] = c.levels;
    out[c.key] = item;
  }
  return out;
}

nlohmann::json study_status_json(const db::StudyStore& store,
                                 const std::vector<db::PointStatus>& points,
                                 const std::optional<study::GridSpec>& grid) {
  nlohmann::json list = nlohmann::json::array();
  std::map<std::string, int> totals;
  for (const db::PointStatus& s : points) {
    list.push_back(point_json(s));
    ++totals[std::string(db::to_string(s.state))];
  }
  return {{"db", store.file().string()},
          {"study", store.study_name()},
          {"points", list},
          {"totals", totals},
          {"modelling_choices", modelling_choices_json(grid)}};
}

nlohmann::json case_table_json(const rig::RigCaseTable& table) {
  nlohmann::json cases = nlohmann::json::array();
  for (const rig::RigCase& c : table.cases) cases.push_back(case_json(c));
  nlohmann::json rig = rig_parameters_json(table.rig);
  rig["spring_cylinder_modulus"] = {{"value", rig::spring_modulus(table.rig)},
                                    {"unit", "Pa"},
                                    {"source", "eq. 3.1, E_s = K_s L / A, A = pi d^2 / 4"}};
  return {{"case_file", table.source.string()},
          {"rig", rig},
          {"drive", drive_parameters_json(table.drive)},
          {"simulation", simulation_parameters_json(table.simulation)},
          {"cases", cases}};
}

}  // namespace ccm
