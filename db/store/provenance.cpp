#include "db/store/provenance.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <ctime>

namespace ccm::db {

RunProvenance current_provenance(const std::string& grid_hash, int ranks, int jobs) {
  RunProvenance p;
  p.ccm_version = CCM_VERSION;
  p.git_hash = CCM_GIT_HASH;
  p.grid_hash = grid_hash;
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) == 0) p.host = host.data();
  if (p.host.empty()) p.host = "unknown";
  p.pid = static_cast<long>(getpid());
  p.ranks = ranks;
  p.jobs = jobs;
  return p;
}

std::string utc_now() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t secs = std::chrono::system_clock::to_time_t(now);
  std::tm tm{};
  gmtime_r(&secs, &tm);
  const auto ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:03}Z", tm.tm_year + 1900, tm.tm_mon + 1,
                     tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, ms);
}

}  // namespace ccm::db
