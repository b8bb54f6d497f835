#include "app/compare_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "app/command_errors.hpp"
#include "app/compare_prediction.hpp"
#include "app/data_paths.hpp"
#include "app/json_output.hpp"
#include "app/output_file.hpp"
#include "app/progress_line.hpp"
#include "app/run_command.hpp"
#include "config/config_error.hpp"
#include "config/text_file.hpp"
#include "db/store/comparison_store.hpp"
#include "db/store/study_store.hpp"
#include "engine/threads/thread_count.hpp"
#include "records/content_hash.hpp"
#include "records/provenance/version.hpp"
#include "run/compare/compare_impact.hpp"
#include "run/compare/rigid_variant.hpp"
#include "run/compare/scene_comparison.hpp"
#include "run/compare/scene_groups.hpp"
#include "run/scene/scene_file.hpp"
#include "run/scene/scene_inputs.hpp"
#include "run/scene/scene_run.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

// What identifies a run: the scene's text, the mesh files it reads, which bodies are rigid, and
// the ccm that runs it (its version and commit: another build may compute another result).
std::string compare_hash(const std::string& text, const Scene& scene,
                         const std::vector<std::string>& rigid) {
  std::string all = scene_inputs_text(text, scene) + "\n#ccm " + version_string();
  all += fmt::format("\n#ccm compare --rigid {}\n", fmt::join(rigid, ","));
  return study::fnv1a64(all);
}

// Both runs' outputs switched on (u_mean, u_max, kinetic energy of every body), so that the
// default observables exist whatever the scene asked.
Scene with_metrics(Scene s) {
  s.output.kinetic_energy = true;
  s.output.displacement = true;
  return s;
}

struct Side {
  std::string label;  // "deformable", "rigid"
  SceneRun run;
  std::unique_ptr<HistoryRecorder> history;
  RunOptions options;
  std::string hash;
};

Side prepare_side(std::string label, Scene scene, std::string hash) {
  Side s{std::move(label), assemble_scene_run(with_metrics(std::move(scene))), nullptr, {}, {}};
  s.history = std::make_unique<HistoryRecorder>(s.run.model.mesh, s.run.output);
  s.options = scene_run_options(s.run, s.history.get());
  s.hash = std::move(hash);
  return s;
}

fs::path cached_history(const fs::path& out, const std::string& hash) {
  return out / "runs" / (hash + ".csv");
}
fs::path cached_summary(const fs::path& out, const std::string& hash) {
  return out / "runs" / (hash + ".json");
}

// A run kept by an earlier comparison, or nothing.
std::optional<ComparedRun> read_cached(const fs::path& out, const std::string& hash) {
  std::ifstream summary(cached_summary(out, hash)), csv(cached_history(out, hash));
  if (!summary || !csv) return std::nullopt;
  ComparedRun r;
  const nlohmann::json j = nlohmann::json::parse(summary, nullptr, false);
  if (j.is_discarded()) return std::nullopt;
  r.hash = hash;
  r.verdict = j.value("verdict", "");
  r.reason = j.value("reason", "");
  r.steps = j.value("steps", 0L);
  r.step_cpu_seconds = j.value("step_cpu_seconds", 0.0);
  r.wall_seconds = j.value("wall_seconds", 0.0);
  std::string line;
  if (!std::getline(csv, line)) return std::nullopt;
  std::stringstream header(line);
  for (std::string c; std::getline(header, c, ',');) r.columns.push_back(c);
  while (std::getline(csv, line)) {
    std::stringstream cells(line);
    std::vector<double> row;
    for (std::string c; std::getline(cells, c, ',');) row.push_back(std::stod(c));
    if (row.size() != r.columns.size()) return std::nullopt;  // a torn file: run again
    r.rows.push_back(std::move(row));
  }
  r.reused = true;
  return r;
}

