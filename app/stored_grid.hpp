// The grid file a study store keeps (db::StudyStore::load_grid), parsed, for the commands that
// state the study's modelling choices (recommend, study status); and the note to print when
// the store does not keep it.
#pragma once

#include <optional>

#include "db/store/study_store.hpp"
#include "study/grid/grid_file.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm {

inline std::optional<study::GridSpec> stored_grid_spec(const db::StudyStore& store) {
  const auto grid = store.load_grid();
  if (!grid) return std::nullopt;
  return study::parse_grid(grid->text, grid->source);
}

inline constexpr const char* kNoStoredGrid =
    "modelling choices not recorded: the store predates schema step 5; run `ccm study run "
    "GRID --db FILE` on the same grid file once (nothing is rerun) to record them";

}  // namespace ccm
