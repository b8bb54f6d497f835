// Time stamps of every output: RFC 3339 UTC with milliseconds (also a TOML offset date-time),
// e.g. 2026-11-22T05:10:00.123Z; they sort as text in time order.
#pragma once

#include <chrono>
#include <string>

namespace ccm {

std::string utc_timestamp(std::chrono::system_clock::time_point t);
inline std::string utc_timestamp_now() { return utc_timestamp(std::chrono::system_clock::now()); }

}  // namespace ccm
