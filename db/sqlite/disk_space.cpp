#include "db/sqlite/disk_space.hpp"

#include <fmt/format.h>

namespace ccm::db {

std::string disk_full_note(const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::path folder =
      file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  const std::filesystem::space_info space = std::filesystem::space(folder, ec);
  if (ec || space.available >= kFullBelowBytes) return "";
  return fmt::format(" (the file system holding {} is full: {} bytes free)", folder.string(),
                     space.available);
}

}  // namespace ccm::db
