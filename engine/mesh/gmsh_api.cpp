#include "engine/mesh/gmsh_api.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <gmshc.h>

#include <type_traits>

namespace ccm::gmsh {
namespace {

// Gmsh's library by its soname (CMake reads it from the library it found: engine/CMakeLists.txt).
// RTLD_LOCAL: its symbols stay out of the global scope, ccm's out of its.
void* library() {
  static void* const handle = [] {
    void* h = dlopen(CCM_GMSH_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
      const char* why = dlerror();
      throw GmshError(fmt::format("cannot load Gmsh's library {}: {}", CCM_GMSH_LIBRARY,
                                  why ? why : "unknown error"));
    }
    return h;
  }();
  return handle;
}

// A C API function of the loaded library, typed by its prototype in <gmshc.h>.
template <class Function>
Function* symbol(const char* name) {
  void* address = dlsym(library(), name);
  if (!address)
    throw GmshError(fmt::format("Gmsh's library {} has no function {}", CCM_GMSH_LIBRARY, name));
  return reinterpret_cast<Function*>(address);
}

// The function `name` of <gmshc.h>, looked up once.
#define CCM_GMSH_C(name)                                                       \
  ([]() -> decltype(&::name) {                                                 \
    static decltype(&::name) const function = symbol<decltype(::name)>(#name); \
    return function;                                                           \
  }())

void free_array(void* p) { CCM_GMSH_C(gmshFree)(p); }

[[noreturn]] void throw_last_error() {
  char* text = nullptr;
  int ierr = 0;
  CCM_GMSH_C(gmshLoggerGetLastError)(&text, &ierr);
  std::string message = (ierr == 0 && text && *text) ? text : "unknown error";
  if (text) free_array(text);
  throw GmshError(message);
}

// Calls a C API function with `args` and its last argument, ierr, and throws Gmsh's message when
// it reports an error.
template <class Function, class... Args>
auto call(Function* function, Args... args) {
  int ierr = 0;
  if constexpr (std::is_void_v<decltype(function(args..., &ierr))>) {
    function(args..., &ierr);
    if (ierr != 0) throw_last_error();
  } else {
    const auto result = function(args..., &ierr);
    if (ierr != 0) throw_last_error();
    return result;
  }
}

// Arrays Gmsh allocates are copied out and freed.
template <class T>
std::vector<T> take(T* data, std::size_t n) {
  std::vector<T> out(data, data + n);
  if (data) free_array(data);
  return out;
}

std::string take_string(char* text) {
  std::string out = text ? text : "";
  if (text) free_array(text);
  return out;
}

// (dim, tag) pairs as Gmsh's C API passes them: dim0, tag0, dim1, tag1, ...
std::vector<int> flat(const vectorpair& pairs) {
  std::vector<int> out;
  out.reserve(2 * pairs.size());
  for (const auto& [dim, tag] : pairs) out.insert(out.end(), {dim, tag});
  return out;
}

vectorpair take_pairs(int* data, std::size_t n) {
  const std::vector<int> ints = take(data, n);
  vectorpair out;
  out.reserve(ints.size() / 2);
  for (std::size_t i = 0; i + 1 < ints.size(); i += 2) out.emplace_back(ints[i], ints[i + 1]);
  return out;
}

using BooleanOperation = decltype(::gmshModelOccCut);

void boolean_operation(BooleanOperation* operation, const vectorpair& objects,
                       const vectorpair& tools, vectorpair& out, std::vector<vectorpair>& map,
                       int tag, bool remove_object, bool remove_tool) {
  std::vector<int> object_ints = flat(objects), tool_ints = flat(tools);
  int* out_data = nullptr;
  std::size_t out_n = 0;
  int** map_data = nullptr;
  std::size_t* map_n = nullptr;
  std::size_t map_nn = 0;
  call(operation, object_ints.data(), object_ints.size(), tool_ints.data(), tool_ints.size(),
       &out_data, &out_n, &map_data, &map_n, &map_nn, tag, remove_object, remove_tool);
  out = take_pairs(out_data, out_n);
  map.clear();
  for (std::size_t i = 0; i < map_nn; ++i) map.push_back(take_pairs(map_data[i], map_n[i]));
  if (map_data) free_array(map_data);
  if (map_n) free_array(map_n);
}

}  // namespace

void load() { library(); }

const char* api_version() { return GMSH_API_VERSION; }

void initialize(int argc, char** argv, bool readConfigFiles) {
  call(CCM_GMSH_C(gmshInitialize), argc, argv, readConfigFiles);
}

void finalize() { call(CCM_GMSH_C(gmshFinalize)); }

void open(const std::string& fileName) { call(CCM_GMSH_C(gmshOpen), fileName.c_str()); }

void write(const std::string& fileName) { call(CCM_GMSH_C(gmshWrite), fileName.c_str()); }

void option::setNumber(const std::string& name, double value) {
  call(CCM_GMSH_C(gmshOptionSetNumber), name.c_str(), value);
}

void model::add(const std::string& name) { call(CCM_GMSH_C(gmshModelAdd), name.c_str()); }

int model::addPhysicalGroup(int dim, const std::vector<int>& tags, int tag) {
  std::vector<int> copy = tags;
  return call(CCM_GMSH_C(gmshModelAddPhysicalGroup), dim, copy.data(), copy.size(), tag);
}

void model::setPhysicalName(int dim, int tag, const std::string& name) {
  call(CCM_GMSH_C(gmshModelSetPhysicalName), dim, tag, name.c_str());
}

void model::getPhysicalGroups(vectorpair& dimTags, int dim) {
  int* data = nullptr;
  std::size_t n = 0;
  call(CCM_GMSH_C(gmshModelGetPhysicalGroups), &data, &n, dim);
  dimTags = take_pairs(data, n);
}

void model::getPhysicalName(int dim, int tag, std::string& name) {
  char* text = nullptr;
  call(CCM_GMSH_C(gmshModelGetPhysicalName), dim, tag, &text);
  name = take_string(text);
}

void model::getEntitiesForPhysicalGroup(int dim, int tag, std::vector<int>& tags) {
  int* data = nullptr;
  std::size_t n = 0;
  call(CCM_GMSH_C(gmshModelGetEntitiesForPhysicalGroup), dim, tag, &data, &n);
  tags = take(data, n);
}

void model::getBoundary(const vectorpair& dimTags, vectorpair& outDimTags, bool combined,
                        bool oriented, bool recursive) {
  std::vector<int> in = flat(dimTags);
  int* data = nullptr;
  std::size_t n = 0;
  call(CCM_GMSH_C(gmshModelGetBoundary), in.data(), in.size(), &data, &n, combined, oriented,
       recursive);
  outDimTags = take_pairs(data, n);
}

void model::getEntitiesInBoundingBox(double xmin, double ymin, double zmin, double xmax,
                                     double ymax, double zmax, vectorpair& tags, int dim) {
  int* data = nullptr;
  std::size_t n = 0;
  call(CCM_GMSH_C(gmshModelGetEntitiesInBoundingBox), xmin, ymin, zmin, xmax, ymax, zmax, &data, &n,
       dim);
  tags = take_pairs(data, n);
}

void model::mesh::generate(int dim) { call(CCM_GMSH_C(gmshModelMeshGenerate), dim); }

void model::mesh::getNodes(std::vector<std::size_t>& nodeTags, std::vector<double>& coord,
                           std::vector<double>& parametricCoord, int dim, int tag,
                           bool includeBoundary, bool returnParametricCoord) {
  std::size_t* tags = nullptr;
  double *xyz = nullptr, *uvw = nullptr;
  std::size_t n_tags = 0, n_xyz = 0, n_uvw = 0;
  call(CCM_GMSH_C(gmshModelMeshGetNodes), &tags, &n_tags, &xyz, &n_xyz, &uvw, &n_uvw, dim, tag,
       includeBoundary, returnParametricCoord);
  nodeTags = take(tags, n_tags);
  coord = take(xyz, n_xyz);
  parametricCoord = take(uvw, n_uvw);
}

void model::mesh::getElementTypes(std::vector<int>& elementTypes, int dim, int tag) {
  int* data = nullptr;
  std::size_t n = 0;
  call(CCM_GMSH_C(gmshModelMeshGetElementTypes), &data, &n, dim, tag);
  elementTypes = take(data, n);
}

void model::mesh::getElementProperties(int elementType, std::string& elementName, int& dim,
                                       int& order, int& numNodes,
                                       std::vector<double>& localNodeCoord, int& numPrimaryNodes) {
  char* name = nullptr;
  double* local = nullptr;
  std::size_t n_local = 0;
  call(CCM_GMSH_C(gmshModelMeshGetElementProperties), elementType, &name, &dim, &order, &numNodes,
       &local, &n_local, &numPrimaryNodes);
  elementName = take_string(name);
  localNodeCoord = take(local, n_local);
}

void model::mesh::getElementsByType(int elementType, std::vector<std::size_t>& elementTags,
                                    std::vector<std::size_t>& nodeTags, int tag) {
  std::size_t *elements = nullptr, *nodes = nullptr;
  std::size_t n_elements = 0, n_nodes = 0;
  call(CCM_GMSH_C(gmshModelMeshGetElementsByType), elementType, &elements, &n_elements, &nodes,
       &n_nodes, tag, 0, 1);
  elementTags = take(elements, n_elements);
  nodeTags = take(nodes, n_nodes);
}

int model::mesh::field::add(const std::string& fieldType, int tag) {
  return call(CCM_GMSH_C(gmshModelMeshFieldAdd), fieldType.c_str(), tag);
}

void model::mesh::field::setNumber(int tag, const std::string& option, double value) {
  call(CCM_GMSH_C(gmshModelMeshFieldSetNumber), tag, option.c_str(), value);
}

void model::mesh::field::setNumbers(int tag, const std::string& option,
                                    const std::vector<double>& value) {
  std::vector<double> copy = value;
  call(CCM_GMSH_C(gmshModelMeshFieldSetNumbers), tag, option.c_str(), copy.data(), copy.size());
}

void model::mesh::field::setAsBackgroundMesh(int tag) {
  call(CCM_GMSH_C(gmshModelMeshFieldSetAsBackgroundMesh), tag);
}

int model::occ::addBox(double x, double y, double z, double dx, double dy, double dz, int tag) {
  return call(CCM_GMSH_C(gmshModelOccAddBox), x, y, z, dx, dy, dz, tag);
}

int model::occ::addCylinder(double x, double y, double z, double dx, double dy, double dz, double r,
                            int tag, double angle) {
  return call(CCM_GMSH_C(gmshModelOccAddCylinder), x, y, z, dx, dy, dz, r, tag, angle);
}

int model::occ::addSphere(double xc, double yc, double zc, double radius, int tag, double angle1,
                          double angle2, double angle3) {
  return call(CCM_GMSH_C(gmshModelOccAddSphere), xc, yc, zc, radius, tag, angle1, angle2, angle3);
}

void model::occ::cut(const vectorpair& objectDimTags, const vectorpair& toolDimTags,
                     vectorpair& outDimTags, std::vector<vectorpair>& outDimTagsMap, int tag,
                     bool removeObject, bool removeTool) {
  boolean_operation(CCM_GMSH_C(gmshModelOccCut), objectDimTags, toolDimTags, outDimTags,
                    outDimTagsMap, tag, removeObject, removeTool);
}

void model::occ::fragment(const vectorpair& objectDimTags, const vectorpair& toolDimTags,
                          vectorpair& outDimTags, std::vector<vectorpair>& outDimTagsMap, int tag,
                          bool removeObject, bool removeTool) {
  boolean_operation(CCM_GMSH_C(gmshModelOccFragment), objectDimTags, toolDimTags, outDimTags,
                    outDimTagsMap, tag, removeObject, removeTool);
}

void model::occ::synchronize() { call(CCM_GMSH_C(gmshModelOccSynchronize)); }

void model::occ::getCenterOfMass(int dim, int tag, double& x, double& y, double& z) {
  call(CCM_GMSH_C(gmshModelOccGetCenterOfMass), dim, tag, &x, &y, &z);
}

}  // namespace ccm::gmsh

#undef CCM_GMSH_C
