#include "app/rig_inputs.hpp"

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/data_paths.hpp"
#include "records/content_hash.hpp"
#include "rig_models/cases/case_code.hpp"
#include "rig_models/cases/case_file.hpp"
#include "rig_models/cases/trial_rig_file.hpp"
#include "rig_models/compare/case_comparison.hpp"
#include "rig_models/core/rig_error.hpp"
#include "rig_models/geometry/geometry_file.hpp"
#include "rig_models/measurement/trial_folder.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw rig::rig_input_error(file, 0, "", "cannot open the file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

double number_of(std::string_view text, std::string_view what) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    throw std::invalid_argument(fmt::format("{}: '{}' is not a number", what, text));
  return v;
}

// --set name=value: each a parameter that applies to this case, value >= 0.
void apply_settings(const std::vector<std::string>& set, const rig::RigCase& c,
                    rig::RunParameters& p) {
  for (const std::string& s : set) {
    const size_t eq = s.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument(fmt::format("--set {}: expected name=value", s));
    const std::string name = s.substr(0, eq);
    if (const std::string problem = rig::parameter_problem(name, c); !problem.empty())
      throw std::invalid_argument(fmt::format("--set {}: {}", s, problem));
    const double v = number_of(std::string_view(s).substr(eq + 1), "--set " + s);
    if (v < 0.0) throw std::invalid_argument(fmt::format("--set {}: must be >= 0", s));
    rig::set_parameter(p, name, v);
  }
}

// The rig the trials were measured on (--data's rig.toml): its values replace the case file's,
// and its sensor patch takes the trials' sensor area.
void apply_trial_rig(const RigCommonArgs& args, RigInputs& in) {
  if (!args.data) return;
  const double area = in.cases.rig.sensor_area.value;
  const auto file = rig::apply_trial_rig_file(*args.data, in.cases.rig);
  if (!file) return;
  in.trial_rig_text = file->text;
  if (in.cases.rig.sensor_area.value != area)
    rig::fit_sensor_patch(in.geometry, in.cases.rig.sensor_area.value);
}

// The case's trials from the folder (every file read and checked), and the driving one.
void read_trials(const RigCommonArgs& args, RigInputs& in) {
  if (!args.data) {
    if (args.trial) throw std::invalid_argument("--trial needs --data DIR (the measured trials)");
    return;
  }
  auto by_case = rig::read_trial_folder(*args.data);
  for (const auto& [code, trials] : by_case)
    for (const rig::MeasuredTrial& m : trials)
      in.warnings.insert(in.warnings.end(), m.warnings.begin(), m.warnings.end());
  const auto it = by_case.find(in.rig_case->code);
  if (it == by_case.end())
    throw std::invalid_argument(fmt::format("--data {}: no trial of {} in the folder",
                                            args.data->string(), in.rig_case->code));
  in.trials = std::move(it->second);
  const int wanted = args.trial.value_or(kDefaultTrial);
  for (const rig::MeasuredTrial& m : in.trials)
    if (m.trial == wanted) in.drive_trial = &m;
  if (!in.drive_trial) {
    std::vector<int> have;
    for (const rig::MeasuredTrial& m : in.trials) have.push_back(m.trial);
    throw std::invalid_argument(fmt::format("--trial {}: {} has trials {} in {}", wanted,
                                            in.rig_case->code, fmt::join(have, ", "),
                                            args.data->string()));
  }
  std::string bytes;
  for (const rig::MeasuredTrial& m : in.trials) bytes += file_text(m.source);
  in.data_hash = study::fnv1a64(bytes);
}

// The open-loop drive's trial is the run's input (its V_i before contact and its contact onset
// are matched by construction, rig_models/compare/case_comparison.hpp): left out of the scores
// unless --score-drive-trial. A physical run has no driving trial and is scored on every trial.
void choose_scored_trials(const RigCommonArgs& args, RigInputs& in) {
  const bool open_loop = in.drive == rig::DriveKind::open_loop;
  if (args.score_drive_trial && !open_loop)
    throw std::invalid_argument(
        "--score-drive-trial: only an open-loop run has a driving trial (a physical run is "
        "scored on every trial)");
  if (open_loop && in.drive_trial && !args.score_drive_trial) in.left_out = in.drive_trial->trial;
  in.scored = rig::scored_trials(in.trials, in.left_out);
}

void check_out(const std::optional<fs::path>& out) {
  if (!out) return;
  std::error_code ec;
  if (out->empty()) throw std::invalid_argument("--out: the output folder must not be empty");
  if (fs::exists(*out, ec) && !fs::is_directory(*out, ec))
    throw std::invalid_argument(fmt::format("--out {}: exists and is not a folder", out->string()));
}

}  // namespace

void print_warnings(const RigInputs& in) {
  for (const std::string& w : in.warnings) fmt::print(stderr, "ccm: warning: {}\n", w);
}

RigInputs read_rig_inputs(const RigCommonArgs& args) {
  if (args.cases.empty()) throw std::invalid_argument(missing_data_message("--cases"));
  if (args.geometry.empty()) throw std::invalid_argument(missing_data_message("--geometry"));
  RigInputs in;
  in.cases_text = file_text(args.cases);
  in.cases = rig::parse_case_table(in.cases_text, args.cases);
  in.geometry_text = file_text(args.geometry);
  in.geometry = rig::parse_geometry(in.geometry_text, args.geometry);
  apply_trial_rig(args, in);
  rig::check_against_cases(in.geometry, in.cases.rig);
  if (!rig::is_case_code(args.case_code))
    throw std::invalid_argument(
        fmt::format("'{}' is not a case of thesis Table 3.2 (RX025 ... FF100; see ccm rig list)",
                    args.case_code));
  in.rig_case = &in.cases.find(args.case_code);
  const auto drive = rig::parse_drive(args.drive);
  if (!drive)
    throw std::invalid_argument(
        fmt::format("--drive {}: expected 'open-loop' or 'physical'", args.drive));
  in.drive = *drive;
  if (!(args.mesh_scale > 0.0 && args.mesh_scale <= 4.0))
    throw std::invalid_argument(
        fmt::format("--mesh-scale {}: must lie in (0, 4]", args.mesh_scale));
  in.parameters = rig::default_parameters(in.cases, *in.rig_case);
  apply_settings(args.set, *in.rig_case, in.parameters);
  read_trials(args, in);
  if (in.drive == rig::DriveKind::open_loop && !in.drive_trial)
    throw std::invalid_argument(
        "the open-loop drive (the default) follows a measured trial: give --data DIR (and "
        "--trial N), or use --drive physical");
  choose_scored_trials(args, in);
  check_out(args.out);
  in.cases_hash = study::fnv1a64(in.cases_text + in.trial_rig_text);
  in.geometry_hash = study::fnv1a64(in.geometry_text);
  in.db = args.db ? *args.db : args.out ? *args.out / "rig.sqlite" : fs::path("rig.sqlite");
  return in;
}

std::string parameter_text(const rig::RunParameters& p, const rig::RigCase& c) {
  std::string s;
  for (std::string_view name : rig::kRunParameterNames) {
    if (!rig::parameter_problem(name, c).empty()) continue;
    if ((name == "mu_s" || name == "mu_k") && !p.mu_s) continue;  // a frictionless clamp
    s += fmt::format("{}{}={}", s.empty() ? "" : ";", name, rig::get_parameter(p, name));
  }
  return s;
}

}  // namespace ccm
