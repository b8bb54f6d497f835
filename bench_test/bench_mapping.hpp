// The mapping file of a bench test (docs/bench-test.md): which measured column is which output of
// the scene, in which unit, filtered how, scored over which window, and how each trial's clock is
// aligned with the simulation's. Read as strictly as a scene file: an unknown key, a unit ccm
// does not know, a filter it cannot build, or a window that is not a window is a ConfigError
// naming the file, the line and the key.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ccm::bench {

// The file name `ccm validate --data FOLDER` looks for in the folder.
inline constexpr const char* kMappingFileName = "bench.toml";

enum class FilterKind { none, cfc, low_pass };

struct ChannelFilter {
  FilterKind kind = FilterKind::none;
  double frequency = 0.0;  // the CFC class, or the low-pass cutoff [Hz]
};

struct ChannelSpec {
  std::string name;
  std::string column;      // in the trial files' header
  std::string unit;        // of the column; converted to SI on reading
  double si_factor = 1.0;  // from units.hpp
  std::string observable;  // a history column of the scene, or a vector's prefix (docs)
  std::optional<std::array<double, 3>> axis;  // unit vector; for a vector observable
  bool derivative = false;                    // the observable's rate (a velocity's acceleration)
  double scale = 1.0;     // multiplies the simulated observable (sign conventions)
  ChannelFilter filter;   // applied alike to the measured and the simulated curve
  double deadband = 0.0;  // SI; |value| below it reads 0, on both curves
  // deadband_first = true: the deadband before the filter (a sensor's own threshold, filtered
  // after it by the logger or the rig's post-processing); default after the filter.
  bool deadband_first = false;
  // apply_to = "simulated": the filter and the deadband condition the simulated curve alone (the
  // logger filtered in hardware, the sensor's deadband is in the data already).
  bool condition_measured = true;
  std::optional<std::array<double, 2>> window;  // s, on the simulation's clock
  // window = "<event>": each trial's own measured window of that event (EventSpec), aligned.
  std::optional<std::string> window_event;
  int observable_line = 0;  // of its observable key
  int line = 0;             // of the channel's table in the mapping file, for messages
};

struct ClockAlignment {
  // Trigger: the time the channel's |value| (filtered) first reaches `threshold` is made the
  // same on the trial's clock and the simulation's.
  std::optional<std::string> channel;
  double threshold = 0.0;
  // Or given offsets [s], added to each trial's clock, one per trial in file-name order.
  std::vector<double> offsets;
  int line = 0;  // of the threshold or the offsets, for messages
};

// [[events]]: the first event of a channel in each trial and in the simulation, from the first
// sample whose |value| (conditioned, SI) is at or above `threshold` to the first later sample
// below it (a contact: its onset and duration); their errors are reported, and a channel may
// be scored inside each trial's measured event alone (window = "<name>").
struct EventSpec {
  std::string name;
  std::string channel;
  double threshold = 0.0;  // SI, > 0
  int line = 0;
};

struct BenchMapping {
  std::filesystem::path file;  // the mapping file
  std::string files_pattern;   // glob of the trial files, in the mapping file's folder
  // The clock: a time column in a unit, or (no time column) a sample rate, the rows its samples.
  std::string time_column;
  std::string time_unit;
  double time_factor = 1.0;
  double sample_rate = 0.0;  // Hz; > 0 only without a time column
  // The file's layout (docs/bench-test.md, "Trial files from other tools").
  char delimiter = ',';
  char decimal = '.';
  int header_line = 0;        // 1-based line of the column names; 0: the first non-blank line
  int skip_after_header = 0;  // lines between the header and the data (a units row)
  std::string comment;        // lines that begin with it are skipped ("#"); empty: none
  bool sparse = false;        // a channel's cell may be empty (sensors at their own rates)
  ClockAlignment align;
  std::vector<ChannelSpec> channels;
  std::vector<EventSpec> events;

  const ChannelSpec* channel(const std::string& name) const;
  const EventSpec* event(const std::string& name) const;
};

// Reads and checks `file`; throws ConfigError.
BenchMapping read_bench_mapping(const std::filesystem::path& file);

// The same from text (`file` names it in messages).
BenchMapping parse_bench_mapping(const std::string& text, const std::filesystem::path& file);

}  // namespace ccm::bench
