#include "io/fields/field_h5.hpp"

#include <hdf5.h>

namespace ccm::fields {
namespace {

// Owns one HDF5 identifier and closes it with the matching H5*close function.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

}  // namespace

FieldH5::FieldH5(const std::filesystem::path& file) : file_(file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by our messages
  id_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id_ < 0) throw FieldFileError(file.string() + ": cannot create HDF5 file");
}

FieldH5::~FieldH5() {
  if (id_ >= 0) H5Fclose(static_cast<hid_t>(id_));
}

void FieldH5::write(const std::string& path, std::span<const double> values, size_t rows,
                    size_t cols) {
  write_raw(path, values.data(), values.size(), rows, cols, false);
}

void FieldH5::write(const std::string& path, std::span<const int> values, size_t rows,
                    size_t cols) {
  write_raw(path, values.data(), values.size(), rows, cols, true);
}

void FieldH5::write_raw(const std::string& path, const void* values, size_t n_values, size_t rows,
                        size_t cols, bool is_int) {
  const auto fail = [&](const char* what) {
    throw FieldFileError(file_.string() + ": " + what + " " + path);
  };
  if (id_ < 0) fail("file already closed, cannot write");
  if (n_values != rows * cols) fail("wrong number of values for dataset");
  const hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr), H5Sclose);
  Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  if (!space.valid() || !links.valid() || H5Pset_create_intermediate_group(links.get(), 1) < 0)
    fail("cannot prepare dataset");
  Handle dataset(
      H5Dcreate2(static_cast<hid_t>(id_), path.c_str(), is_int ? H5T_STD_I32LE : H5T_IEEE_F64LE,
                 space.get(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (!dataset.valid()) fail("cannot create dataset");
  if (n_values > 0 && H5Dwrite(dataset.get(), is_int ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, H5S_ALL,
                               H5S_ALL, H5P_DEFAULT, values) < 0)
    fail("cannot write dataset");
}

void FieldH5::close() {
  if (id_ < 0) return;
  const herr_t flushed = H5Fflush(static_cast<hid_t>(id_), H5F_SCOPE_GLOBAL);
  const herr_t closed = H5Fclose(static_cast<hid_t>(id_));
  id_ = -1;
  if (flushed < 0 || closed < 0) throw FieldFileError(file_.string() + ": cannot close HDF5 file");
}

}  // namespace ccm::fields
