#include "reports/figures/rig_section.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "reports/figures/rig_channel_figures.hpp"
#include "reports/figures/rig_tables.hpp"

namespace ccm::reports {

Section rig_section(const RigReportData& rig) {
  Section s{.id = "rig", .title = "Benchtop rig"};
  if (rig.runs.empty()) {
    s.paragraphs.push_back(kNoRigRunText);
  } else {
    s.paragraphs.push_back(fmt::format(
        "{} rig simulation{} (the latest `ccm rig run` per case and drive) against the measured "
        "trials stored with {}: per channel the simulation, the trials and their mean +/- one "
        "standard deviation, and the contact onset and end.",
        rig.runs.size(), rig.runs.size() == 1 ? "" : "s", rig.runs.size() == 1 ? "it" : "them"));
    for (const db::StoredRigRun& run : rig.runs)
      for (Figure& f : rig_channel_figures(run)) s.figures.push_back(std::move(f));
    s.tables.push_back(rig_metrics_table(rig));
    s.tables.push_back(rig_runs_table(rig));
  }
  if (!rig.calibrations.empty()) s.tables.push_back(rig_calibration_table(rig));
  const bool any_left_out = std::any_of(
      rig.calibrations.begin(), rig.calibrations.end(), [](const db::RigCalibrationRecord& k) {
        return !k.predictions.empty() ||
               std::any_of(k.trials.begin(), k.trials.end(),
                           [](const db::RigCalibrationTrial& t) { return !t.fitted; });
      });
  if (any_left_out) s.tables.push_back(rig_prediction_table(rig));
  return s;
}

}  // namespace ccm::reports
