// Reading the rig's case file (rig_models/cases.toml) into a typed, checked RigCaseTable.
// Every parameter is { value, unit, source }: the unit must be the one expected, the source
// must be given. The 12 cases must be those of thesis Table 3.2, each code agreeing with its
// number, impactor, artifact and target speed; free artifacts carry pivot friction, fixed
// ones not (they are held by the pin's clamp, [rig] clamp_stiffness and clamp_damping).
#pragma once

#include <filesystem>
#include <string_view>

#include "config/strict_table.hpp"
#include "rig_models/cases/rig_case.hpp"

namespace ccm::rig {

// Parses the text of a case file; `source` names it in messages ("<file>:<line>: <key>: ...").
RigCaseTable parse_case_table(std::string_view text, const std::filesystem::path& source);

// Reads and parses a case file; throws RigInputError when it cannot be read or is wrong.
RigCaseTable read_case_table(const std::filesystem::path& file);

// Sets every [rig] key that `table` gives (each { value, unit, source }, checked as in a case
// file) in `rig`, leaving the others; throws RigInputError naming the key.
void override_rig(const StrictTable& table, RigParameters& rig);

// Table 3.2's code of case `number` (1..12): RX025 RX050 RX100 FX... RF... FF...
std::string table_3_2_code(int number);

}  // namespace ccm::rig
