// `ccm study refine --db FILE [--axis A] [--tolerance T] [--budget RUNS] [--jobs N]`: adds points
// to a study where its answer changes (study/refine/boundary_refinement.hpp) and runs them, round
// after round, until every boundary is located to the tolerance or the budget is spent; prints
// each boundary and the runs used. The study's grid file is the one its store keeps. A killed
// refine resumes: the points it registered are run first (each run once, as `study run`).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "app/command_errors.hpp"
#include "app/json_output.hpp"
#include "app/run_command.hpp"
#include "app/run_schedule.hpp"
#include "app/stored_grid.hpp"
#include "app/study_commands.hpp"
#include "app/study_runs.hpp"
#include "app/study_store_open.hpp"
#include "db/store/point_key.hpp"
#include "engine/threads/thread_count.hpp"
#include "records/content_hash.hpp"
#include "run/parallel/rank_context.hpp"
#include "run/runner/study_scene.hpp"
#include "study/fit/study_fits.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/recommend/recommendation.hpp"
#include "study/refine/boundary_refinement.hpp"

namespace ccm {
namespace {

using study::GridPoint;
using study::GridSpec;

struct RefineSetup {
  GridSpec spec;
  std::string grid_hash;
  std::string axis;  // "ER" or "axes.<path>"
  double tolerance = 0.0;
  long budget = 0;
};

// The axis as people name it: "ER", or the path.
std::string axis_label(const std::string& axis) {
  return axis.starts_with(study::kTemplateAxisPrefix)
             ? axis.substr(study::kTemplateAxisPrefix.size())
             : axis;
}

// The values the grid file gives the axis.
std::vector<double> axis_values(const GridSpec& spec, const std::string& axis) {
  if (!spec.scene_template) return spec.modulus_ratios;
  for (const study::TemplateAxis& a : spec.scene_template->axes)
    if (std::string(study::kTemplateAxisPrefix) + a.path == axis) return a.values;
  return {};
}

std::string chosen_axis(const GridSpec& spec, const std::string& given) {
  if (!spec.scene_template) {
    if (!given.empty() && given != "ER")
      throw StudyInputError(fmt::format(
          "--axis {}: the thesis grid is refined along ER (its other axes are levels)", given));
    return "ER";
  }
  const auto& axes = spec.scene_template->axes;
  if (given.empty()) return std::string(study::kTemplateAxisPrefix) + axes.front().path;
  for (const study::TemplateAxis& a : axes)
    if (a.path == given) return std::string(study::kTemplateAxisPrefix) + a.path;
  std::string paths;
  for (const study::TemplateAxis& a : axes) paths += (paths.empty() ? "" : ", ") + a.path;
  throw StudyInputError(
      fmt::format("--axis {}: not a path of the grid's [axes] (they are: {})", given, paths));
}

// A quarter of the finest spacing of the grid's values on the axis: decades when they share a
// sign, else the axis's units.
double default_tolerance(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const bool geometric = values.front() > 0.0 || values.back() < 0.0;
  double finest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < values.size(); ++k)
    finest = std::min(finest, geometric ? std::abs(std::log10(values[k] / values[k - 1]))
                                        : values[k] - values[k - 1]);
  return 0.25 * finest;
}

RefineSetup refine_setup(const StudyRefineArgs& args) {
  const auto store = open_study_store(args.db);
  const auto grid = store->load_grid();
  if (!grid) throw StudyInputError(std::string(kNoStoredGrid));
  RefineSetup s{stored_grid_spec(*store).value(), study::fnv1a64(grid->text), "", 0.0, 0};
  s.axis = chosen_axis(s.spec, args.axis);
  const std::vector<double> values = axis_values(s.spec, s.axis);
  if (values.size() < 2)
    throw StudyInputError(fmt::format("the grid has one value on {}: nothing to refine", s.axis));
  s.tolerance = args.tolerance > 0.0 ? args.tolerance : default_tolerance(values);
  s.budget = args.budget > 0 ? args.budget : 4 * study::grid_size(s.spec);
  return s;
}

// The study's points whose two runs are not both done (a killed refine's), as planned runs.
std::vector<PlannedRun> unfinished_runs(const StudyRefineArgs& args, const RefineSetup& s) {
  const auto store = open_study_store(args.db);
  study::StudyPoints points;
  for (const db::PointStatus& p : store->status())
    if (p.state != db::PointState::done && !study::is_convergence_point(p.point))
      points.grid.push_back(p.point);
  return plan_runs(s.spec, points);
}

// The runs of the study: two per point (the budget counts them all).
long study_runs(const StudyRefineArgs& args) {
  return 2 * static_cast<long>(open_study_store(args.db)->status().size());
}

int next_index(const StudyRefineArgs& args) {
  int next = 0;
  for (const db::PointStatus& p : open_study_store(args.db)->status())
    next = std::max(next, p.point.index + 1);
  return next;
}

// Registers the runs' points and runs them (one process: study_refine_command refuses mpirun).
void run_planned(const StudyRefineArgs& args, const RefineSetup& s,
                 const std::vector<PlannedRun>& runs) {
  if (runs.empty()) return;
  study::RankContext ranks;
  register_points(args.db, s.spec, s.grid_hash, runs);
  run_all({args.db, args.jobs, args.quiet}, ranks, s.spec, s.grid_hash, runs);
}

// The points that split the plan's intervals, as many as `budget_runs` allows (two runs each).
std::vector<GridPoint> split_points(const StudyRefineArgs& args, const RefineSetup& s,
                                    const study::RefinePlan& plan, long budget_runs) {
  std::vector<GridPoint> out;
  std::set<std::string> seen;  // the study's points (an unstable one is in no interval)
  for (const db::PointStatus& p : open_study_store(args.db)->status()) seen.insert(p.content_hash);
  int index = next_index(args);
  for (const study::RefineInterval& i : plan.to_split) {
    if (2 * static_cast<long>(out.size() + 1) > budget_runs) break;
    GridPoint p = study::moved_point(s.spec, i.lo, s.axis, i.middle(), index);
    if (!seen.insert(db::grid_point_hash(p)).second) continue;
    out.push_back(p);
    ++index;
  }
  return out;
}

void print_boundaries(const StudyRefineArgs& args, const RefineSetup& s,
                      const study::RefinePlan& plan, bool resolved) {
  fmt::print("{}\nboundaries of the answer along {}:\n", study::decision_rule_text(args.max_error),
             axis_label(s.axis));
  if (plan.boundaries.empty()) fmt::print("  none: every line has one answer\n");
  for (const study::RefineInterval& i : plan.boundaries)
    fmt::print("  {}\n", study::boundary_text(i, axis_label(s.axis), s.tolerance));
  fmt::print("runs: {} of the budget {} (the study's, its grid's included); {}\n", study_runs(args),
             s.budget,
             resolved ? "every boundary located to the tolerance"
                      : "stopped by the budget before every boundary was located");
}

nlohmann::json side_json(const GridPoint& p, double value, study::ImpactModel answer) {
  return {{"point", p.index},      {"value", value},        {"answer", study::to_string(answer)},
          {"ER", p.modulus_ratio}, {"RLS", p.length_ratio}, {"KE", p.kinetic_energy}};
}

nlohmann::json refine_json(const StudyRefineArgs& args, const RefineSetup& s,
                           const study::RefinePlan& plan, bool resolved) {
  nlohmann::json boundaries = nlohmann::json::array();
  for (const study::RefineInterval& i : plan.boundaries)
    boundaries.push_back({{"line", i.line},
                          {"below", side_json(i.lo, i.lo_x, i.lo_answer)},
                          {"above", side_json(i.hi, i.hi_x, i.hi_answer)},
                          {"width", i.width},
                          {"width_unit", i.geometric ? "decades" : "axis units"},
                          {"resolved", i.width <= s.tolerance},
                          {"errors_change", i.errors_change},
                          {"cost_changes", i.cost_changes}});
  return {{"axis", axis_label(s.axis)}, {"rule", study::decision_rule_text(args.max_error)},
          {"tolerance", s.tolerance},   {"budget", s.budget},
          {"runs", study_runs(args)},   {"every_boundary_located", resolved},
          {"boundaries", boundaries}};
}

int study_refine(const StudyRefineArgs& args) {
  const RefineSetup s = refine_setup(args);
  run_planned(args, s, unfinished_runs(args, s));
  study::RefinePlan plan;
  std::vector<study::PointMetrics> measured;
  for (int round = 1;; ++round) {
    const DerivedResults results = derive_results(args.db, s.spec, s.grid_hash);
    measured = results.grid;
    plan = study::plan_refinement(study::decide_grid_points(results.fits, measured, args.max_error),
                                  s.axis, s.tolerance);
    const std::vector<GridPoint> points = split_points(args, s, plan, s.budget - study_runs(args));
    if (points.empty()) break;
    if (!args.quiet && !args.json)
      fmt::print("refine round {}: {} point(s) on {}, {} runs\n", round, points.size(),
                 axis_label(s.axis), 2 * points.size());
    run_planned(args, s, plan_runs(s.spec, {points, {}}));
  }
  const bool resolved = std::none_of(plan.to_split.begin(), plan.to_split.end(),
                                     [](const study::RefineInterval& i) { return i.boundary; });
  if (args.json)
    print_json(refine_json(args, s, plan, resolved));
  else
    print_boundaries(args, s, plan, resolved);
  if (const long failed = count_failed(args.db, s.spec, s.grid_hash); failed > 0) {
    fmt::print(stderr, "ccm: error: {} run(s) failed; `ccm study status --db {}` names them\n",
               failed, args.db.string());
    return exit_code::internal_error;
  }
  return exit_code::completed;
}

}  // namespace

int study_refine_command(const StudyRefineArgs& args) {
  return run_reporting_errors([&] {
    if (args.jobs < 1)
      throw StudyInputError(fmt::format("--jobs must be at least 1 (got {})", args.jobs));
    if (study::launched_by_mpi())
      throw StudyInputError(
          "study refine runs in one process (its rounds depend on each other's results): run it "
          "without mpirun, with --jobs N local workers");
    set_default_threads(
        resolve_threads(args.threads, threads_per_job(available_cores(), args.jobs)));
    return study_refine(args);
  });
}

}  // namespace ccm
