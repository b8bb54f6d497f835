// The ccm command line: `ccm --version`, `ccm run SCENE --out DIR [--quiet]`,
// `ccm study run GRID --db FILE [--jobs N]`, `ccm study status --db FILE [--json]`,
// `ccm study scene GRID --point N [--model ccm|rigid]`,
// `ccm recommend --db FILE --er X --rls Y --ke Z [--max-error E] [--axis N=V]... [--json]`,
// `ccm report --db FILE --out DIR [--max-error E]`, `ccm rig list [--json]`,
// `ccm rig run CASE [--data DIR --trial N] [--drive open-loop|physical] [--out DIR] [--db FILE]
// [--json]`,
// `ccm rig calibrate CASE --params mu_s,mu_k[,...] --data DIR [...]`,
// `ccm mesh info FILE [--json] [--material E,NU,RHO]`,
// `ccm compare SCENE --rigid BODY[,BODY...] [--observe COL,...] [--max-error E] [--out DIR]
// [--json]`.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <CLI/CLI.hpp>

#include "app/command_words.hpp"
#include "app/compare_command.hpp"
#include "app/data_paths.hpp"
#include "app/mesh_commands.hpp"
#include "app/rig_commands.hpp"
#include "app/run_command.hpp"
#include "app/study_commands.hpp"
#include "app/validate_command.hpp"
#include "engine/mesh/mesh_cache.hpp"
#include "records/provenance/version.hpp"
#include "rig_models/sim/run_parameters.hpp"