ComparedRun run_side(Side& side, const CompareArgs& args, const fs::path& out) {
  if (auto cached = read_cached(out, side.hash)) return *cached;
  ProgressLine progress(side.label);
  side.options.progress = progress.on_terminal(args.quiet);
  const RunSummary s = run_explicit(side.run.model, side.options);
  progress.finish();
  ComparedRun r;
  r.hash = side.hash;
  r.verdict = std::string(to_string(s.verdict));
  if (s.verdict == Verdict::unstable) r.reason = s.instability.reason;
  r.steps = s.steps;
  r.step_cpu_seconds = s.step_cpu_seconds;
  r.wall_seconds = s.wall_seconds;
  r.columns = side.history->columns();
  r.rows = side.history->rows();
  fs::create_directories(out / "runs");
  write_history_csv(cached_history(out, side.hash), *side.history);
  const nlohmann::json j = {{"scene", args.scene.string()},
                            {"bodies_rigid", side.label == "rigid"},
                            {"verdict", r.verdict},
                            {"reason", r.reason},
                            {"steps", r.steps},
                            {"step_cpu_seconds", r.step_cpu_seconds},
                            {"wall_seconds", r.wall_seconds}};
  write_atomic(cached_summary(out, side.hash), j.dump(2) + "\n");
  return r;
}

// The hash of a run that differs from `hash`'s by `what` (its end).
std::string hash_with(const std::string& hash, const std::string& what) {
  return study::fnv1a64(hash + "\n#" + what);
}

double last_sample_time(const ComparedRun& r) {
  const std::optional<std::size_t> t = r.column("time");
  if (!t || r.rows.empty()) return 0.0;
  return r.rows.back()[*t];
}

// The two runs, on common sample times. With [time] end_after_separation (a whole impact) the
// deformable run ends one hold after its bodies separate and the rigid run not before that; when
// the rigid run ends later, the deformable run is run again to the rigid run's end without the
// criterion (up to its first end it is the same run, bit for bit: docs/scene-file.md). So the
// final state is after both have separated, and both step loops cover the same time.
std::pair<ComparedRun, ComparedRun> run_both(Side& deformable, Side& rigid, const Scene& scene,
                                             const CompareArgs& args, const fs::path& out) {
  ComparedRun d = run_side(deformable, args, out);
  if (!scene.time.end_after_separation || d.verdict != "completed")
    return {d, run_side(rigid, args, out)};
  const double t_d = last_sample_time(d);
  rigid.options.time.earliest_end = t_d;
  rigid.hash = hash_with(rigid.hash, fmt::format("earliest_end {}", t_d));
  ComparedRun r = run_side(rigid, args, out);
  const double t_r = last_sample_time(r);
  if (r.verdict == "completed" && t_r > t_d) {
    Scene longer = scene;
    longer.time.end = t_r;
    longer.time.end_after_separation.reset();
    Side again = prepare_side("deformable", std::move(longer),
                              hash_with(deformable.hash, fmt::format("end {}", t_r)));
    d = run_side(again, args, out);
  }
  return {d, r};
}

// The one rule (study/recommend/decision_rule.hpp), said of the observables compared.
std::string compare_rule_text(double max_error) {
  return fmt::format(
      "rule: rigid is good enough where the rigid run's final-state error is within {:g} on "
      "every observable AND the rigid run is cheaper (cost ratio > 1); otherwise keep it "
      "deformable",
      max_error);
}

nlohmann::json run_json(const ComparedRun& r) {
  return {{"hash", r.hash},
          {"verdict", r.verdict},
          {"reason", r.reason},
          {"steps", r.steps},
          {"step_cpu_seconds", r.step_cpu_seconds},
          {"wall_seconds", r.wall_seconds},
          {"reused", r.reused}};
}

nlohmann::json comparison_json(const CompareArgs& args, const std::vector<std::string>& observables,
                               const ComparedRun& d, const ComparedRun& r,
                               const ComparisonOutcome& o) {
  nlohmann::json errors = nlohmann::json::array();
  for (const ObservableErrors& e : o.errors)
    errors.push_back(
        {{"observable", e.column}, {"final_state", e.final_state}, {"cumulative", e.cumulative}});
  nlohmann::json j = {{"scene", args.scene.string()},
                      {"rigid_bodies", args.rigid},
                      {"observables", observables},
                      {"max_error", args.max_error},
                      {"deformable_run", run_json(d)},
                      {"rigid_run", run_json(r)},
                      {"cost_ratio", o.cost_ratio},
                      {"errors", errors},
                      {"rule", compare_rule_text(args.max_error)}};
  if (!o.unusable.empty()) {
    j["unusable"] = o.unusable;
    return j;
  }
  j["decision"] = {
      {"model", o.decision.model == study::ImpactModel::rigid ? "rigid" : "deformable"},
      {"worst_final_state_error", o.decision.worst_error},
      {"rigid_within_error", o.decision.rigid_within_error},
      {"rigid_cheaper", o.decision.rigid_cheaper}};
  return j;
}

