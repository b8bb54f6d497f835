#include "app/bench_run.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "bench_test/bench_trials.hpp"

namespace ccm {

BenchData load_bench_data(const std::filesystem::path& folder) {
  const std::filesystem::path mapping_file = folder / bench::kMappingFileName;
  if (!std::filesystem::is_directory(folder))
    throw std::invalid_argument(fmt::format("--data {}: not a folder", folder.string()));
  if (!std::filesystem::exists(mapping_file))
    throw std::invalid_argument(fmt::format(
        "--data {}: has no {} (the mapping from measured channels to the scene's outputs, "
        "docs/bench-test.md)",
        folder.string(), bench::kMappingFileName));
  BenchData d{bench::read_bench_mapping(mapping_file), {}};
  d.trials = bench::prepare_trials(d.mapping, bench::read_bench_trials(d.mapping));
  return d;
}

BenchRun::BenchRun(Scene scene, const bench::BenchMapping& mapping)
    : mapping_(&mapping), run_(assemble_scene_run(std::move(scene))) {
  history_ = std::make_unique<HistoryRecorder>(run_.model.mesh, run_.output);
  // The options add the contact's history columns: the observables are looked up after them.
  options_ = scene_run_options(run_, history_.get());
  for (const bench::ChannelSpec& c : mapping.channels)
    observables_.push_back(bench::resolve_observable(c, history_->columns(), mapping.file));
}

const RunSummary& BenchRun::run(ProgressFn progress) {
  options_.progress = std::move(progress);
  summary_ = run_explicit(run_.model, options_);
  return summary_;
}

std::map<std::string, rig::TimeSeries> BenchRun::simulated() const {
  std::map<std::string, rig::TimeSeries> out;
  for (std::size_t i = 0; i < mapping_->channels.size(); ++i)
    out[mapping_->channels[i].name] =
        bench::simulated_curve(mapping_->channels[i], observables_[i], history_->rows());
  return out;
}

}  // namespace ccm
