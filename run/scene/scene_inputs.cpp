#include "run/scene/scene_inputs.hpp"

#include "config/text_file.hpp"

namespace ccm {

std::string scene_inputs_text(const std::string& text, const Scene& scene) {
  std::string all = text;
  for (const BodySpec& b : scene.bodies)
    if (b.geometry.shape == Shape::mesh) all += "\n#mesh " + read_config_text(b.geometry.file);
  return all;
}

}  // namespace ccm
