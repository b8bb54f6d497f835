#include "run/compare/scene_comparison.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "config/did_you_mean.hpp"
#include "run/scene/scene.hpp"
#include "study/metrics/model_errors.hpp"

namespace ccm {
namespace {

size_t column_of(const ComparedRun& run, const std::string& name) {
  const std::optional<std::size_t> c = run.column(name);
  if (!c) throw std::logic_error(fmt::format("compare: no column '{}' in a run", name));
  return *c;
}

std::vector<double> series(const ComparedRun& run, const std::string& name) {
  const size_t c = column_of(run, name);
  std::vector<double> out;
  for (const std::vector<double>& row : run.rows) out.push_back(row.at(c));
  return out;
}

// Empty when both runs completed and share their sample times, else why not.
std::string unusable_reason(const ComparedRun& d, const ComparedRun& r) {
  if (d.verdict != "completed") return "the deformable run is " + d.verdict + ": " + d.reason;
  if (r.verdict != "completed") return "the rigid run is " + r.verdict + ": " + r.reason;
  const std::vector<double> td = series(d, "time"), tr = series(r, "time");
  if (td.size() != tr.size() || td.size() < 2)
    return fmt::format("the runs have {} and {} samples", td.size(), tr.size());
  const double tol = 1e-9 * std::max(std::abs(td.back()), 1e-300);
  for (size_t i = 0; i < td.size(); ++i)
    if (std::abs(td[i] - tr[i]) > tol)
      return fmt::format("sample {} is at {} s in one run and {} s in the other", i, td[i], tr[i]);
  return {};
}

}  // namespace

std::optional<std::size_t> ComparedRun::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) return std::nullopt;
  return static_cast<std::size_t>(it - columns.begin());
}

std::vector<std::string> default_observables(const Scene& variant) {
  std::vector<std::string> out;
  for (const BodySpec& b : variant.bodies)
    if (!b.rigid)
      for (const char* metric : {"u_mean", "u_max", "kinetic_energy"})
        out.push_back(b.name + "." + metric);
  return out;
}

void check_observables(const std::vector<std::string>& observables,
                       const std::vector<std::string>& deformable_columns,
                       const std::vector<std::string>& rigid_columns) {
  if (observables.empty())
    throw std::invalid_argument(
        "--observe: nothing to compare (every body is rigid: name an observable, e.g. a rigid "
        "body's kinetic_energy or a contact pair's column)");
  std::vector<std::string_view> both;
  for (const std::string& c : deformable_columns)
    if (c != "time" &&
        std::find(rigid_columns.begin(), rigid_columns.end(), c) != rigid_columns.end())
      both.push_back(c);
  for (const std::string& o : observables) {
    if (std::find(both.begin(), both.end(), o) != both.end()) continue;
    const std::string_view close = closest_name(o, both);
    throw std::invalid_argument(fmt::format(
        "--observe {}: not a history column of both runs{} (columns of both: {})", o,
        close.empty() ? "" : fmt::format("; did you mean '{}'?", close), fmt::join(both, ", ")));
  }
}

ComparisonOutcome compare_runs(const ComparedRun& deformable, const ComparedRun& rigid,
                               const std::vector<std::string>& observables, double max_error) {
  ComparisonOutcome out;
  out.cost_ratio = rigid.step_cpu_seconds > 0.0
                       ? deformable.step_cpu_seconds / rigid.step_cpu_seconds
                       : std::numeric_limits<double>::infinity();
  out.unusable = unusable_reason(deformable, rigid);
  if (!out.unusable.empty()) return out;
  const std::vector<double> time = series(deformable, "time");
  std::vector<double> final_state;
  for (const std::string& name : observables) {
    const std::vector<double> d = series(deformable, name), r = series(rigid, name);
    ObservableErrors e{name, study::final_state_error(d, r), 0.0};
    try {
      e.cumulative = study::cumulative_error(time, d, r);
    } catch (const std::domain_error&) {
      e.cumulative = std::numeric_limits<double>::infinity();  // means cancel: no scale
    }
    final_state.push_back(e.final_state);
    out.errors.push_back(std::move(e));
  }
  out.decision = study::decide_model(final_state, out.cost_ratio, max_error);
  return out;
}

}  // namespace ccm
