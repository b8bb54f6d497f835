// `ccm study status --db FILE [--json]`: done / running / failed / unstable per grid point, and the
// study's modelling choices (from the grid file the store keeps).
#include <fmt/format.h>

#include <map>

#include "app/command_errors.hpp"
#include "app/json_output.hpp"
#include "app/run_command.hpp"
#include "app/stored_grid.hpp"
#include "app/study_commands.hpp"
#include "app/study_store_open.hpp"
#include "db/store/study_store.hpp"
#include "study/recommend/modelling_choices.hpp"

namespace ccm {
namespace {

std::string run_text(const std::optional<db::RunStatus>& run) {
  return run ? std::string(db::to_string(*run)) : std::string("pending");
}

void print_status(const std::vector<db::PointStatus>& points) {
  fmt::print("{:>5} {:>8} {:>5} {:>6} {:>10}  {:>9} {:>9}  {}\n", "point", "ER", "RLS", "KE[J]",
             "state", "ccm", "rigid", "reason");
  std::map<std::string, int> totals;
  for (const auto& s : points) {
    const auto& p = s.point;
    std::string extra;
    for (const auto& [name, value] : p.other_axes) extra += fmt::format(" {}={:g}", name, value);
    fmt::print("{:>5} {:>8.0e} {:>5.2f} {:>6g} {:>10}  {:>9} {:>9}  {}{}\n", p.index,
               p.modulus_ratio, p.length_ratio, p.kinetic_energy, db::to_string(s.state),
               run_text(s.ccm), run_text(s.rigid), s.reason, extra);
    ++totals[std::string(db::to_string(s.state))];
  }
  std::string line;
  for (const auto& [state, n] : totals)
    line += fmt::format("{}{} {}", line.empty() ? "" : ", ", n, state);
  fmt::print("{} points: {}\n", points.size(), line.empty() ? "none" : line);
}

void print_choices(const std::optional<study::GridSpec>& grid) {
  if (!grid) {
    fmt::print("{}\n", kNoStoredGrid);
    return;
  }
  fmt::print("modelling choices (grid file {}):\n", grid->source.string());
  for (const study::ModellingChoice& c : study::modelling_choices(*grid))
    fmt::print("  {}\n", c.text());
}

}  // namespace

int study_status_command(const StudyStatusArgs& args) {
  return run_reporting_errors([&] {
    auto store = open_study_store(args.db);
    if (args.json) {
      print_json(study_status_json(*store, store->status(), stored_grid_spec(*store)));
      return exit_code::completed;
    }
    print_status(store->status());
    print_choices(stored_grid_spec(*store));
    return exit_code::completed;
  });
}

}  // namespace ccm
