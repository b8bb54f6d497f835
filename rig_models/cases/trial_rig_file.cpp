#include "rig_models/cases/trial_rig_file.hpp"

#include <toml++/toml.h>

#include <fstream>
#include <sstream>

#include "config/strict_table.hpp"
#include "rig_models/cases/case_file.hpp"
#include "rig_models/core/rig_error.hpp"

namespace ccm::rig {

std::optional<TrialRigFile> apply_trial_rig_file(const std::filesystem::path& folder,
                                                 RigParameters& rig) {
  const std::filesystem::path path = folder / kTrialRigFileName;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw rig_input_error(path, 0, "", "cannot open the file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  TrialRigFile file{path, text.str()};
  toml::table root;
  try {
    root = toml::parse(file.text, path.string());
  } catch (const toml::parse_error& e) {
    throw rig_input_error(path, static_cast<int>(e.source().begin.line), "", e.description());
  }
  const StrictTable fields(root, "", path);
  fields.allow_only({"rig"});
  override_rig(fields.need_table("rig"), rig);
  return file;
}

}  // namespace ccm::rig
