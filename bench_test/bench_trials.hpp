// Reading the trials of a bench test: one CSV file per trial, matched by the mapping's file
// pattern in its folder and taken in name order. A header row names the columns; the time
// column and every channel's column must be there (others are ignored); every row has every
// cell, a finite number (in a sparse file, a channel's cell may be empty where its sensor did not
// sample; the time never). Lines that begin with the mapping's comment mark are skipped. Values
// are converted to SI by the mapping's units. Refused with a
// ConfigError naming the file, the line and the column: a file that cannot be read, no header,
// a missing or repeated column, a row with the wrong number of cells, a non-numeric or
// non-finite cell, time going backwards or repeating, a forward jump of the clock beyond 100
// median steps (rig_models/measurement/clock_jump.hpp), fewer than 10 rows. Also when no file
// matches, or the mapping's offsets are not one per trial.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "bench_test/bench_mapping.hpp"
#include "rig_models/signal/time_series.hpp"

namespace ccm::bench {

struct BenchTrial {
  std::filesystem::path file;
  std::vector<double> t;  // s, every row's time on the trial's own clock, strictly increasing
  // By channel name, SI: the rows where the channel's cell is filled (every row unless the
  // mapping says the file is sparse).
  std::map<std::string, rig::TimeSeries> channels;
};

// The trial of one file's text (`source` names it in messages).
BenchTrial parse_bench_trial(std::string_view text, const std::filesystem::path& source,
                             const BenchMapping& mapping);

// Every trial of the mapping, in file-name order.
std::vector<BenchTrial> read_bench_trials(const BenchMapping& mapping);

}  // namespace ccm::bench
