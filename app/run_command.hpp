// `ccm run SCENE --out DIR`: parse, validate and mesh everything, and only then create DIR, run
// and write history.csv, summary.toml and a copy of the scene into it.
#pragma once

#include <filesystem>

namespace ccm {

// Process exit codes of the ccm command line.
namespace exit_code {
constexpr int completed = 0;
constexpr int internal_error = 1;
constexpr int bad_input = 2;
constexpr int unstable = 3;
}  // namespace exit_code

struct RunArgs {
  std::filesystem::path scene;  // "-": read the scene from stdin (relative paths: the cwd's)
  std::filesystem::path out;
  bool quiet = false;   // no progress line and no summary table
  bool fields = false;  // write every field (docs/fields.md), whatever [output] fields says
  int threads = 0;      // 0: CCM_THREADS, else the cores available (resolve_threads)
};

// The name a scene read from stdin goes by in messages.
inline constexpr const char* kStdinSceneName = "<stdin>";

// The thread count of a run: `requested` when positive, else CCM_THREADS when set, else
// `automatic`. Throws std::invalid_argument for a negative request or a bad CCM_THREADS.
int resolve_threads(int requested, int automatic);

// Runs the scene and returns the exit code. Messages go to stderr as "ccm: error: ...";
// the summary table goes to stdout.
int run_command(const RunArgs& args);

}  // namespace ccm
