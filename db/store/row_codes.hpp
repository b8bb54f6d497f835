// Conversions between stored text columns and the store's types (internal to db/store).
#pragma once

#include <string>

#include "db/sqlite/statement.hpp"
#include "db/store/study_store.hpp"

namespace ccm::db {

RunStatus run_status_from_text(const std::string& text);
study::ImpactModel model_from_text(const std::string& text);

// A GridPoint from the columns point_index, content_hash, modulus_ratio, length_ratio,
// kinetic_energy, other_axes starting at `first` (content_hash is skipped).
study::GridPoint point_from_row(const Statement& row, int first);

}  // namespace ccm::db
