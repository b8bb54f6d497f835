// The rig case table as text, for `ccm rig list`: the shared rig parameters with unit and
// source, then one row per case of thesis Table 3.2.
#pragma once

#include <string>

#include "rig_models/cases/rig_case.hpp"

namespace ccm::rig {

std::string format_case_table(const RigCaseTable& table);

}  // namespace ccm::rig
