// Opening an existing study store for reading commands (status, recommend, report): read-only
// (nothing is written, not even beside the file); a missing file, a file that is not a store
// (an empty one too) or a store without a study is bad input, never silently created.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>

#include "db/store/study_store.hpp"

namespace ccm {

struct StudyInputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws StudyInputError when the file does not exist or holds no study, db::StoreError when
// it is not a ccm store (an empty file too) or of a newer schema.
inline std::unique_ptr<db::StudyStore> open_study_store(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file))
    throw StudyInputError(file.string() + ": no such study database (run `ccm study run` first)");
  auto store = std::make_unique<db::StudyStore>(file, db::Access::read_only);
  if (!store->open_existing_study())
    throw StudyInputError(file.string() + ": holds no study yet (an empty store)");
  return store;
}

}  // namespace ccm
