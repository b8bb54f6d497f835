// After `ccm rig calibrate` has found its best parameters, how far to trust them:
//   - the spread of each parameter (rig_models/calibrate/parameter_profile.hpp: the objective's
//     curvature along it and the half-width of a 5 % rise), with a warning for a parameter that
//     ended on a bound of its range (its best may lie beyond);
//   - the score of the calibrated parameters on trials of the fitted case left out of the fit
//     (--fit-trials: the search fits some trials, the others are scored with the start's and the
//     best run, the same runs);
//   - the score of the calibrated parameters on cases left out of the fit (--predict): each run
//     with the starting and with the calibrated parameters, scored on its own trials. One
//     parameter set per configuration (R/F impactor x X/F artifact): a predicted case must share
//     the fitted case's configuration, and every tuned parameter must apply to it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/rig_commands.hpp"
#include "app/rig_inputs.hpp"
#include "app/rig_output.hpp"
#include "app/rig_runner.hpp"
#include "db/store/rig_store.hpp"
#include "rig_models/calibrate/bounded_search.hpp"
#include "rig_models/calibrate/parameter_profile.hpp"

namespace ccm {

struct PredictionCase {
  // The calibration's, for this case; --start and --end (trial times of the fitted case) moved
  // by the difference of the two cases' measured contact onsets (their driving trials').
  RigCommonArgs args;
  RigInputs inputs;
};

// `p` with the searched parameters set to `x`.
rig::RunParameters with_values(rig::RunParameters p, const std::vector<rig::SearchParameter>& s,
                               const std::vector<double>& x);

// One run of the case per search point (the parameters `s` set to its values), the k-th
// labelled label(k): what run_rig_batch takes.
std::vector<RigRunJob> runs_at(const RigInputs& in, const RigCommonArgs& args,
                               const std::vector<rig::SearchParameter>& s,
                               const std::vector<std::vector<double>>& points,
                               const std::function<std::string(size_t)>& label);

// Reads and checks every --predict case before any run. Throws std::invalid_argument (a case
// of another configuration, a parameter that does not apply, the fitted case itself) or
// rig::RigInputError (its files).
std::vector<PredictionCase> read_prediction_cases(const RigCalibrateArgs& args,
                                                  const RigInputs& fitted,
                                                  const std::vector<rig::SearchParameter>& params);

// The trials --fit-trials names (empty without it: every scored trial is fitted). Throws
// std::invalid_argument unless each is one of the trials the run is scored on (in.scored) and
// at least one scored trial is left out.
std::vector<int> read_fit_trials(const RigCalibrateArgs& args, const RigInputs& in);

// What the search minimises: the objective over the fitted trials (rig_objective.hpp), over every
// scored trial when `fit` is empty; none when the run was not compared.
std::optional<double> fitted_objective(const RigRunOutcome& o, const std::vector<int>& fit);

// Per scored trial, fitted or left out, the objective of the starting and of the best run over
// that trial alone.
std::vector<db::RigCalibrationTrial> trial_scores(const RigInputs& in, const std::vector<int>& fit,
                                                  const RigRunOutcome& before,
                                                  const RigRunOutcome& after);
// Prints them, and the left-out trials' objective together (nothing without --fit-trials).
void print_trial_scores(const std::vector<db::RigCalibrationTrial>& trials,
                        const RigRunOutcome& before, const RigRunOutcome& after);

// The spread of each parameter at `best` (2-3 runs of the fitted case each, scored on the fitted
// trials `fit`; up to `jobs` at once), and a warning on stderr for each that ended on a bound.
std::vector<rig::ParameterSpread> profile_calibration(
    const RigInputs& in, const RigCommonArgs& args, const std::vector<rig::SearchParameter>& params,
    const std::vector<int>& fit, const std::vector<double>& best, double best_objective, int jobs);
void print_spread(const std::vector<rig::ParameterSpread>& spread);

// Each predicted case run with the starting and with the calibrated parameters (up to `jobs`
// runs at once).
struct Prediction {
  const PredictionCase* predicted = nullptr;
  RigRunOutcome start, calibrated;
};
std::vector<Prediction> run_predictions(const std::vector<PredictionCase>& cases,
                                        const std::vector<rig::SearchParameter>& params,
                                        const std::vector<double>& best, int jobs);
void print_predictions(const std::vector<Prediction>& predictions);

}  // namespace ccm
