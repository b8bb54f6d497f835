// `ccm rig list [--cases FILE] [--json]`: the 12 benchtop cases of thesis Table 3.2 with every rig
// parameter, its unit and its source. `ccm rig mapping CASE [--data DIR]`: the case as a bench
// test, the mapping file `ccm rig run` scores through (bench_test/rig_case_scores.hpp).
#include <fmt/format.h>

#include "app/data_paths.hpp"
#include "app/json_output.hpp"
#include "app/run_command.hpp"
#include "app/study_commands.hpp"
#include "bench_test/rig_case_scores.hpp"
#include "rig_models/cases/case_code.hpp"
#include "rig_models/cases/case_file.hpp"
#include "rig_models/cases/case_table.hpp"
#include "rig_models/cases/trial_rig_file.hpp"

namespace ccm {

int rig_list_command(const RigListArgs& args) {
  try {
    if (args.cases.empty()) throw std::invalid_argument(missing_data_message("--cases"));
    const rig::RigCaseTable table = rig::read_case_table(args.cases);
    if (args.json)
      print_json(case_table_json(table));
    else
      fmt::print("{}", rig::format_case_table(table));
    return exit_code::completed;
  } catch (const std::exception& e) {  // bad case file: the message names file, line and key
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  }
}

int rig_mapping_command(const RigMappingArgs& args) {
  try {
    if (args.cases.empty()) throw std::invalid_argument(missing_data_message("--cases"));
    rig::RigCaseTable table = rig::read_case_table(args.cases);
    if (args.data) rig::apply_trial_rig_file(*args.data, table.rig);
    if (!rig::is_case_code(args.case_code))
      throw std::invalid_argument(
          fmt::format("'{}' is not a case of thesis Table 3.2 (RX025 ... FF100; see ccm rig list)",
                      args.case_code));
    fmt::print("{}",
               bench::rig_case_mapping_text(args.case_code, {table.rig.sensor_deadband.value,
                                                             table.rig.low_pass_cutoff.value}));
    return exit_code::completed;
  } catch (const std::exception& e) {  // the message names the file, line and key, or the case
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  }
}

}  // namespace ccm
