#include "tests/io/fields/field_files_check.hpp"

#include <hdf5.h>
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <catch2/catch.hpp>
#include <sstream>

namespace ccm::test {
namespace {

namespace fs = std::filesystem;

std::string attr(const xmlNode* n, const char* name) {
  xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(name));
  if (!v) return {};
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}

bool is(const xmlNode* n, const char* name) {
  return n->type == XML_ELEMENT_NODE &&
         xmlStrcmp(n->name, reinterpret_cast<const xmlChar*>(name)) == 0;
}

std::vector<const xmlNode*> children(const xmlNode* n, const char* name) {
  std::vector<const xmlNode*> out;
  for (const xmlNode* c = n->children; c; c = c->next)
    if (is(c, name)) out.push_back(c);
  return out;
}

XdmfDataItem data_item(const xmlNode* n) {
  XdmfDataItem item;
  std::istringstream dims(attr(n, "Dimensions"));
  for (unsigned long long d; dims >> d;) item.dims.push_back(d);
  item.number_type = attr(n, "NumberType");
  item.precision = std::stoi(attr(n, "Precision"));
  REQUIRE(attr(n, "Format") == "HDF");
  xmlChar* content = xmlNodeGetContent(n);
  const std::string text(reinterpret_cast<const char*>(content));
  xmlFree(content);
  const size_t colon = text.find(':');
  REQUIRE(colon != std::string::npos);
  item.file = text.substr(0, colon);
  item.dataset = text.substr(colon + 1);
  return item;
}

void collect_items(const xmlNode* n, std::vector<XdmfDataItem>& items) {
  for (const xmlNode* c = n->children; c; c = c->next) {
    if (is(c, "DataItem")) items.push_back(data_item(c));
    collect_items(c, items);
  }
}

XdmfFrame frame_of(const xmlNode* spatial) {
  REQUIRE(attr(spatial, "GridType") == "Collection");
  REQUIRE(attr(spatial, "CollectionType") == "Spatial");
  XdmfFrame f;
  const auto time = children(spatial, "Time");
  REQUIRE(time.size() == 1);
  f.time = std::stod(attr(time[0], "Value"));
  for (const xmlNode* grid : children(spatial, "Grid")) {
    const std::string name = attr(grid, "Name");
    f.grids.push_back(name);
    REQUIRE(children(grid, "Topology").size() == 1);
    REQUIRE(children(grid, "Geometry").size() == 1);
    for (const xmlNode* a : children(grid, "Attribute")) {
      f.attributes.push_back(name + "/" + attr(a, "Name"));
      std::string unit;
      for (const xmlNode* info : children(a, "Information"))
        if (attr(info, "Name") == "unit") unit = attr(info, "Value");
      f.units.push_back(unit);
      if (name == "bodies" && attr(a, "Name") == "displacement")
        f.displacement_item.push_back(data_item(children(a, "DataItem").at(0)));
    }
  }
  return f;
}

// Owns one HDF5 identifier.
struct H5 {
  hid_t id;
  herr_t (*close)(hid_t);
  ~H5() {
    if (id >= 0) close(id);
  }
};

}  // namespace

XdmfContent read_xdmf(const fs::path& xdmf) {
  xmlDoc* doc = xmlReadFile(xdmf.c_str(), nullptr, XML_PARSE_NONET);
  REQUIRE(doc != nullptr);  // well formed
  XdmfContent c;
  const xmlNode* root = xmlDocGetRootElement(doc);
  REQUIRE(is(root, "Xdmf"));
  c.version = attr(root, "Version");
  const auto domains = children(root, "Domain");
  REQUIRE(domains.size() == 1);
  const auto top = children(domains[0], "Grid");
  REQUIRE(top.size() == 1);
  REQUIRE(attr(top[0], "CollectionType") == "Temporal");
  for (const xmlNode* spatial : children(top[0], "Grid")) c.frames.push_back(frame_of(spatial));
  collect_items(root, c.items);
  xmlFreeDoc(doc);
  return c;
}

void check_datasets(const fs::path& xdmf, const XdmfContent& content) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  REQUIRE_FALSE(content.items.empty());
  for (const XdmfDataItem& item : content.items) {
    INFO(item.file << ":" << item.dataset);
    const fs::path h5 = xdmf.parent_path() / item.file;
    REQUIRE(fs::exists(h5));
    H5 file{H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    REQUIRE(file.id >= 0);
    H5 dataset{H5Dopen2(file.id, item.dataset.c_str(), H5P_DEFAULT), H5Dclose};
    REQUIRE(dataset.id >= 0);
    H5 space{H5Dget_space(dataset.id), H5Sclose};
    const int rank = H5Sget_simple_extent_ndims(space.id);
    std::vector<hsize_t> dims(static_cast<size_t>(rank));
    H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
    CHECK(std::vector<unsigned long long>(dims.begin(), dims.end()) == item.dims);
    H5 type{H5Dget_type(dataset.id), H5Tclose};
    const H5T_class_t cls = H5Tget_class(type.id);
    CHECK(cls == (item.number_type == "Float" ? H5T_FLOAT : H5T_INTEGER));
    CHECK(H5Tget_size(type.id) == static_cast<size_t>(item.precision));
    if (cls == H5T_INTEGER) CHECK(H5Tget_sign(type.id) == H5T_SGN_2);
  }
}

std::vector<double> read_h5_doubles(const fs::path& h5, const std::string& path,
                                    std::vector<unsigned long long>* dims_out) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  H5 file{H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  REQUIRE(file.id >= 0);
  H5 dataset{H5Dopen2(file.id, path.c_str(), H5P_DEFAULT), H5Dclose};
  REQUIRE(dataset.id >= 0);
  H5 space{H5Dget_space(dataset.id), H5Sclose};
  const hssize_t n = H5Sget_simple_extent_npoints(space.id);
  std::vector<hsize_t> dims(static_cast<size_t>(H5Sget_simple_extent_ndims(space.id)));
  H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
  if (dims_out) dims_out->assign(dims.begin(), dims.end());
  std::vector<double> values(static_cast<size_t>(n));
  REQUIRE(H5Dread(dataset.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >=
          0);
  return values;
}

}  // namespace ccm::test
