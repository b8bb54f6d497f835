// libFuzzer target: a measured trial CSV (fuzz_readers.hpp).
#include "fuzz/fuzz_readers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ccm::fuzz::trial_csv_input(ccm::fuzz::as_text(data, size));
  return 0;
}
