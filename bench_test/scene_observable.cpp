#include "bench_test/scene_observable.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string_view>

#include "config/config_error.hpp"
#include "config/did_you_mean.hpp"

namespace ccm::bench {

namespace {

std::optional<std::size_t> index_of(const std::vector<std::string>& columns,
                                    const std::string& name) {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) return std::nullopt;
  return static_cast<std::size_t>(it - columns.begin());
}

// The three columns of a vector named by `prefix`: prefix + x, y, z or prefix + _x, _y, _z.
std::optional<std::vector<std::size_t>> vector_columns(const std::vector<std::string>& columns,
                                                       const std::string& prefix) {
  for (std::string_view sep : {"", "_"}) {
    std::vector<std::size_t> out;
    for (const char* axis : {"x", "y", "z"})
      if (auto i = index_of(columns, prefix + std::string(sep) + axis)) out.push_back(*i);
    if (out.size() == 3) return out;
  }
  return std::nullopt;
}

[[noreturn]] void fail(const std::filesystem::path& file, const ChannelSpec& c,
                       std::string_view problem) {
  throw config_error(file, c.observable_line, fmt::format("channels.{}.observable", c.name),
                     problem);
}

}  // namespace

ResolvedObservable resolve_observable(const ChannelSpec& c, const std::vector<std::string>& columns,
                                      const std::filesystem::path& file) {
  ResolvedObservable r;
  r.derivative = c.derivative;
  std::string name = c.observable;
  std::optional<std::vector<std::size_t>> vector = vector_columns(columns, name);
  // "<point>.a": the rate of "<point>.v".
  if (!index_of(columns, name) && !vector && name.size() > 2 &&
      name.compare(name.size() - 2, 2, ".a") == 0) {
    vector = vector_columns(columns, name.substr(0, name.size() - 1) + "v");
    if (vector) {
      if (c.derivative)
        fail(file, c, "'.a' is already the rate of '.v'; derivative = true would take it twice");
      r.derivative = true;
    }
  }
  if (const std::optional<std::size_t> scalar = index_of(columns, name)) {
    if (c.axis)
      fail(file, c, fmt::format("'{}' is one history column, a scalar: it takes no axis", name));
    r.columns = {*scalar};
    r.weights = {1.0};
    return r;
  }
  if (vector) {
    if (!c.axis)
      fail(file, c, fmt::format("'{}' is a vector (three history columns): give its axis", name));
    r.columns = *vector;
    r.weights = {(*c.axis)[0], (*c.axis)[1], (*c.axis)[2]};
    return r;
  }
  const std::vector<std::string_view> names(columns.begin() + 1, columns.end());
  const std::string_view near = closest_name(name, names);
  fail(file, c,
       near.empty()
           ? fmt::format("'{}' names no output of the scene (its history has {} columns; `ccm "
                         "run` writes them in history.csv)",
                         name, names.size())
           : fmt::format("'{}' names no output of the scene (did you mean '{}'?)", name, near));
}

rig::TimeSeries simulated_curve(const ChannelSpec& c, const ResolvedObservable& o,
                                const std::vector<std::vector<double>>& rows) {
  rig::TimeSeries s;
  for (const std::vector<double>& row : rows) {
    double v = 0.0;
    for (std::size_t k = 0; k < o.columns.size(); ++k) v += o.weights[k] * row[o.columns[k]];
    s.t.push_back(row[0]);
    s.value.push_back(c.scale * v);
  }
  if (!o.derivative) return s;
  rig::TimeSeries rate;
  for (std::size_t k = 1; k < s.t.size(); ++k) {
    const double dt = s.t[k] - s.t[k - 1];
    if (!(dt > 0.0)) continue;  // a repeated final sample
    rate.t.push_back(0.5 * (s.t[k] + s.t[k - 1]));
    rate.value.push_back((s.value[k] - s.value[k - 1]) / dt);
  }
  return rate;
}

}  // namespace ccm::bench
