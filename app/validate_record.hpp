// Recording a `ccm validate` in a ccm store (db/store/validation_store.hpp) for `ccm report`.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "app/bench_run.hpp"
#include "app/validate_command.hpp"

namespace ccm {

// The store a validation is recorded in: --db, else the main job's; checked before any run (a
// file that is not a ccm store, or of a newer ccm, is refused: db::StoreError).
std::filesystem::path validation_store(const ValidateArgs& args);

// Records it when the store exists; returns what to tell the user.
std::string record_validation_result(const std::filesystem::path& store, const ValidateArgs& args,
                                     const BenchData& data, const bench::BenchScores& scores,
                                     const std::set<std::string>& left_out,
                                     const nlohmann::json& document);

}  // namespace ccm
