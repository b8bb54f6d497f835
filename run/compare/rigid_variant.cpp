#include "run/compare/rigid_variant.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "config/did_you_mean.hpp"

namespace ccm {
namespace {

BodySpec& named_body(Scene& scene, const std::string& name) {
  for (BodySpec& b : scene.bodies)
    if (b.name == name) return b;
  std::vector<std::string_view> names;
  for (const BodySpec& b : scene.bodies) names.push_back(b.name);
  const std::string_view close = closest_name(name, names);
  throw RigidVariantError(fmt::format(
      "--rigid {}: no body named '{}' in {} (bodies: {}){}", name, name, scene.source.string(),
      fmt::join(names, ", "), close.empty() ? "" : fmt::format("; did you mean '{}'?", close)));
}

}  // namespace

Scene with_rigid_bodies(const Scene& scene, const std::vector<std::string>& names) {
  if (names.empty()) throw RigidVariantError("--rigid: name at least one body");
  Scene out = scene;
  for (size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    if (std::find(names.begin(), names.begin() + static_cast<long>(k), name) !=
        names.begin() + static_cast<long>(k))
      throw RigidVariantError(fmt::format("--rigid {}: the body is named twice", name));
    BodySpec& b = named_body(out, name);
    if (b.rigid)
      throw RigidVariantError(fmt::format(
          "--rigid {}: the body is rigid in {} already (kind = \"rigid\"): compare needs it "
          "deformable as written",
          name, scene.source.string()));
    b.rigid = true;
    const auto held = [&](const FixedSpec& f) { return f.body && *f.body == name; };
    const bool fixed = std::any_of(out.fixed.begin(), out.fixed.end(), held);
    b.motion = fixed ? RigidMotion::fixed : RigidMotion::free;
    if (fixed) b.initial_velocity = Vec3::Zero();
    std::erase_if(out.fixed, held);
  }
  return out;
}

}  // namespace ccm
