// Provenance of the report (this ccm, machine, date) and of the study (grid and scene hashes,
// the ccm versions and hosts that ran it, dates).
#pragma once

#include <string>

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

struct ReportStamp {
  std::string ccm_version;     // version_string() of the ccm that wrote the report
  std::string generated_at{};  // ISO 8601 UTC
  std::string host{};          // machine that wrote the report
};

ReportStamp current_stamp();
Section provenance_section(const ReportData& data, const ReportStamp& stamp);

}  // namespace ccm::reports
