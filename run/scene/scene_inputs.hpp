// Everything a scene's run reads, as one text to hash: the scene file's text and the mesh files it
// names (a changed mesh file is another run).
#pragma once

#include <string>

#include "run/scene/scene.hpp"

namespace ccm {

std::string scene_inputs_text(const std::string& text, const Scene& scene);

}  // namespace ccm
