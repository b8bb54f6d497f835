// The libFuzzer targets, one per reader of outside input (fuzz_readers.hpp), in one executable
// that is compiled and linked once: the target is the name it runs as. fuzz/CMakeLists.txt links
// fuzz_scene_file, fuzz_grid_file, ... to ccm_fuzz, and scripts/fuzz.sh runs those names.
//
// With CCM_FUZZ_MAKE_SEED=<path> in the environment, the two targets the repository holds no
// seed files for write theirs and exit: fuzz_store_file a small valid store at <path>,
// fuzz_msh_mesh .msh files made with Gmsh in the folder <path>.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include "engine/mesh/gmsh_api.hpp"
#include "fuzz/fuzz_readers.hpp"

namespace {

namespace gmsh = ccm::gmsh;

const ccm::fuzz::Target* g_target = nullptr;

// A coarse box with a named surface and volume, in MSH 4.1 and 2.2, ASCII.
void make_msh_seeds(const std::filesystem::path& folder) {
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

void make_store_seed(const std::string& file) {
  ccm::db::StudyStore store(file);
  store.open_study("seed", "0123456789abcdef");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const std::string name = *argc > 0 ? std::filesystem::path((*argv)[0]).filename().string() : "";
  g_target = ccm::fuzz::target_named(name);
  if (g_target == nullptr) {
    std::fprintf(stderr, "ccm fuzz: run as one of the target names (fuzz/CMakeLists.txt):");
    for (const ccm::fuzz::Target& t : ccm::fuzz::targets())
      std::fprintf(stderr, " %s", std::string(t.name).c_str());
    std::fprintf(stderr, "\n");
    std::exit(2);
  }
  if (const char* seed = std::getenv("CCM_FUZZ_MAKE_SEED")) {
    if (name == "fuzz_store_file") make_store_seed(seed);
    if (name == "fuzz_msh_mesh") make_msh_seeds(seed);
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  g_target->read(ccm::fuzz::as_text(data, size));
  return 0;
}
