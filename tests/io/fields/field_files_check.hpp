// Test support: reads a field output (fields.xdmf + fields.h5) back with independent parsers —
// libxml2 for the XDMF, the HDF5 C API for the data — and checks that every dataset the XDMF
// references exists in the HDF5 file with the shape and number type the XDMF declares.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ccm::test {

struct XdmfDataItem {
  std::vector<unsigned long long> dims;  // as declared
  std::string number_type;               // "Float", "Int"
  int precision = 0;                     // bytes
  std::string file;                      // as written (relative to the .xdmf)
  std::string dataset;                   // "/frames/000003/displacement"
};

struct XdmfFrame {
  double time = 0.0;
  std::vector<std::string> grids;               // names of the frame's uniform grids
  std::vector<std::string> attributes;          // "<grid>/<attribute>"
  std::vector<std::string> units;               // one per attribute, from its Information
  std::vector<XdmfDataItem> displacement_item;  // the "bodies" displacement, when present
};

struct XdmfContent {
  std::string version;
  std::vector<XdmfFrame> frames;
  std::vector<XdmfDataItem> items;  // every DataItem of the file
};

// Parses the file with libxml2 (REQUIRE: well formed, root <Xdmf Version="3.0">, one temporal
// collection of spatial collections, each with a <Time>).
XdmfContent read_xdmf(const std::filesystem::path& xdmf);

// REQUIRE for each item: the HDF5 file it names exists next to the .xdmf, holds the dataset,
// with exactly the declared dimensions and a matching class and size (IEEE float 8 bytes, or
// signed integer 4 bytes).
void check_datasets(const std::filesystem::path& xdmf, const XdmfContent& content);

// A float64 dataset's values (row-major) and dimensions.
std::vector<double> read_h5_doubles(const std::filesystem::path& h5, const std::string& dataset,
                                    std::vector<unsigned long long>* dims = nullptr);

}  // namespace ccm::test
