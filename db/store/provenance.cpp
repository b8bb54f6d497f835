#include "db/store/provenance.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <ctime>

#include "records/provenance/timestamp.hpp"
#include "records/provenance/version.hpp"

namespace ccm::db {

RunProvenance current_provenance(const std::string& grid_hash, int ranks, int jobs) {
  RunProvenance p;
  p.ccm_version = ccm_version();
  p.git_hash = git_hash();
  p.grid_hash = grid_hash;
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) == 0) p.host = host.data();
  if (p.host.empty()) p.host = "unknown";
  p.pid = static_cast<long>(getpid());
  p.ranks = ranks;
  p.jobs = jobs;
  return p;
}

std::string utc_now() { return utc_timestamp_now(); }

}  // namespace ccm::db
