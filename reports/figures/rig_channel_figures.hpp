// The benchtop rig's channel figures (thesis Figs. 3-23 ... 3-37): for one stored rig run, one
// figure per channel (V_i, theta_a, P) against time, with the simulation as a line, the
// measured trials' mean +/- one sample standard deviation as a band (two trials or more), each
// trial as a thin line, and dashed vertical marks at the measured and simulated contact onset
// and end (from the pressure, rig_models/compare/channel_metrics.hpp).
#pragma once

#include <string>
#include <vector>

#include "db/store/rig_reader.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

// "RX025 (open-loop drive)": the case and drive a rig legend and table row name.
std::string rig_case_label(const db::RigRunRow& row);

// "trials 1, 2, 3"; "no trial" when empty.
std::string trials_label(const std::vector<int>& trials);

// Three figures (velocity, angle, pressure), ids fig-rig-<case>-<drive>-<channel>; a channel
// with no stored sample is left out.
std::vector<Figure> rig_channel_figures(const db::StoredRigRun& run);

}  // namespace ccm::reports
