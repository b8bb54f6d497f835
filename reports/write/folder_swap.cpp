#include "reports/write/folder_swap.hpp"

#include <unistd.h>

#include <string>

#include "reports/report_error.hpp"

namespace ccm::reports {
namespace {

namespace fs = std::filesystem;

fs::path sibling(const fs::path& target, const std::string& tag) {
  const fs::path absolute = fs::absolute(target).lexically_normal();
  const fs::path dir = absolute.has_filename() ? absolute : absolute.parent_path();
  std::string name(1, '.');
  name += dir.filename().string();
  name += '.';
  name += tag;
  name += '-';
  name += std::to_string(getpid());
  return dir.parent_path() / name;
}

}  // namespace

fs::path make_staging_folder(const fs::path& target) {
  const fs::path staging = sibling(target, "staging");
  std::error_code ec;
  fs::remove_all(staging, ec);
  fs::create_directories(staging, ec);
  if (ec)
    throw ReportError(staging.string() + ": cannot create the report folder: " + ec.message());
  return staging;
}

void swap_in_folder(const fs::path& staging, const fs::path& target) {
  const fs::path old = sibling(target, "old");
  std::error_code ec;
  const bool exists = fs::exists(target);
  if (exists && !fs::is_directory(target))
    throw ReportError(target.string() + ": exists and is not a folder; choose another --out");
  if (exists) fs::rename(target, old, ec);
  if (!ec) fs::rename(staging, target, ec);
  if (ec) {
    std::error_code ignored;
    if (exists && !fs::exists(target)) fs::rename(old, target, ignored);  // put the old back
    fs::remove_all(staging, ignored);
    throw ReportError(target.string() + ": cannot replace the report folder: " + ec.message());
  }
  fs::remove_all(old, ec);
}

}  // namespace ccm::reports
