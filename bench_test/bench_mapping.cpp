#include "bench_test/bench_mapping.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <set>
#include <string_view>
#include <utility>

#include "bench_test/units.hpp"
#include "config/config_error.hpp"
#include "config/did_you_mean.hpp"
#include "config/strict_table.hpp"
#include "config/text_file.hpp"

namespace ccm::bench {

namespace {

std::string unit_of(const StrictTable& t, std::string_view key, double& factor) {
  const std::string unit = t.need_string(key);
  const std::optional<double> f = si_factor(unit);
  if (!f) t.fail(key, unknown_value_problem(unit, known_units()));
  factor = *f;
  return unit;
}

// A name of a channel: the characters of a scene's names, so that it can name files and columns.
void check_name(const StrictTable& t, std::string_view key, const std::string& name) {
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-')
      t.fail(key, fmt::format("'{}' may use only A-Z a-z 0-9 _ -", name));
}

// "CFC60", "CFC 180", "cfc1000": a channel frequency class; "low_pass" with `cutoff`; "none".
ChannelFilter filter_of(const StrictTable& t) {
  ChannelFilter f;
  const std::string text = t.get_or<std::string>("filter", "none");
  if (text == "none") {
    if (t.has("cutoff")) t.fail("cutoff", "only with filter = \"low_pass\"");
    return f;
  }
  if (text == "low_pass") {
    f.kind = FilterKind::low_pass;
    f.frequency = t.need_number("cutoff");
    if (!(f.frequency > 0.0)) t.fail("cutoff", fmt::format("{} Hz must be > 0", f.frequency));
    return f;
  }
  std::string upper;
  for (char c : text)
    if (c != ' ') upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (upper.rfind("CFC", 0) == 0 && upper.size() > 3) {
    try {
      std::size_t used = 0;
      const double cfc = std::stod(upper.substr(3), &used);
      if (used == upper.size() - 3 && cfc > 0.0) {
        if (t.has("cutoff")) t.fail("cutoff", "only with filter = \"low_pass\"");
        f.kind = FilterKind::cfc;
        f.frequency = cfc;
        return f;
      }
    } catch (const std::exception&) {
    }
  }
  t.fail("filter", fmt::format("'{}' is not a filter: \"none\", \"CFC60\", \"CFC180\", \"CFC600\", "
                               "\"CFC1000\" (any CFC<n>) or \"low_pass\" with cutoff",
                               text));
}

std::array<double, 3> axis_of(const StrictTable& t) {
  const std::vector<double> v = t.number_array("axis");
  if (v.size() != 3) t.fail("axis", fmt::format("needs 3 components, has {}", v.size()));
  const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(norm > 0.0)) t.fail("axis", "must not be zero");
  return {v[0] / norm, v[1] / norm, v[2] / norm};
}

// window = [start, end] in s, or the name of an event (checked against [[events]] later).
void read_window(const StrictTable& t, ChannelSpec& c) {
  if (!t.has("window")) return;
  if (t.node("window")->is_string()) {
    c.window_event = t.need_string("window");
    return;
  }
  const std::vector<double> w = t.number_array("window");
  if (w.size() != 2)
    t.fail("window", fmt::format("needs [start, end] in s, has {} numbers", w.size()));
  if (!(w[1] > w[0]))
    t.fail("window", fmt::format("end {} s must be after start {} s", w[1], w[0]));
  c.window = std::array<double, 2>{w[0], w[1]};
}

ChannelSpec channel_of(const StrictTable& t) {
  t.allow_only({"name", "column", "unit", "observable", "axis", "derivative", "scale", "filter",
                "cutoff", "deadband", "deadband_first", "apply_to", "window"});
  ChannelSpec c;
  c.line = t.line();
  c.name = t.need_string("name");
  check_name(t, "name", c.name);
  c.column = t.need_string("column");
  c.unit = unit_of(t, "unit", c.si_factor);
  c.observable = t.need_string("observable");
  c.observable_line = t.line_of_key("observable");
  if (t.has("axis")) c.axis = axis_of(t);
  c.derivative = t.get_or<bool>("derivative", false);
  c.scale = t.number_or("scale", 1.0);
  if (c.scale == 0.0) t.fail("scale", "must not be 0");
  c.filter = filter_of(t);
  c.deadband = t.number_or("deadband", 0.0);
  if (c.deadband < 0.0) t.fail("deadband", fmt::format("{} must be >= 0", c.deadband));
  c.deadband_first = t.get_or<bool>("deadband_first", false);
  const std::string apply_to = t.get_or<std::string>("apply_to", "both");
  if (apply_to != "both" && apply_to != "simulated")
    t.fail("apply_to",
           unknown_value_problem(apply_to, std::array<std::string_view, 2>{"both", "simulated"}));
  c.condition_measured = apply_to == "both";
  read_window(t, c);
  return c;
}

std::vector<std::string_view> channel_names(const std::vector<ChannelSpec>& channels) {
  std::vector<std::string_view> names;
  for (const ChannelSpec& c : channels) names.push_back(c.name);
  return names;
}

EventSpec event_of(const StrictTable& t, const std::vector<ChannelSpec>& channels) {
  t.allow_only({"name", "channel", "threshold"});
  EventSpec e;
  e.line = t.line();
  e.name = t.need_string("name");
  check_name(t, "name", e.name);
  e.channel = t.need_string("channel");
  const std::vector<std::string_view> names = channel_names(channels);
  if (std::find(names.begin(), names.end(), e.channel) == names.end())
    t.fail("channel", unknown_value_problem(e.channel, names));
  e.threshold = t.need_number("threshold");
  if (!(e.threshold > 0.0))
    t.fail("threshold",
           fmt::format("{} must be > 0 (|value| at or above it is the event)", e.threshold));
  return e;
}

// A channel's window = "<event>" names an event of the file.
void check_event_windows(const std::vector<StrictTable>& tables, const BenchMapping& m) {
  std::vector<std::string_view> names;
  for (const EventSpec& e : m.events) names.push_back(e.name);
  for (std::size_t i = 0; i < m.channels.size(); ++i) {
    const ChannelSpec& c = m.channels[i];
    if (c.window_event && !m.event(*c.window_event))
      tables[i].fail("window", names.empty()
                                   ? fmt::format("'{}' names no [[events]] entry (the file "
                                                 "has none)",
                                                 *c.window_event)
                                   : unknown_value_problem(*c.window_event, names));
  }
}

ClockAlignment alignment_of(const StrictTable& t, const std::vector<ChannelSpec>& channels) {
  t.allow_only({"channel", "threshold", "offsets"});
  ClockAlignment a;
  if (t.has("channel") == t.has("offsets"))
    t.fail("", "names either a trigger (channel and threshold) or offsets, one of the two");
  if (t.has("offsets")) {
    a.offsets = t.number_array("offsets");
    a.line = t.line_of_key("offsets");
    if (t.has("threshold")) t.fail("threshold", "only with a trigger channel");
    return a;
  }
  a.channel = t.need_string("channel");
  const std::vector<std::string_view> names = channel_names(channels);
  if (std::find(names.begin(), names.end(), *a.channel) == names.end())
    t.fail("channel", unknown_value_problem(*a.channel, names));
  a.threshold = t.need_number("threshold");
  a.line = t.line_of_key("threshold");
  if (!(a.threshold > 0.0))
    t.fail("threshold",
           fmt::format("{} must be > 0 (|value| reaching it is the trigger)", a.threshold));
  return a;
}

// The clock: time_column with time_unit, or sample_rate alone.
void read_clock(const StrictTable& t, BenchMapping& m) {
  if (t.has("time_column") == t.has("sample_rate"))
    t.fail("", "names either time_column (with time_unit) or sample_rate [Hz], one of the two");
  if (t.has("sample_rate")) {
    if (t.has("time_unit")) t.fail("time_unit", "only with time_column");
    m.sample_rate = t.need_number("sample_rate");
    if (!(m.sample_rate > 0.0))
      t.fail("sample_rate", fmt::format("{} Hz must be > 0", m.sample_rate));
    return;
  }
  m.time_column = t.need_string("time_column");
  m.time_unit = unit_of(t, "time_unit", m.time_factor);
  if (m.time_unit != "s" && m.time_unit != "ms" && m.time_unit != "us")
    t.fail("time_unit", fmt::format("'{}' is not a unit of time (s, ms, us)", m.time_unit));
}

char one_of(const StrictTable& t, std::string_view key, char fallback,
            std::initializer_list<std::pair<std::string_view, char>> allowed) {
  const std::optional<std::string> v = t.string(key);
  if (!v) return fallback;
  std::vector<std::string_view> names;
  for (const auto& [name, c] : allowed) {
    if (*v == name) return c;
    names.push_back(name);
  }
  t.fail(key, unknown_value_problem(*v, names));
}

void read_layout(const StrictTable& t, BenchMapping& m) {
  m.delimiter = one_of(t, "delimiter", ',', {{",", ','}, {";", ';'}, {"tab", '\t'}, {"\t", '\t'}});
  m.decimal = one_of(t, "decimal", '.', {{".", '.'}, {",", ','}});
  if (m.decimal == ',' && m.delimiter == ',')
    t.fail("decimal", "a decimal comma needs another delimiter (delimiter = \";\" or \"tab\")");
  m.header_line = static_cast<int>(t.get_or<long>("header_line", 0));
  if (t.has("header_line") && m.header_line < 1)
    t.fail("header_line", fmt::format("{} must be a line number, >= 1", m.header_line));
  m.skip_after_header = static_cast<int>(t.get_or<long>("skip_after_header", 0));
  if (m.skip_after_header < 0)
    t.fail("skip_after_header", fmt::format("{} must be >= 0", m.skip_after_header));
  m.comment = t.get_or<std::string>("comment", "");
  m.sparse = t.get_or<bool>("sparse", false);
  if (m.sparse && !t.has("time_column"))
    t.fail("sparse", "a sparse file needs its time column (the rows are not evenly spaced)");
}

}  // namespace

