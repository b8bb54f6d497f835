#include "rig_models/measurement/trial_folder.hpp"

#include <algorithm>

#include "rig_models/core/rig_error.hpp"
#include "rig_models/measurement/trial_csv.hpp"

namespace ccm::rig {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> csv_files(const fs::path& folder) {
  std::error_code ec;
  fs::directory_iterator it(folder, ec);
  if (ec) throw rig_input_error(folder, 0, "", "cannot list the folder: " + ec.message());
  std::vector<fs::path> files;
  for (const auto& entry : it)
    if (entry.path().extension() == ".csv") files.push_back(entry.path());
  if (files.empty()) throw rig_input_error(folder, 0, "", "no measured trial (*.csv) here");
  std::sort(files.begin(), files.end());  // deterministic order
  return files;
}

void add_trial(std::vector<MeasuredTrial>& trials, MeasuredTrial m) {
  if (m.trial == 0)
    throw rig_input_error(m.source, 0, "",
                          "no trial number: add '# trial: <N>' or name the file <CASE>_t<N>.csv");
  for (const MeasuredTrial& other : trials)
    if (other.trial == m.trial)
      throw rig_input_error(
          m.source, 0, "",
          fmt::format("trial {} of {} is also in {}", m.trial, m.case_code, other.source.string()));
  trials.push_back(std::move(m));
}

}  // namespace

std::map<std::string, std::vector<MeasuredTrial>> read_trial_folder(const fs::path& folder) {
  std::map<std::string, std::vector<MeasuredTrial>> by_case;
  for (const fs::path& file : csv_files(folder)) {
    MeasuredTrial m = read_trial_csv(file);
    const std::string code = m.case_code;
    add_trial(by_case[code], std::move(m));
  }
  for (auto& [code, trials] : by_case)
    std::sort(trials.begin(), trials.end(),
              [](const MeasuredTrial& a, const MeasuredTrial& b) { return a.trial < b.trial; });
  return by_case;
}

}  // namespace ccm::rig
