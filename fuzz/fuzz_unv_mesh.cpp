// libFuzzer target: a .unv mesh file (fuzz_readers.hpp).
#include "fuzz/fuzz_readers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ccm::fuzz::mesh_file_input(ccm::fuzz::as_text(data, size), ".unv");
  return 0;
}
