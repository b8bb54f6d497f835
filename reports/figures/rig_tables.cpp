#include "reports/figures/rig_tables.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "reports/figures/rig_channel_figures.hpp"

namespace ccm::reports {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct ChannelRow {
  const char* name;  // V_i, theta_a, P
  const char* unit;
  rig::ChannelAgainstTrials rig::CaseComparison::*metrics;
};

constexpr ChannelRow kChannels[] = {{"V_i", "m/s", &rig::CaseComparison::velocity},
                                    {"theta_a", "deg", &rig::CaseComparison::angle},
                                    {"P", "kPa", &rig::CaseComparison::pressure}};

double mean_nrmse(const rig::ChannelAgainstTrials& a) {
  double sum = 0.0;
  int n = 0;
  for (const rig::ChannelComparison& c : a.per_trial)
    if (c.nrmse) sum += *c.nrmse, ++n;
  return n > 0 ? sum / n : kNaN;
}

std::string optional_cell(const std::optional<double>& v) { return v ? cell(*v) : "-"; }

std::string spread_cell(const db::RigCalibrationParameter& p) {
  if (p.half_width) return cell(*p.half_width);
  return p.curvature ? "unidentified" : "-";
}

std::string mean_cell(const std::optional<rig::Spread>& s) {
  return s ? cell(s->mean) : std::string("-");
}

}  // namespace

Table rig_metrics_table(const RigReportData& rig) {
  Table t{.id = "rig-metrics",
          .caption =
              "Each rig run against its measured trials, per channel: mean over the trials of "
              "RMSE, nRMSE (RMSE / measured range), peak error and peak-time error "
              "(simulated - measured); contact onset and duration errors come from the "
              "pressure and are given on its row.",
          .header = {"case", "channel", "unit", "trials", "RMSE [unit]", "nRMSE [-]",
                     "peak error [unit]", "peak-time error [s]", "contact onset error [s]",
                     "contact duration error [s]"}};
  for (const db::StoredRigRun& run : rig.runs) {
    const db::RigRunRecord& r = run.record;
    if (!r.comparison) continue;
    for (const ChannelRow& ch : kChannels) {
      const rig::ChannelAgainstTrials& a = (*r.comparison).*ch.metrics;
      const bool contact_row = ch.metrics == &rig::CaseComparison::pressure;
      t.rows.push_back({rig_case_label(r.row), ch.name, ch.unit, std::to_string(a.per_trial.size()),
                        cell(a.rmse.mean), cell(mean_nrmse(a)), cell(a.peak_error.mean),
                        cell(a.peak_time_error.mean),
                        contact_row ? mean_cell(r.comparison->onset_error) : "-",
                        contact_row ? mean_cell(r.comparison->duration_error) : "-"});
    }
  }
  return t;
}

Table rig_runs_table(const RigReportData& rig) {
  Table t{.id = "rig-runs",
          .caption = "The rig runs shown: the latest run (purpose 'run') per case and drive.",
          .header = {"run", "case", "parameters", "elements", "steps", "dt min [s]", "dt max [s]",
                     "wall time [s]", "max energy-balance error [-]", "verdict", "reason",
                     "compared with"}};
  for (const db::StoredRigRun& run : rig.runs) {
    const db::RigRunRow& w = run.record.row;
    t.rows.push_back({std::to_string(run.id), rig_case_label(w), w.parameters,
                      std::to_string(w.n_elements), std::to_string(w.steps),
                      optional_cell(w.dt_min), optional_cell(w.dt_max), cell(w.wall_seconds),
                      optional_cell(w.max_energy_error), w.status,
                      w.reason.empty() ? "-" : w.reason, trials_label(run.record.trials)});
  }
  return t;
}

Table rig_calibration_table(const RigReportData& rig) {
  Table t{.id = "rig-calibrations",
          .caption =
              "Every calibration: each parameter before and after, within its bounds, its "
              "spread (the half-width over which the objective rises 5 %: a sensitivity, not a "
              "confidence interval; '-' when not profiled, 'unidentified' where the objective "
              "does not rise), and the objective before and after.",
          .header = {"case", "algorithm", "parameter", "lower", "upper", "before", "after", "+-",
                     "objective", "objective before", "objective after", "evaluations", "result"}};
  for (const db::RigCalibrationRecord& k : rig.calibrations)
    for (const db::RigCalibrationParameter& p : k.parameters)
      t.rows.push_back({fmt::format("{} ({} drive)", k.case_code, k.drive), k.algorithm, p.name,
                        cell(p.lower), cell(p.upper), cell(p.initial), cell(p.final),
                        spread_cell(p), k.objective_name, cell(k.objective_before),
                        cell(k.objective_after),
                        fmt::format("{} of {}", k.evaluations, k.max_evaluations), k.result});
  return t;
}

Table rig_prediction_table(const RigReportData& rig) {
  Table t{.id = "rig-left-out",
          .caption =
              "Cases and trials left out of each calibration: a case of --predict scored on its "
              "own trials, a trial of the fitted case left out by --fit-trials scored alone; the "
              "objective with the starting and with the calibrated parameters. A calibration "
              "that generalises lowers both the fitted and these.",
          .header = {"fitted case", "parameters", "left-out case", "objective with the start",
                     "objective calibrated", "runs (rig_runs.id)"}};
  for (const db::RigCalibrationRecord& k : rig.calibrations) {
    std::string names;
    for (const db::RigCalibrationParameter& p : k.parameters)
      names += (names.empty() ? "" : ", ") + p.name;
    for (const db::RigCalibrationPrediction& p : k.predictions)
      t.rows.push_back({fmt::format("{} ({} drive)", k.case_code, k.drive), names, p.case_code,
                        optional_cell(p.objective_start), optional_cell(p.objective_calibrated),
                        fmt::format("{}, {}", p.start_run_id, p.calibrated_run_id)});
    for (const db::RigCalibrationTrial& trial : k.trials)
      if (!trial.fitted)
        t.rows.push_back({fmt::format("{} ({} drive)", k.case_code, k.drive), names,
                          fmt::format("{} trial {}", k.case_code, trial.trial),
                          optional_cell(trial.objective_before),
                          optional_cell(trial.objective_after),
                          fmt::format("{}, {}", k.before_run_id, k.after_run_id)});
  }
  return t;
}

}  // namespace ccm::reports
