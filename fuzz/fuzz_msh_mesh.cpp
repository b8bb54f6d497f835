// libFuzzer target: a .msh mesh file (fuzz_readers.hpp). With CCM_FUZZ_MAKE_SEED=<folder> in the
// environment it writes seed files there with Gmsh (a coarse box with a named surface and volume,
// in MSH 4.1 and 2.2, ASCII) and exits: the repository holds no .msh file (scripts/fuzz.sh).
#include <gmsh.h>

#include "fuzz/fuzz_readers.hpp"

namespace {

void make_seeds(const std::filesystem::path& folder) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  const int box = gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {box}), "body");
  gmsh::vectorpair faces;
  gmsh::model::getBoundary({{3, box}}, faces, false, false);
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {faces[0].second}), "side");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.6);
  gmsh::model::mesh::generate(3);
  gmsh::write((folder / "box41.msh").string());
  gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
  gmsh::write((folder / "box22.msh").string());
  gmsh::finalize();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* folder = std::getenv("CCM_FUZZ_MAKE_SEED")) {
    make_seeds(folder);
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ccm::fuzz::mesh_file_input(ccm::fuzz::as_text(data, size), ".msh");
  return 0;
}
