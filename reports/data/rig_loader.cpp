#include "reports/data/rig_loader.hpp"

namespace ccm::reports {

RigReportData load_rig_report_data(db::Connection& connection) {
  RigReportData data;
  for (long long id : db::latest_rig_run_ids(connection, "run"))
    data.runs.push_back(db::load_rig_run(connection, id));
  data.calibrations = db::load_rig_calibrations(connection);
  return data;
}

}  // namespace ccm::reports
