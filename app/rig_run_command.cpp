// `ccm rig run`: read and check every input (measured data included), open the store, run the
// case once, compare it with every trial, then store, write and print.
#include <fmt/format.h>

#include <filesystem>

#include "app/json_output.hpp"
#include "app/rig_command_errors.hpp"
#include "app/rig_commands.hpp"
#include "app/rig_run_json.hpp"
#include "app/rig_runner.hpp"
#include "app/run_command.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/observe/field_catalog.hpp"
#include "rig_models/core/rig_error.hpp"

namespace ccm {
namespace {

// --fields writes into --out; --field-interval is a whole multiple of the case's output interval.
void check_field_args(const RigCommonArgs& args, const RigInputs& in) {
  if (args.field_interval && !args.fields)
    throw std::invalid_argument("--field-interval applies only with --fields");
  if (!args.fields) return;
  if (!args.out)
    throw std::invalid_argument("--fields writes into the output folder: give --out DIR");
  if (!args.field_interval) return;
  const double output_interval = in.cases.simulation.output_interval.value;
  const std::string problem = field_interval_problem(*args.field_interval, output_interval);
  if (!problem.empty())
    throw std::invalid_argument(
        fmt::format("--field-interval {}: {}", *args.field_interval, problem));
}

int run(const RigCommonArgs& args) {
  const RigInputs in = read_rig_inputs(args);
  check_field_args(args, in);
  print_warnings(in);
  if (in.db.has_parent_path()) std::filesystem::create_directories(in.db.parent_path());
  db::RigStore store(in.db);
  const RigRunOutcome o = run_rig_once(in, args, in.parameters, in.rig_case->code);
  const int code =
      o.result.summary.verdict == Verdict::completed ? exit_code::completed : exit_code::unstable;
  const long long id = store.record_run(store_record(in, o, args, "run"));
  if (args.out) write_run_files(*args.out, in, o, args, code);
  if (args.json) {
    print_json(rig_run_json(in, o, args, id, code));
  } else if (!args.quiet) {
    fmt::print("{}", run_table(in, o));
    fmt::print("  {:<15}{} (rig_runs.id {})\n", "stored", in.db.string(), id);
    if (args.out) fmt::print("  {:<15}{}\n", "files", args.out->string());
    fmt::print("{}", comparison_table(in, o));
  }
  return code;
}

}  // namespace

int rig_run_command(const RigCommonArgs& args) {
  return run_rig_reporting_errors([&] { return run(args); });
}

}  // namespace ccm
