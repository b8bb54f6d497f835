// Content hashes of what was run: stable across runs, machines and builds.
#pragma once

#include <string>
#include <string_view>

#include "study/grid/grid_point.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// FNV-1a 64 of the bytes, as 16 lowercase hex digits: the hash `ccm run` writes to summary.toml
// as scene_fnv1a64 (app/run_command.cpp uses this one).
std::string fnv1a64(std::string_view data);

// The resume key of one run: FNV-1a 64 of the model name, the point's axis values and the
// canonical scene text of the point (point_scene_text), which holds every fixed parameter the
// model uses. Independent of the point's index: reordering a grid file's axes keeps the keys.
std::string run_key(const GridSpec& spec, const GridPoint& point, ImpactModel model);

}  // namespace ccm::study
