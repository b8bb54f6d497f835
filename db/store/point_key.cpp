#include "db/store/point_key.hpp"

#include <fmt/format.h>

#include <cstdint>

namespace ccm::db {

namespace {
std::string fnv1a64(std::string_view data) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : data) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return fmt::format("{:016x}", h);
}
}  // namespace

std::string other_axes_text(const study::GridPoint& point) {
  std::string text;
  for (const auto& [name, value] : point.other_axes)  // std::map: sorted by name
    text += fmt::format("{}{}={}", text.empty() ? "" : ";", name, value);
  return text;
}

std::string grid_point_hash(const study::GridPoint& point) {
  return fnv1a64(fmt::format("ER={};RLS={};KE={};{}", point.modulus_ratio, point.length_ratio,
                             point.kinetic_energy, other_axes_text(point)));
}

}  // namespace ccm::db
