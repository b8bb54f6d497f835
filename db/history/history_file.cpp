#include "db/history/history_file.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "db/sqlite/connection.hpp"
#include "db/sqlite/disk_space.hpp"

namespace ccm::db {

namespace {

// Owns one HDF5 identifier and closes it with the matching H5*close function.
class H5Handle {
 public:
  H5Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~H5Handle() {
    if (id_ >= 0) close_(id_);
  }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw StoreError(file.string() + ": " + what);
}

void write_dataset(hid_t group, const std::filesystem::path& file, const char* name,
                   const std::vector<double>& values) {
  const hsize_t n = values.size();
  H5Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  H5Handle dataset(
      H5Dcreate2(group, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (!space.valid() || !dataset.valid()) fail(file, std::string("cannot create dataset ") + name);
  if (n > 0 &&
      H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail(file, std::string("cannot write dataset ") + name);
}

std::vector<double> read_dataset(hid_t group, const std::filesystem::path& file,
                                 const std::string& path) {
  H5Handle dataset(H5Dopen2(group, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) fail(file, "missing dataset " + path);
  H5Handle space(H5Dget_space(dataset.get()), H5Sclose);
  hsize_t n = 0;
  if (!space.valid() || H5Sget_simple_extent_ndims(space.get()) != 1 ||
      H5Sget_simple_extent_dims(space.get(), &n, nullptr) < 0)
    fail(file, "dataset " + path + " is not one-dimensional");
  std::vector<double> values(n);
  if (n > 0 &&
      H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail(file, "cannot read dataset " + path);
  return values;
}

void write_impactor(hid_t h5, const std::filesystem::path& tmp,
                    const study::ImpactorHistory& impactor) {
  H5Handle group(H5Gcreate2(h5, kImpactorGroup, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!group.valid()) fail(tmp, std::string("cannot create group ") + kImpactorGroup);
  write_dataset(group.get(), tmp, "mass", {impactor.mass});
  write_dataset(group.get(), tmp, "vx", impactor.vx);
  write_dataset(group.get(), tmp, "vy", impactor.vy);
  write_dataset(group.get(), tmp, "vz", impactor.vz);
}

// The HDF5 file built in memory (the core driver, no backing store): HDF5 itself never writes to
// disk, so that a full disk fails our write below with its reason, not HDF5's flush (whose failed
// close left a file open that HDF5's own exit handler then crashed on).
std::vector<char> file_image(const std::filesystem::path& tmp,
                             const study::ArtifactHistory& history,
                             const study::ImpactorHistory& impactor) {
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!fapl.valid() || H5Pset_fapl_core(fapl.get(), 64 * 1024, 0) < 0)
    fail(tmp, "cannot set up an in-memory HDF5 file");
  H5Handle h5(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
  if (!h5.valid()) fail(tmp, "cannot create HDF5 file");
  {
    H5Handle group(H5Gcreate2(h5.get(), kArtifactGroup, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Gclose);
    if (!group.valid()) fail(tmp, std::string("cannot create group ") + kArtifactGroup);
    write_dataset(group.get(), tmp, "time", history.time);
    write_dataset(group.get(), tmp, "u_mean", history.u_mean);
    write_dataset(group.get(), tmp, "u_max", history.u_max);
    write_dataset(group.get(), tmp, "kinetic_energy", history.kinetic_energy);
  }
  if (!impactor.empty()) write_impactor(h5.get(), tmp, impactor);
  if (H5Fflush(h5.get(), H5F_SCOPE_GLOBAL) < 0) fail(tmp, "cannot flush HDF5 file");
  const ssize_t size = H5Fget_file_image(h5.get(), nullptr, 0);
  if (size <= 0) fail(tmp, "cannot take the HDF5 file's image");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(h5.get(), image.data(), image.size()) != size)
    fail(tmp, "cannot take the HDF5 file's image");
  return image;
}

void write_file(const std::filesystem::path& tmp, const study::ArtifactHistory& history,
                const study::ImpactorHistory& impactor) {
  const std::vector<char> image = file_image(tmp, history, impactor);
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  out.write(image.data(), static_cast<std::streamsize>(image.size()));
  out.close();
  if (!out) fail(tmp, "cannot write the history file" + disk_full_note(tmp));
}

}  // namespace

void write_history_file(const std::filesystem::path& file, const study::ArtifactHistory& history,
                        const study::ImpactorHistory& impactor) {
  // The pid keeps two processes writing the same run from sharing a temporary file.
  const std::filesystem::path tmp = file.string() + ".tmp" + std::to_string(::getpid());
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by our messages
  try {
    write_file(tmp, history, impactor);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) fail(file, "cannot rename the history file into place: " + ec.message());
}

study::ArtifactHistory read_history_file(const std::filesystem::path& file, const char* group) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (!std::filesystem::exists(file)) fail(file, "history file is missing");
  H5Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!h5.valid()) fail(file, "cannot open HDF5 file");
  const std::string prefix = std::string(group) + "/";
  study::ArtifactHistory history;
  history.time = read_dataset(h5.get(), file, prefix + "time");
  history.u_mean = read_dataset(h5.get(), file, prefix + "u_mean");
  history.u_max = read_dataset(h5.get(), file, prefix + "u_max");
  history.kinetic_energy = read_dataset(h5.get(), file, prefix + "kinetic_energy");
  return history;
}

study::ImpactorHistory read_impactor_history(const std::filesystem::path& file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  H5Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!h5.valid()) fail(file, "cannot open HDF5 file");
  study::ImpactorHistory impactor;
  if (H5Lexists(h5.get(), kImpactorGroup, H5P_DEFAULT) <= 0) return impactor;
  const std::string prefix = std::string(kImpactorGroup) + "/";
  const std::vector<double> mass = read_dataset(h5.get(), file, prefix + "mass");
  if (mass.size() != 1) fail(file, "dataset " + prefix + "mass does not hold one value");
  impactor.mass = mass[0];
  impactor.vx = read_dataset(h5.get(), file, prefix + "vx");
  impactor.vy = read_dataset(h5.get(), file, prefix + "vy");
  impactor.vz = read_dataset(h5.get(), file, prefix + "vz");
  return impactor;
}

}  // namespace ccm::db
