// Recording a `ccm validate` in a ccm store (db/store/validation_store.hpp) for `ccm report`.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "app/bench_run.hpp"
#include "app/validate_command.hpp"
#include "db/store/validation_store.hpp"

namespace ccm {

// The store a validation is recorded in: --db, else the main job's; checked before any run (a
// file that is not a ccm store, or of a newer ccm, is refused: db::StoreError).
std::filesystem::path validation_store(const ValidateArgs& args);

// The validation as the store keeps it (and the report and the output folder draw it).
db::ValidationRow validation_row(const ValidateArgs& args, const BenchData& data,
                                 const bench::BenchScores& scores,
                                 const std::set<std::string>& left_out,
                                 const nlohmann::json& document);

// Records it when the store exists; returns what to tell the user.
std::string record_validation_row(const std::filesystem::path& store, const db::ValidationRow& row);

// Into `out`: ratings.csv (the rating table) and one SVG per channel (the simulation against the
// trials' mean and spread), drawn by the report's own section (reports/figures/
// validation_section.hpp). Throws reports::ReportError when gnuplot is missing or fails.
void write_validation_figures(const std::filesystem::path& out, const db::ValidationRow& row);

}  // namespace ccm