const ChannelSpec* BenchMapping::channel(const std::string& name) const {
  for (const ChannelSpec& c : channels)
    if (c.name == name) return &c;
  return nullptr;
}

const EventSpec* BenchMapping::event(const std::string& name) const {
  for (const EventSpec& e : events)
    if (e.name == name) return &e;
  return nullptr;
}

BenchMapping parse_bench_mapping(const std::string& text, const std::filesystem::path& file) {
  const toml::table root = parse_toml(text, file);
  const StrictTable top(root, "", file);
  top.allow_only({"trials", "align", "channels", "events"});
  BenchMapping m;
  m.file = file;
  const StrictTable trials = top.need_table("trials");
  trials.allow_only({"files", "time_column", "time_unit", "sample_rate", "delimiter", "decimal",
                     "header_line", "skip_after_header", "comment", "sparse"});
  m.files_pattern = trials.need_string("files");
  if (m.files_pattern.find('/') != std::string::npos)
    trials.fail("files", "a file-name pattern in the mapping file's folder, without '/'");
  read_clock(trials, m);
  read_layout(trials, m);
  std::set<std::string> names;
  const std::vector<StrictTable> channel_tables = top.need_tables("channels");
  for (const StrictTable& t : channel_tables) {
    ChannelSpec c = channel_of(t);
    if (!names.insert(c.name).second)
      t.fail("name", fmt::format("'{}' names an earlier channel too", c.name));
    if (!m.time_column.empty() && c.column == m.time_column)
      t.fail("column", fmt::format("'{}' is the time column", c.column));
    m.channels.push_back(std::move(c));
  }
  std::set<std::string> event_names;
  for (const StrictTable& t : top.tables("events")) {
    m.events.push_back(event_of(t, m.channels));
    if (!event_names.insert(m.events.back().name).second)
      t.fail("name", fmt::format("'{}' names an earlier event too", m.events.back().name));
  }
  check_event_windows(channel_tables, m);
  if (auto align = top.table("align")) m.align = alignment_of(*align, m.channels);
  return m;
}

BenchMapping read_bench_mapping(const std::filesystem::path& file) {
  return parse_bench_mapping(read_config_text(file), file);
}

}  // namespace ccm::bench
