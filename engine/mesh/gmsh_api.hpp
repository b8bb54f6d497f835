// The part of Gmsh's C++ API that ccm uses, with the same names, arguments and defaults as
// <gmsh.h> (Gmsh 4.8), in namespace ccm::gmsh. Gmsh's shared library is loaded on the first call
// (dlopen), not when ccm starts: libgmsh brings about 90 shared libraries (OpenCASCADE, FLTK, ...)
// whose loading took 0.12 s of every ccm process, most of which never mesh (a cached mesh, a
// study's report, a test's `ccm --help`). docs/build.md, "Gmsh, loaded when needed".
//
// Each function forwards to Gmsh's C API (<gmshc.h>, the same library), whose prototypes type the
// loaded symbols. An error Gmsh reports becomes a GmshError with Gmsh's last error message; a
// library that cannot be loaded, a GmshError naming it.
#pragma once

#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ccm::gmsh {

struct GmshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Loads Gmsh's library now (once per process; later calls return at once). Read_msh_file loads
// it before it forks its reader, so that a process reading many files loads it once.
void load();

// The version of Gmsh's API ccm was built against (GMSH_API_VERSION); does not load the library.
const char* api_version();

using vectorpair = std::vector<std::pair<int, int>>;

void initialize(int argc = 0, char** argv = nullptr, bool readConfigFiles = true);
void finalize();
void open(const std::string& fileName);
void write(const std::string& fileName);

namespace option {
void setNumber(const std::string& name, double value);
}

namespace model {
void add(const std::string& name);
int addPhysicalGroup(int dim, const std::vector<int>& tags, int tag = -1);
void setPhysicalName(int dim, int tag, const std::string& name);
void getPhysicalGroups(vectorpair& dimTags, int dim = -1);
void getPhysicalName(int dim, int tag, std::string& name);
void getEntitiesForPhysicalGroup(int dim, int tag, std::vector<int>& tags);
void getBoundary(const vectorpair& dimTags, vectorpair& outDimTags, bool combined = true,
                 bool oriented = true, bool recursive = false);
void getEntitiesInBoundingBox(double xmin, double ymin, double zmin, double xmax, double ymax,
                              double zmax, vectorpair& tags, int dim = -1);

namespace mesh {
void generate(int dim = 3);
void getNodes(std::vector<std::size_t>& nodeTags, std::vector<double>& coord,
              std::vector<double>& parametricCoord, int dim = -1, int tag = -1,
              bool includeBoundary = false, bool returnParametricCoord = true);
void getElementTypes(std::vector<int>& elementTypes, int dim = -1, int tag = -1);
void getElementProperties(int elementType, std::string& elementName, int& dim, int& order,
                          int& numNodes, std::vector<double>& localNodeCoord, int& numPrimaryNodes);
void getElementsByType(int elementType, std::vector<std::size_t>& elementTags,
                       std::vector<std::size_t>& nodeTags, int tag = -1);

namespace field {
int add(const std::string& fieldType, int tag = -1);
void setNumber(int tag, const std::string& option, double value);
void setNumbers(int tag, const std::string& option, const std::vector<double>& value);
void setAsBackgroundMesh(int tag);
}  // namespace field
}  // namespace mesh

namespace occ {
int addBox(double x, double y, double z, double dx, double dy, double dz, int tag = -1);
int addCylinder(double x, double y, double z, double dx, double dy, double dz, double r,
                int tag = -1, double angle = 2 * std::numbers::pi);
int addSphere(double xc, double yc, double zc, double radius, int tag = -1,
              double angle1 = -std::numbers::pi / 2, double angle2 = std::numbers::pi / 2,
              double angle3 = 2 * std::numbers::pi);
void cut(const vectorpair& objectDimTags, const vectorpair& toolDimTags, vectorpair& outDimTags,
         std::vector<vectorpair>& outDimTagsMap, int tag = -1, bool removeObject = true,
         bool removeTool = true);
void fragment(const vectorpair& objectDimTags, const vectorpair& toolDimTags,
              vectorpair& outDimTags, std::vector<vectorpair>& outDimTagsMap, int tag = -1,
              bool removeObject = true, bool removeTool = true);
void synchronize();
void getCenterOfMass(int dim, int tag, double& x, double& y, double& z);
}  // namespace occ
}  // namespace model

}  // namespace ccm::gmsh
