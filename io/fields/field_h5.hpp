// The HDF5 half of the field files (docs/fields.md): one file, datasets at absolute paths
// ("/mesh/nodes", "/frames/000003/displacement"), their groups created on the way. HDF5 C API.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>

namespace ccm::fields {

struct FieldFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class FieldH5 {
 public:
  // Creates (or truncates) the file. Throws FieldFileError.
  explicit FieldH5(const std::filesystem::path& file);
  ~FieldH5();
  FieldH5(const FieldH5&) = delete;
  FieldH5& operator=(const FieldH5&) = delete;

  // A dataset of `rows` x `cols` values, row-major (cols == 1: one-dimensional, `rows` long).
  void write(const std::string& path, std::span<const double> values, size_t rows, size_t cols);
  void write(const std::string& path, std::span<const int> values, size_t rows, size_t cols);
  // Flushes and closes; later writes throw. Called by the destructor when not called before.
  void close();

 private:
  void write_raw(const std::string& path, const void* values, size_t n_values, size_t rows,
                 size_t cols, bool is_int);

  std::filesystem::path file_;
  long long id_ = -1;  // hid_t
};

}  // namespace ccm::fields
