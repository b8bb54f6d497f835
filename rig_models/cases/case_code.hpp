// The code of a benchtop case (thesis Table 3.2): impactor R (rigid) or F (flexible), artifact
// X (fixed) or F (free), target impact speed in cm/s as three digits: RX025 ... FF100.
#pragma once

#include <string_view>

namespace ccm::rig {

// True for the 12 codes of Table 3.2.
constexpr bool is_case_code(std::string_view code) {
  if (code.size() != 5) return false;
  if (code[0] != 'R' && code[0] != 'F') return false;
  if (code[1] != 'X' && code[1] != 'F') return false;
  const std::string_view speed = code.substr(2);
  return speed == "025" || speed == "050" || speed == "100";
}

}  // namespace ccm::rig
