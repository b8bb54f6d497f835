// libFuzzer target: a scene file (fuzz_readers.hpp).
#include "fuzz/fuzz_readers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ccm::fuzz::scene_file_input(ccm::fuzz::as_text(data, size));
  return 0;
}
