// What `ccm validate` prints and writes (docs/bench-test.md): the scores as a table and as JSON,
// and each channel's compared curves as CSV.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/bench_scores.hpp"

namespace ccm {

// Every channel's scores; `left_out` names the trials a fit did not see (marked in the output).
nlohmann::json scores_json(const bench::BenchScores& scores,
                           const std::set<std::string>& left_out = {});

void print_scores(const bench::BenchScores& scores, const std::set<std::string>& left_out = {});

// One channel's compared curves as CSV: time, simulated, mean, low, high.
std::string channel_curves_csv(const bench::ChannelCurves& curves);

// <out>/<channel>.csv for every channel.
void write_channel_curves(const std::filesystem::path& out, const bench::BenchScores& scores);

}  // namespace ccm
