// The units a bench test's channels may be recorded in, each with its factor to SI (value in SI
// = value x factor). Names as engineers write them in column headers and data sheets.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace ccm::bench {

// The factor to SI of `unit`, or none when ccm does not know it.
std::optional<double> si_factor(std::string_view unit);

// The SI unit `unit` converts to ("g": "m/s^2"); empty when ccm does not know it.
std::string_view si_unit(std::string_view unit);

// Every unit known, for the did-you-mean of a mistyped one.
std::vector<std::string_view> known_units();

}  // namespace ccm::bench