namespace {

// The exit codes of every subcommand, for the top level's and the groups' --help.
constexpr const char* kExitCodes =
    "Exit codes: 0 success, 1 internal error, 2 bad input (nothing written), 3 unstable run "
    "(results up to the instability written). Each subcommand's --help lists its own.";

// The options `ccm rig run` and `ccm rig calibrate` share.
void add_rig_options(CLI::App* app, ccm::RigCommonArgs& a) {
  a.cases = ccm::default_data_file("rig/cases.toml");
  a.geometry = ccm::default_data_file("rig/geometry.toml");
  app->add_option("CASE", a.case_code, "Case code of thesis Table 3.2 (RX025 ... FF100)")
      ->required();
  app->add_option("--data", a.data,
                  "Folder of measured trials <CASE>_t<N>.csv (every file is read and checked "
                  "before anything runs)");
  app->add_option("--trial", a.trial,
                  "Trial that drives the run (open loop) or gives its gap (physical); default 2, "
                  "the trial the thesis simulated");
  app->add_option("--drive", a.drive,
                  "open-loop (default: the thesis's drive, F = M_i dV_i/dt of the measured "
                  "velocity, 3.3.2) or physical (hanging weight through a pulley, slack string, "
                  "track friction)")
      ->capture_default_str();
  app->add_option("--start", a.start, "Start of the simulated window [s, trial time] (open loop)");
  app->add_option("--end", a.end, "End of the simulated window [s, trial time]");
  app->add_option("--mesh-scale", a.mesh_scale, "Every mesh size times this (2: coarser, faster)")
      ->capture_default_str();
  app->add_option("--set", a.set,
                  fmt::format("Run parameter name=value ({}); repeatable",
                              fmt::join(ccm::rig::kRunParameterNames, ", ")));
  app->add_flag("--score-drive-trial", a.score_drive_trial,
                "Open loop: score the run on the trial that drives it too (left out by default: "
                "its V_i before contact and its contact onset are the run's input)");
  app->add_option("--cases", a.cases, "Case file (TOML)")->capture_default_str();
  app->add_option("--geometry", a.geometry, "Rig geometry file (TOML)")->capture_default_str();
  app->add_option("--out,-o", a.out,
                  "Folder for channels.csv, history.csv and summary.toml (written only after a "
                  "run)");
  app->add_option("--db", a.db,
                  "Store (SQLite; created if absent); default <out>/rig.sqlite, else ./rig.sqlite");
  app->add_flag("--quiet,-q", a.quiet, "No progress line and no tables");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ccm: explicit finite-element simulations of soft bodies", "ccm"};
  app.set_version_flag("--version", "ccm " + ccm::version_string());
  app.require_subcommand(1);
  app.footer(kExitCodes);

  ccm::RunArgs args;
  CLI::App* run = app.add_subcommand("run", "Run a scene file and write its results into a folder");
  run->add_option("SCENE", args.scene,
                  "Scene file (TOML; see docs/scene-file.md); - reads it from stdin")
      ->required();
  run->add_option("--out,-o", args.out,
                  "Output folder for history.csv, summary.toml and scene.toml (created only "
                  "once the scene has been read and meshed)")
      ->required();
  run->add_flag("--quiet,-q", args.quiet, "No progress line and no summary table");
  run->add_flag("--fields", args.fields,
                "Write every field (fields.xdmf + fields.h5 for ParaView, docs/fields.md) at the "
                "scene's field_interval, whatever its [output] fields says");
  run->add_option("--threads", args.threads,
                  "Threads for the structure (0, the default: $CCM_THREADS, else the cores "
                  "available); the result is bitwise the same for any count");
  run->footer(
      "Exit codes: 0 completed, 1 internal error, 2 bad input (nothing written), 3 unstable "
      "(results up to the instability written).");

  ccm::CompareArgs compare_args;
  CLI::App* compare = app.add_subcommand(
      "compare",
      "Run a scene as written and with bodies rigid: the rigid run's errors, the cost ratio and "
      "whether rigid is good enough (docs/compare.md)");
  compare->add_option("SCENE", compare_args.scene, "Scene file (TOML; docs/scene-file.md)")
      ->required();
  compare
      ->add_option("--rigid", compare_args.rigid,
                   "Bodies to make rigid, comma-separated (each deformable in the scene)")
      ->required()
      ->delimiter(',');
  compare
      ->add_option("--observe", compare_args.observe,
                   "History columns to compare, comma-separated (default: u_mean, u_max and "
                   "kinetic_energy of every body that stays deformable)")
      ->delimiter(',');
  compare
      ->add_option("--max-error", compare_args.max_error,
                   "Rigid is good enough where every final-state error is within this and it is "
                   "cheaper")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  compare->add_option("--out,-o", compare_args.out,
                      "Folder for the two runs (kept under their content hash: asking again "
                      "reuses them) and comparison.json; default compare-<scene name>");
  compare->add_option("--db", compare_args.db,
                      "Study store whose prediction for this scene's groups is shown beside the "
                      "measured answer, and where the comparison is recorded (default: the "
                      "prediction from the reference store ccm ships when installed, else from "
                      "results/default-study.sqlite; the record in results/default-study.sqlite)");
  compare->add_flag("--json", compare_args.json, "Print the comparison as JSON");
  compare->add_flag("--quiet,-q", compare_args.quiet, "No progress line");
  compare->add_option("--threads", compare_args.threads, "As `ccm run --threads`");
  compare->footer(
      "Exit codes: 0 compared, 1 internal error, 2 bad input (nothing run, nothing written), 3 a "
      "run went unstable (no answer; what it left is written).");

  ccm::ValidateArgs validate_args;
  CLI::App* validate = app.add_subcommand(
      "validate",
      "Run a scene once and rate it against your bench test's trials: nRMSE, peaks and the "
      "ISO/TS 18571 rating per channel and trial (docs/bench-test.md)");
  validate->add_option("SCENE", validate_args.scene, "Scene file (TOML; docs/scene-file.md)")
      ->required();
  validate
      ->add_option("--data", validate_args.data,
                   "Folder of the trials and of bench.toml, the mapping from measured channels "
                   "to the scene's outputs")
      ->required();
  validate->add_option("--out,-o", validate_args.out,
                       "Folder for history.csv, validation.json and one CSV per channel; default "
                       "validate-<scene name>");
  validate->add_option("--fit", validate_args.fit,
                       "PATH=LO:HI: fit the scene's number at PATH (the path syntax of grids over "
                       "a scene) within [LO, HI] to the trials; repeat for more parameters");
  validate
      ->add_option("--fit-trials", validate_args.fit_trials,
                   "Trials to fit to, comma-separated, 1-based in file-name order (default: all "
                   "but the last); the others are left out and scored with the fitted values")
      ->delimiter(',');
  validate->add_flag("--cross-validate", validate_args.cross_validate,
                     "With --fit: leave each trial out in turn (fit on the others, score on it), "
                     "then fit on every trial");
  validate
      ->add_option("--evaluations", validate_args.evaluations,
                   "Runs the fit's search may use (the sensitivity profile adds 2-3 per "
                   "parameter)")
      ->capture_default_str();
  validate->add_option("--db", validate_args.db,
                       "Store to record the validation in, for `ccm report` (default: "
                       "results/default-study.sqlite when it exists)");
  validate->add_flag("--json", validate_args.json, "Print the scores as JSON");
  validate->add_flag("--quiet,-q", validate_args.quiet, "No progress line");
  validate->add_option("--threads", validate_args.threads, "As `ccm run --threads`");
  validate->footer(
      "Exit codes: 0 rated, 1 internal error, 2 bad input (nothing run, nothing written), 3 no "
      "rating: the run went unstable or cannot be scored against the trials (its history is "
      "written).");

  ccm::StudyRunArgs study_run_args;
  ccm::StudyStatusArgs study_status_args;
  CLI::App* study = app.add_subcommand("study", "Trade studies: run a grid, show its status");
  study->require_subcommand(1);
  study->footer(kExitCodes);
  CLI::App* study_run = study->add_subcommand(
      "run",
      "Run every point of a grid file (both models) not yet in the store, then its "
      "metrics, fits and recommendation table");
  study_run->add_option("GRID", study_run_args.grid, "Grid file (TOML; see docs/grid-file.md)")
      ->required();
  study_run->add_option("--db", study_run_args.db, "Study store (SQLite; created if absent)")
      ->required();
  study_run
      ->add_option("--jobs,-j", study_run_args.jobs,
                   "Local worker processes (under mpirun each rank is one worker)")
      ->default_val(1);
  study_run->add_flag("--quiet,-q", study_run_args.quiet, "No progress line and no tables");
  study_run->add_option("--threads", study_run_args.threads,
                        "Threads per run (0, the default: $CCM_THREADS, else the cores available "
                        "divided among the --jobs workers; 1 per MPI rank)");
  study_run->footer(
      "Resumes where a killed study stopped. Exit codes: 0 done, 1 some run failed or internal "
      "error, 2 bad input.");
  CLI::App* study_status =
      study->add_subcommand("status", "Done / running / failed / unstable per grid point");
  study_status->add_option("--db", study_status_args.db, "Study store (SQLite; only read)")
      ->required();
  study_status->add_flag("--json", study_status_args.json, "Print the status as JSON");
  study_status->footer(
      "Exit codes: 0 printed, 1 internal error, 2 bad input (no such file, not a ccm store, no "
      "study in it). Never writes a file.");

  ccm::StudyRefineArgs refine_args;
  CLI::App* study_refine = study->add_subcommand(
      "refine",
      "Add points where a study's answer changes (between neighbours with different answers, "
      "and next to points the fits flag) until the boundary is located or the budget is spent");
  study_refine->add_option("--db", refine_args.db, "Study store of `ccm study run`")->required();
  study_refine->add_option("--axis", refine_args.axis,
                           "The axis refined: ER (the thesis grid) or a path of a grid over a "
                           "scene (default: ER, or the grid's first path)");
  study_refine->add_option("--tolerance", refine_args.tolerance,
                           "The boundary's width when located: decades on an axis of one sign, "
                           "else its units (default: a quarter of the grid's finest spacing)");
  study_refine->add_option("--budget", refine_args.budget,
                           "The study's runs at most, its grid's included (default: twice the "
                           "grid's)");
  study_refine->add_option("--max-error", refine_args.max_error, "As `ccm recommend`")
      ->default_val(0.1);
  study_refine->add_option("--jobs,-j", refine_args.jobs, "Local worker processes")->default_val(1);
  study_refine->add_flag("--quiet,-q", refine_args.quiet, "No progress line");
  study_refine->add_flag("--json", refine_args.json,
                         "Print the boundaries and the runs as JSON (instead of the text)");
  study_refine->add_option("--threads", refine_args.threads, "As `ccm study run --threads`");
  study_refine->footer(
      "Resumes where a killed refine stopped (its points' runs first). Exit codes: 0 done, 1 some "
      "run failed or internal error, 2 bad input.");

  ccm::StudySceneArgs study_scene_args;
  CLI::App* study_scene = study->add_subcommand(
      "scene", "Print the scene file of one run of a grid (to repeat it with `ccm run`)");
  study_scene->add_option("GRID", study_scene_args.grid, "Grid file (TOML)")->required();
  study_scene->add_option("--point,-p", study_scene_args.point, "Point index (as in the tables)")
      ->required();
  study_scene->add_option("--model,-m", study_scene_args.model, "ccm or rigid")
      ->check(CLI::IsMember({"ccm", "rigid"}))
      ->default_val("ccm");
  study_scene->footer("Exit codes: 0 printed, 1 internal error, 2 bad input.");

  ccm::RecommendArgs rec;
  CLI::App* recommend = app.add_subcommand(
      "recommend", "Which impactor model to use at a design point, and why (from a study)");
  recommend->add_option("--db", rec.db,
                        "Study store (SQLite); default the reference store ccm ships "
                        "(share/ccm/reference/whole-impacts.sqlite)");
  recommend->add_option("--er", rec.er, "Modulus ratio E_impactor / E_artifact")->required();
  recommend->add_option("--rls", rec.rls, "Length ratio D_impactor / L_artifact")->required();
  recommend->add_option("--ke", rec.ke, "Impactor kinetic energy [J]")->required();
  recommend
      ->add_option("--max-error", rec.max_error,
                   "Use rigid where its final-state errors are all within this and it is cheaper")
      ->capture_default_str();
  recommend->add_option("--axis", rec.axes,
                        "Level of another grid axis, name=value (repeatable; required for an "
                        "axis with several levels)");
  recommend->add_flag("--json", rec.json, "Print the recommendation as JSON");
  recommend->footer(
      "Exit codes: 0 answered, 1 internal error, 2 bad input (no such store, no fits, a bad "
      "axis). Never writes a file.");

  ccm::ReportArgs report_args;
  CLI::App* report = app.add_subcommand(
      "report", "Write a study's self-contained HTML report (figures as SVG, tables as CSV)");
  report->add_option("--db", report_args.db, "Study store (SQLite)")->required();
  report->add_option("--out,-o", report_args.out, "Report folder (replaced whole)")->required();
  report
      ->add_option("--max-error", report_args.max_error,
                   "Error threshold of the decision rule (as `ccm recommend --max-error`)")
      ->capture_default_str();
  report->footer(
      "Exit codes: 0 written, 1 internal error (e.g. gnuplot missing), 2 bad input. Writes the "
      "report folder only, never the store.");

  ccm::RigListArgs rig_list_args;
  CLI::App* rig = app.add_subcommand("rig", "Benchtop rig models (thesis chapter 3)");
  rig->require_subcommand(1);
  rig->footer(kExitCodes);
  CLI::App* rig_list = rig->add_subcommand("list", "The 12 cases of thesis Table 3.2");
  rig_list_args.cases = ccm::default_data_file("rig/cases.toml");
  rig_list->add_option("--cases", rig_list_args.cases, "Case file (TOML)")->capture_default_str();
  rig_list->add_flag("--json", rig_list_args.json, "Print the parameters and cases as JSON");
  rig_list->footer("Exit codes: 0 printed, 2 bad input (the case file missing or defective).");
  ccm::RigMappingArgs rig_mapping_args;
  CLI::App* rig_mapping = rig->add_subcommand(
      "mapping",
      "Print a case's bench-test mapping (bench.toml): the channels, sensor model and "
      "contact event ccm rig run scores through (docs/bench-test.md)");
  rig_mapping->add_option("CASE", rig_mapping_args.case_code, "Case code (RX025 ... FF100)")
      ->required();
  rig_mapping_args.cases = ccm::default_data_file("rig/cases.toml");
  rig_mapping->add_option("--cases", rig_mapping_args.cases, "Case file (TOML)")
      ->capture_default_str();
  rig_mapping->add_option("--data", rig_mapping_args.data,
                          "Trial folder whose rig.toml gives the sensor's deadband and low-pass");
  rig_mapping->footer("Exit codes: 0 printed, 2 bad input (a file defective, an unknown case).");
  ccm::RigCommonArgs rig_run_args;
  CLI::App* rig_run = rig->add_subcommand(
      "run", "Simulate a case, compare it with its measured trials, store and print the result");
  add_rig_options(rig_run, rig_run_args);
  rig_run->add_flag("--fields", rig_run_args.fields,
                    "Also write every field into --out (fields.xdmf + fields.h5 for ParaView, "
                    "docs/fields.md)");
  rig_run->add_option("--field-interval", rig_run_args.field_interval,
                      "Time between field frames [s]; a whole multiple of the case's output "
                      "interval; default 10 output intervals");
  rig_run->add_flag("--json", rig_run_args.json,
                    "Print the run, its comparison and where it is stored as JSON (instead of "
                    "the tables)");
  rig_run->footer(
      "Exit codes: 0 completed, 1 internal error, 2 bad input (nothing written), 3 unstable "
      "(results up to the instability stored and written).");
  ccm::RigCalibrateArgs rig_calibrate_args;
  CLI::App* rig_calibrate = rig->add_subcommand(
      "calibrate",
      "Tune friction and stiffness parameters against the measured trials (NLopt, bounded, "
      "derivative-free)");
  add_rig_options(rig_calibrate, rig_calibrate_args.common);
  rig_calibrate
      ->add_option("--params", rig_calibrate_args.params,
                   fmt::format("Parameters to tune, comma-separated: {}",
                               fmt::join(ccm::rig::kRunParameterNames, ", ")))
      ->required();
  rig_calibrate->add_option("--bounds", rig_calibrate_args.bounds,
                            "Search range name=lower:upper (repeatable; defaults in "
                            "docs/rig-models.md)");
  rig_calibrate
      ->add_option("--max-evals", rig_calibrate_args.max_evaluations,
                   "Most simulations the search may run")
      ->capture_default_str();
  rig_calibrate->add_option(
      "--predict", rig_calibrate_args.predict,
      "Cases left out of the fit, comma-separated, of the fitted case's "
      "configuration: each run with the starting and the calibrated "
      "parameters and scored on its own trials (--start and --end moved to its own contact onset)");
  rig_calibrate->add_option(
      "--fit-trials", rig_calibrate_args.fit_trials,
      "Trials the search fits, comma-separated (default: every trial the run is scored on); "
      "the run's other scored trials are left out of the fit and scored with the start and the "
      "calibrated parameters");
  rig_calibrate->add_flag("!--no-profile", rig_calibrate_args.profile,
                          "Skip the parameters' spread after the fit (2-3 runs per parameter)");
  rig_calibrate
      ->add_option("--jobs,-j", rig_calibrate_args.jobs,
                   "Runs at once (threads, one core each): the search's opening points, the "
                   "profile's and the predictions' runs; the result is the same for any count")
      ->default_val(1);
  rig_calibrate->footer("Exit codes: 0 done, 1 internal error, 2 bad input (nothing written).");

  ccm::MeshInfoArgs mesh_info_args;
  CLI::App* mesh = app.add_subcommand("mesh", "Mesh files (.msh, .unv, .inp, .geo)");
  mesh->require_subcommand(1);
  mesh->footer(kExitCodes);
  CLI::App* mesh_info = mesh->add_subcommand(
      "info", "Node and tet counts, extent, named groups and element quality of a mesh file");
  mesh_info->add_option("FILE", mesh_info_args.file, "Mesh file (see docs/meshes.md)")->required();
  mesh_info->add_flag("--json", mesh_info_args.json, "Print the figures as JSON");
  mesh_info
      ->add_option("--material", mesh_info_args.material,
                   "E,NU,RHO (Pa, -, kg/m^3): also print the stable step h_e / c_d of the worst "
                   "tets and of the median tet")
      ->expected(3)
      ->delimiter(',');
  mesh_info->footer(
      "Exit codes: 0 read, 1 internal error, 2 bad input (the message names the "
      "file, the line and the dataset or keyword).");

  // Every command that meshes reads its meshes back from the mesh cache (docs/mesh-cache.md).
  bool no_mesh_cache = false;
  for (CLI::App* meshes : {run, compare, validate, study_run, study_refine, rig_run, rig_calibrate})
    meshes->add_flag("--no-mesh-cache", no_mesh_cache,
                     "Mesh every body afresh and file nothing (also CCM_MESH_CACHE=off)");

  if (const auto unknown = ccm::unknown_command(app, argc, argv)) {
    fmt::print(stderr, "ccm: error: {}\nRun 'ccm --help' for usage.\n", *unknown);
    return ccm::exit_code::bad_input;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    fmt::print(stderr, "ccm: error: {}\nRun 'ccm --help' for usage.\n", e.what());
    return ccm::exit_code::bad_input;
  }
  if (no_mesh_cache) {
    ccm::MeshCacheSettings off = ccm::mesh_cache_settings();
    off.enabled = false;
    ccm::set_mesh_cache_settings(off);
  }
  if (*study_run) return ccm::study_run_command(study_run_args);
  if (*study_status) return ccm::study_status_command(study_status_args);
  if (*study_refine) return ccm::study_refine_command(refine_args);
  if (*study_scene) return ccm::study_scene_command(study_scene_args);
  if (*recommend) return ccm::recommend_command(rec);
  if (*rig_list) return ccm::rig_list_command(rig_list_args);
  if (*rig_mapping) return ccm::rig_mapping_command(rig_mapping_args);
  if (*rig_run) return ccm::rig_run_command(rig_run_args);
  if (*rig_calibrate) return ccm::rig_calibrate_command(rig_calibrate_args);
  if (*report) return ccm::report_command(report_args);
  if (*mesh_info) return ccm::mesh_info_command(mesh_info_args);
  if (*compare) return ccm::compare_command(compare_args);
  if (*validate) return ccm::validate_command(validate_args);
  return ccm::run_command(args);
}
