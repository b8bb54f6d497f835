// `ccm validate`'s records in a ccm store (docs/store.md, schema step 9): one row per validation
// of a scene against a bench test, its scores per channel and trial (and the trials' mean), each
// channel's compared curves, and the whole validation.json. One transaction per record.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "db/sqlite/connection.hpp"

namespace ccm::db {

struct ValidationScoreRow {
  std::string channel;
  std::string against;  // a trial's file name, or "mean"
  bool left_out = false;
  long long samples = 0;
  std::optional<double> nrmse;
  double peak_measured = 0.0, peak_simulated = 0.0, peak_time_error = 0.0;
  double corridor = 0.0, phase = 0.0, magnitude = 0.0, slope = 0.0, rating = 0.0;
  std::string grade;
};

struct ValidationCurvesRow {
  std::string channel;
  std::string unit;        // the SI unit of the curves
  std::string curves_csv;  // time,simulated,mean,low,high
};

struct ValidationRow {
  std::string scene, data;
  std::string fitted;    // the fit's parameters (JSON); empty without --fit
  std::string document;  // validation.json
  std::vector<ValidationScoreRow> scores;
  std::vector<ValidationCurvesRow> curves;
  std::string recorded_at;  // filled on reading
};

// Opens (migrating) the store at `file`, which must exist, and adds the validation; returns its
// id. Throws StoreError naming the file when it is not a ccm store or is newer than this ccm.
long long record_validation(const std::filesystem::path& file, const ValidationRow& row);

// Every validation of an open store, oldest first; none for a store before schema step 9.
std::vector<ValidationRow> load_validations(Connection& connection);

}  // namespace ccm::db
