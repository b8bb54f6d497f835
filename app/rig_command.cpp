// `ccm rig list [--cases FILE] [--json]`: the 12 benchtop cases of thesis Table 3.2 with every rig
// parameter, its unit and its source.
#include <fmt/format.h>

#include "app/data_paths.hpp"
#include "app/json_output.hpp"
#include "app/run_command.hpp"
#include "app/study_commands.hpp"
#include "rig_models/cases/case_file.hpp"
#include "rig_models/cases/case_table.hpp"

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

}  // namespace ccm
