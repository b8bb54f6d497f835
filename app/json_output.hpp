// The --json output of the subcommands (nlohmann_json): one JSON document on stdout, the
// field names those of the files the values come from (case file, store columns). Errors still
// go to stderr as text, with the same exit codes.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "db/store/study_store.hpp"
#include "rig_models/cases/rig_case.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm {

// Prints the document, indented by 2, and a newline.
void print_json(const nlohmann::json& document);

// The study's modelling choices (study/recommend/modelling_choices.hpp) at the axis levels
// given (every level of a swept choice when none): {"recorded": false, "note": ...} for a
// store that kept no grid file.
nlohmann::json modelling_choices_json(const std::optional<study::GridSpec>& grid,
                                      const study::AxisLevels& levels_used = {});

// `ccm study status --json`: the store, each point's state and runs, the totals per state and
// the modelling choices.
nlohmann::json study_status_json(const db::StudyStore& store,
                                 const std::vector<db::PointStatus>& points,
                                 const std::optional<study::GridSpec>& grid);

// `ccm rig list --json`: the case file's rig, drive and simulation parameters (each
// {value, unit, source}, named as in the case file) and its cases.
nlohmann::json case_table_json(const rig::RigCaseTable& table);

}  // namespace ccm
