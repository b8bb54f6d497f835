// `ccm compare`'s records in a ccm store (docs/store.md, schema step 6): one row per comparison
// of a scene with some of its bodies rigid, with the measured answer, the study's prediction
// beside it and the whole comparison document. One transaction per record.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "db/sqlite/connection.hpp"

namespace ccm::db {

struct ComparisonRow {
  std::string scene;
  std::string deformable_hash, rigid_hash;  // content hashes of the two runs
  std::string rigid_bodies;                 // comma-separated
  std::string observables;                  // comma-separated
  double max_error = 0.0;
  std::optional<double> worst_error, cost_ratio;
  std::string answer;     // "rigid" | "deformable"; empty when unusable
  std::string unusable;   // why there is no answer
  std::string predicted;  // the study's answer; empty when none
  std::optional<bool> agrees;
  std::string prediction_note;
  std::string document;     // comparison.json
  std::string recorded_at;  // filled on reading
};

// Opens (migrating) the store at `file`, which must exist, and adds the row; returns its id.
// Throws StoreError naming the file when it is not a ccm store or is newer than this ccm.
long long record_comparison(const std::filesystem::path& file, const ComparisonRow& row);

// Every comparison of an open store, oldest first; none for a store before schema step 6.
std::vector<ComparisonRow> load_comparisons(Connection& connection);

}  // namespace ccm::db
