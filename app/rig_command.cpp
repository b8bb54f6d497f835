// `ccm rig list [--cases FILE]`: the 12 benchtop cases of thesis Table 3.2 with every rig
// parameter, its unit and its source.
#include <fmt/format.h>

#include "rig_models/cases/case_file.hpp"
#include "rig_models/cases/case_table.hpp"
#include "app/run_command.hpp"
#include "app/study_commands.hpp"

namespace ccm {

int rig_list_command(const RigListArgs& args) {
  try {
    fmt::print("{}", rig::format_case_table(rig::read_case_table(args.cases)));
    return exit_code::completed;
  } catch (const std::exception& e) {  // bad case file: the message names file, line and key
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  }
}

}  // namespace ccm
