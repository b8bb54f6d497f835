// Reading one { value, unit, source } parameter of a rig file: the unit must be the one
// expected, the source given, the value finite and at least `minimum` (strictly above it when
// `strictly` is set). Failures are RigInputError "<file>:<line>: <key path>: <problem>".
#pragma once

#include <string_view>

#include "config/strict_table.hpp"
#include "rig_models/cases/rig_case.hpp"

namespace ccm::rig {

struct ValueBound {
  double minimum = 0.0;
  bool strictly = true;  // value > minimum; else value >= minimum
};

SourcedValue read_sourced(const StrictTable& parent, std::string_view key, std::string_view unit,
                          ValueBound bound = {});

}  // namespace ccm::rig
