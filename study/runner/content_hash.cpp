#include "study/runner/content_hash.hpp"

#include <fmt/format.h>

#include <cstdint>

#include "study/grid/point_scene.hpp"

namespace ccm::study {

std::string fnv1a64(std::string_view data) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : data) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return fmt::format("{:016x}", h);
}

std::string run_key(const GridSpec& spec, const GridPoint& point, ImpactModel model) {
  // {:a}: exact hexadecimal floats, so two values that differ in the last bit differ here.
  std::string text =
      fmt::format("ccm grid run v1\nmodel = {}\nER = {:a}\nRLS = {:a}\nKE = {:a}\n",
                  to_string(model), point.modulus_ratio, point.length_ratio, point.kinetic_energy);
  for (const auto& [name, value] : point.other_axes)
    text += fmt::format("{} = {:a}\n", name, value);
  return fnv1a64(text + point_scene_text(spec, point, model));
}

}  // namespace ccm::study
