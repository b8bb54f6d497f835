// Reads a study's report data from its store: status, runs with histories, metrics, fits and
// provenance, and the benchtop rig's runs and calibrations of the same store.
#pragma once

#include "db/store/study_store.hpp"
#include "reports/data/report_data.hpp"

namespace ccm::reports {

// The store must be bound to its study (StudyStore::open_study or open_existing_study).
ReportData load_report_data(const db::StudyStore& store);

}  // namespace ccm::reports
