// What `ccm validate` prints and writes (docs/bench-test.md): the scores as a table and as JSON,
// and each channel's compared curves as CSV.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/bench_scores.hpp"

namespace ccm {

// The scores, or none after saying on stderr why the run's curves cannot be scored (a trigger
// the simulation never reaches, a window without samples): `ccm validate` then exits 3.
std::optional<bench::BenchScores> scored(const bench::BenchMapping& mapping,
                                         const std::vector<bench::PreparedTrial>& trials,
                                         const std::map<std::string, rig::TimeSeries>& simulated);

// Every channel's scores; `left_out` names the trials a fit did not see (marked in the output).
nlohmann::json scores_json(const bench::BenchScores& scores,
                           const std::set<std::string>& left_out = {});

void print_scores(const bench::BenchScores& scores, const std::set<std::string>& left_out = {});

// One channel's compared curves as CSV: time, simulated, mean, low, high.
std::string channel_curves_csv(const bench::ChannelCurves& curves);

// <out>/<channel>.csv for every channel.
void write_channel_curves(const std::filesystem::path& out, const bench::BenchScores& scores);

}  // namespace ccm
