// A scene run to its end in the test's process, and the columns of its history by name: for
// tests that compare whole runs (tests/run/compare/).
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "run/scene/scene_run.hpp"

namespace ccm::test {

class SceneHistory {
 public:
  // Runs `scene`; REQUIREs that it completes.
  explicit SceneHistory(Scene scene) : run_(assemble_scene_run(std::move(scene))) {
    HistoryRecorder history(run_.model.mesh, run_.output);
    RunOptions opt = scene_run_options(run_, &history);
    const RunSummary s = run_explicit(run_.model, opt);
    INFO(s.instability.reason);
    REQUIRE(s.verdict == Verdict::completed);
    columns_ = history.columns();
    rows_ = history.rows();
  }
  // The column named `name` (REQUIREd to exist), one value per sample.
  std::vector<double> column(const std::string& name) const {
    const auto c =
        static_cast<size_t>(std::find(columns_.begin(), columns_.end(), name) - columns_.begin());
    REQUIRE(c < columns_.size());
    std::vector<double> out;
    for (const auto& row : rows_) out.push_back(row[c]);
    return out;
  }

 private:
  SceneRun run_;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
};

}  // namespace ccm::test
