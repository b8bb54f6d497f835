// Reads the benchtop rig's records a report shows from its store (db/store/rig_reader.hpp):
// the latest rig run of purpose 'run' per case and drive, whole (metrics, contact, simulated
// and measured channels), and every calibration.
#pragma once

#include "db/sqlite/connection.hpp"
#include "reports/data/report_data.hpp"

namespace ccm::reports {

RigReportData load_rig_report_data(db::Connection& connection);

}  // namespace ccm::reports
