// `ccm study run GRID --db FILE [--jobs N]`, `ccm study status --db FILE [--json]`,
// `ccm rig list [--cases FILE] [--json]`,
// `ccm recommend --db FILE --er X --rls Y --ke Z [--max-error E] [--axis NAME=VALUE]... [--json]`
// and
// `ccm report --db FILE --out DIR [--max-error E]`.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "study/recommend/decision_rule.hpp"

namespace ccm {

struct StudyRunArgs {
  std::filesystem::path grid;
  std::filesystem::path db;
  int jobs = 1;        // local worker processes (without MPI)
  bool quiet = false;  // no progress line, no tables
  int threads = 0;     // per run; 0: CCM_THREADS, else threads_per_job (run_schedule.hpp)
};

struct StudyRefineArgs {
  std::filesystem::path db;
  std::string axis;        // "ER" or a template's coordinate path; "": ER, or the first path
  double tolerance = 0.0;  // the boundary's width when resolved; 0: a quarter of the finest
                           // spacing of the axis's grid values
  long budget = 0;         // the study's runs at most (its grid's too); 0: twice the grid's
  double max_error = 0.1;  // the rule's threshold (study/recommend/decision_rule.hpp)
  int jobs = 1;
  bool quiet = false;
  bool json = false;  // the boundaries and runs as one JSON document
  int threads = 0;
};

struct StudySceneArgs {
  std::filesystem::path grid;
  int point = 0;              // a grid or convergence point's index (as in `ccm study run`)
  std::string model = "ccm";  // ccm or rigid
};

struct StudyStatusArgs {
  std::filesystem::path db;
  bool json = false;
};

struct RecommendArgs {
  std::filesystem::path db;
  double er = 1.0, rls = 1.0, ke = 0.0;
  double max_error = study::kDefaultMaxError;  // the decision rule's error threshold
  std::vector<std::string> axes;               // "name=value", one per other grid axis
  bool json = false;
};

struct ReportArgs {
  std::filesystem::path db;
  std::filesystem::path out;
  double max_error = study::kDefaultMaxError;  // the decision rule's error threshold
};

struct RigListArgs {
  std::filesystem::path cases;  // default: rig/cases.toml of the data folder (app/data_paths.hpp)
  bool json = false;
};

struct RigMappingArgs {
  std::string case_code;
  std::filesystem::path cases;                // default: rig/cases.toml of the data folder
  std::optional<std::filesystem::path> data;  // a trial folder whose rig.toml sets the sensor
};

// Each returns the process exit code (app/run_command.hpp exit_code).
int study_run_command(const StudyRunArgs& args);
int study_status_command(const StudyStatusArgs& args);
int study_refine_command(const StudyRefineArgs& args);
int study_scene_command(const StudySceneArgs& args);
int recommend_command(const RecommendArgs& args);
int rig_list_command(const RigListArgs& args);
int rig_mapping_command(const RigMappingArgs& args);
int report_command(const ReportArgs& args);

}  // namespace ccm
