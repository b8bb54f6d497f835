// libFuzzer target: a store file (fuzz_readers.hpp). With CCM_FUZZ_MAKE_SEED=<file> in the
// environment it writes a small valid store there and exits (scripts/fuzz.sh seeds the corpus
// with it).
#include "fuzz/fuzz_readers.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* seed = std::getenv("CCM_FUZZ_MAKE_SEED")) {
    ccm::db::StudyStore store(seed);
    store.open_study("seed", "0123456789abcdef");
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ccm::fuzz::store_file_input(ccm::fuzz::as_text(data, size));
  return 0;
}