// t_c: the first sample at which the artifact has moved (u_max above 1e-6 of its largest).
std::optional<double> contact_time(const ComparedRun& d, const GroupsOrReason& g) {
  if (!g.groups || d.rows.empty()) return std::nullopt;
  const std::optional<std::size_t> col = d.column(g.groups->artifact + ".u_max");
  if (!col) return std::nullopt;
  const size_t c = *col;
  double largest = 0.0;
  for (const auto& row : d.rows) largest = std::max(largest, row[c]);
  for (const auto& row : d.rows)
    if (largest > 0.0 && row[c] > 1e-6 * largest) return row[0];
  return std::nullopt;
}

void print_table(const CompareArgs& args, const ComparedRun& d, const ComparedRun& r,
                 const ComparisonOutcome& o) {
  fmt::print("ccm compare {}  (rigid: {})\n", args.scene.string(), fmt::join(args.rigid, ", "));
  for (const auto& [label, run] : {std::pair{"deformable", &d}, std::pair{"rigid", &r}})
    fmt::print("  {:<11} {} in {} steps, step loop {:.3f} s CPU{}\n", label, run->verdict,
               run->steps, run->step_cpu_seconds, run->reused ? " (reused)" : "");
  if (!o.unusable.empty()) {
    fmt::print("  not comparable: {}\n", o.unusable);
    return;
  }
  fmt::print("\n  {:<40} {:>12} {:>12}\n", "observable", "final-state", "cumulative");
  for (const ObservableErrors& e : o.errors)
    fmt::print("  {:<40} {:>12.4g} {:>12.4g}\n", e.column, e.final_state, e.cumulative);
  fmt::print("\n  cost ratio (deformable / rigid step loop, CPU): {:.3g}\n", o.cost_ratio);
  const bool rigid = o.decision.model == study::ImpactModel::rigid;
  fmt::print("  answer: {} (worst final-state error {:.3g})\n  {}\n",
             rigid ? "rigid is good enough" : "keep it deformable", o.decision.worst_error,
             compare_rule_text(args.max_error));
}

// The designer's metrics (docs/metrics.md), or why there are none.
void print_impact(const std::optional<CompareImpact>& impact) {
  if (!impact) {
    fmt::print("\n  designer's metrics: none (no single impactor and artifact, or no contact)\n");
    return;
  }
  const study::ImpactQuantities &d = impact->deformable, &r = impact->rigid;
  const study::ImpactErrors& e = impact->errors;
  fmt::print("\n  {:<28} {:>12} {:>12} {:>8}   (docs/metrics.md)\n", "designer's metric",
             "deformable", "rigid", "error");
  for (const auto& [name, dv, rv, ev] :
       {std::tuple{"peak contact force [N]", d.peak_force, r.peak_force, e.peak_force},
        std::tuple{"deepest indentation [m]", d.indentation, r.indentation, e.indentation},
        std::tuple{"contact duration [s]", d.contact_duration, r.contact_duration,
                   e.contact_duration},
        std::tuple{"rebound speed [m/s]", d.rebound_speed, r.rebound_speed, e.rebound_speed}})
    fmt::print("  {:<28} {:>12.4g} {:>12.4g} {:>8.3f}\n", name, dv, rv, ev);
}

nlohmann::json impact_json(const std::optional<CompareImpact>& impact) {
  if (!impact) return nullptr;
  auto quantities = [](const study::ImpactQuantities& q) {
    return nlohmann::json{{"peak_force", q.peak_force},
                          {"indentation", q.indentation},
                          {"contact_duration", q.contact_duration},
                          {"rebound_speed", q.rebound_speed},
                          {"approach_speed", q.approach_speed}};
  };
  const study::ImpactErrors& e = impact->errors;
  return {{"deformable", quantities(impact->deformable)},
          {"rigid", quantities(impact->rigid)},
          {"errors",
           {{"peak_force", e.peak_force},
            {"indentation", e.indentation},
            {"contact_duration", e.contact_duration},
            {"rebound_speed", e.rebound_speed}}}};
}

