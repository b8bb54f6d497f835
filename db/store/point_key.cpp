#include "db/store/point_key.hpp"

#include <fmt/format.h>

#include <cstdint>

#include "records/content_hash.hpp"

namespace ccm::db {

std::string other_axes_text(const study::GridPoint& point) {
  std::string text;
  for (const auto& [name, value] : point.other_axes)  // std::map: sorted by name
    text += fmt::format("{}{}={}", text.empty() ? "" : ";", name, value);
  return text;
}

std::string grid_point_hash(const study::GridPoint& point) {
  return study::fnv1a64(fmt::format("ER={};RLS={};KE={};{}", point.modulus_ratio,
                                    point.length_ratio, point.kinetic_energy,
                                    other_axes_text(point)));
}

}  // namespace ccm::db
