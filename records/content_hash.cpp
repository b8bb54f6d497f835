#include "records/content_hash.hpp"

#include <fmt/format.h>

#include <cstdint>

namespace ccm::study {

std::string fnv1a64(std::string_view data) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : data) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return fmt::format("{:016x}", h);
}

}  // namespace ccm::study
