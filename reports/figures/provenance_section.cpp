#include "reports/figures/provenance_section.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <array>

#include "db/store/provenance.hpp"
#include "records/provenance/version.hpp"

namespace ccm::reports {
namespace {

std::string joined(const std::vector<std::string>& items) {
  if (items.empty()) return "-";
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : "; ") + i;
  return out;
}

std::string host_name() {
  std::array<char, 256> name{};
  return gethostname(name.data(), name.size() - 1) == 0 ? std::string(name.data()) : "unknown";
}

}  // namespace

ReportStamp current_stamp() { return {version_string(), db::utc_now(), host_name()}; }

Section provenance_section(const ReportData& data, const ReportStamp& stamp) {
  const StudyProvenance& p = data.provenance;
  Table t{.id = "provenance",
          .caption = "Where the results and this report come from.",
          .header = {"item", "value"},
          .rows = {{"study", p.study_name},
                   {"study database", data.database},
                   {"study created", p.created_at},
                   {"grid file hash", p.grid_hash},
                   {"runs: first started", p.first_run_started_at},
                   {"runs: last ended", p.last_run_ended_at},
                   {"runs: ccm version (git hash)", joined(p.ccm_versions)},
                   {"runs: machines", joined(p.hosts)},
                   {"runs: scene content hashes", joined(p.scene_hashes)},
                   {"report: ccm version", stamp.ccm_version},
                   {"report: generated", stamp.generated_at},
                   {"report: machine", stamp.host}}};
  Section s{.id = "provenance", .title = "Provenance"};
  s.tables.push_back(std::move(t));
  return s;
}

}  // namespace ccm::reports