// The comparison as a row of the store (db/store/comparison_store.hpp).
db::ComparisonRow comparison_row(const CompareArgs& args,
                                 const std::vector<std::string>& observables, const ComparedRun& d,
                                 const ComparedRun& r, const ComparisonOutcome& o,
                                 const ComparePrediction& p, const nlohmann::json& document) {
  db::ComparisonRow row;
  row.scene = args.scene.string();
  row.deformable_hash = d.hash;
  row.rigid_hash = r.hash;
  row.rigid_bodies = fmt::format("{}", fmt::join(args.rigid, ","));
  row.observables = fmt::format("{}", fmt::join(observables, ","));
  row.max_error = args.max_error;
  row.cost_ratio = o.cost_ratio;
  row.unusable = o.unusable;
  if (o.unusable.empty()) {
    row.worst_error = o.decision.worst_error;
    row.answer = o.decision.model == study::ImpactModel::rigid ? "rigid" : "deformable";
  }
  if (p.recommendation)
    row.predicted = p.recommendation->model == study::ImpactModel::rigid ? "rigid" : "deformable";
  row.agrees = p.agrees;
  row.prediction_note = p.note;
  row.document = document.dump();
  return row;
}

int compare(const CompareArgs& args) {
  set_default_threads(resolve_threads(args.threads, available_cores()));
  const std::string text = read_config_text(args.scene);
  const Scene scene = parse_scene(text, args.scene);
  const Scene variant = with_rigid_bodies(scene, args.rigid);
  // Everything is built and checked before either run starts.
  Side deformable = prepare_side("deformable", scene, compare_hash(text, scene, {}));
  Side rigid = prepare_side("rigid", variant, compare_hash(text, scene, args.rigid));
  const std::vector<std::string> observables =
      args.observe.empty() ? default_observables(variant) : args.observe;
  check_observables(observables, deformable.history->columns(), rigid.history->columns());
  const fs::path out =
      args.out.empty() ? fs::path("compare-" + args.scene.stem().string()) : args.out;
  const fs::path record_db = args.db.empty() ? fs::path(kMainJobStore) : args.db;
  const fs::path predict_db = prediction_store(args.db, record_db);
  // A store that is there must be a ccm store this ccm can read and write: checked before the runs.
  for (const fs::path& db : {record_db, predict_db})
    if (fs::exists(db)) db::StudyStore check(db, db::Access::read_only);
  if (fs::exists(out) && !fs::is_directory(out))
    throw std::invalid_argument(
        fmt::format("--out {}: exists and is not a directory", out.string()));

  const auto [d, r] = run_both(deformable, rigid, scene, args, out);
  const ComparisonOutcome o = compare_runs(d, r, observables, args.max_error);
  GroupsOrReason groups = scene_groups(scene, deformable.run.model, args.rigid, {});
  if (const auto t_c = contact_time(d, groups))
    groups.groups->window = contact_window(*groups.groups, scene, *t_c);
  std::optional<CompareImpact> impact;
  if (const auto& g = groups.groups; g && o.unusable.empty())
    impact = compare_impact(d, r, g->impactor, g->artifact, g->m_I);
  const ComparePrediction prediction =
      predict_for_scene(predict_db, std::move(groups), o, args.max_error,
                        scene.time.end_after_separation.has_value());
  nlohmann::json j = comparison_json(args, observables, d, r, o);
  j["impact"] = impact_json(impact);
  j["study_prediction"] = prediction_json(predict_db, prediction);
  // Recorded in the study's store, for `ccm report`, when there is one.
  std::string recorded = fmt::format("not recorded: no store at {}", record_db.string());
  if (fs::is_regular_file(record_db)) {
    const long long id =
        db::record_comparison(record_db, comparison_row(args, observables, d, r, o, prediction, j));
    recorded = fmt::format("recorded in {} (comparison {}; `ccm report` shows it)",
                           record_db.string(), id);
  }
  j["store"] = recorded;
  write_atomic(out / "comparison.json", j.dump(2) + "\n");
  if (args.json)
    print_json(j);
  else {
    print_table(args, d, r, o);
    print_impact(impact);
    print_prediction(predict_db, prediction);
    fmt::print("\n  {}\n", recorded);
  }
  if (!o.unusable.empty()) return exit_code::unstable;
  return exit_code::completed;
}

}  // namespace

int compare_command(const CompareArgs& args) {
  return run_scene_command([&] { return compare(args); });
}

}  // namespace ccm
