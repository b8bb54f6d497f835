// Conversions between stored text columns and the store's types (internal to db/store).
#pragma once

#include <map>
#include <string>

#include "db/sqlite/statement.hpp"
#include "db/store/study_store.hpp"

namespace ccm::db {

RunStatus run_status_from_text(const std::string& text);
study::ImpactModel model_from_text(const std::string& text);

// A GridPoint from the columns point_index, content_hash, modulus_ratio, length_ratio,
// kinetic_energy, other_axes starting at `first` (content_hash is skipped).
// "name=value;name=value" (db/store/point_key.hpp other_axes_text) back to a map.
std::map<std::string, double> other_axes_from_text(const std::string& text);

study::GridPoint point_from_row(const Statement& row, int first);

}  // namespace ccm::db
