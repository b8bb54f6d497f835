// The modelling choices behind a study's answers, read from its grid file (stored with the
// study, db::StudyStore::load_grid): the rigid model's penalty stiffness K_P and damping zeta,
// the DCR pair's restitution and friction, and the mesh sizes. A choice that is a grid axis
// (GridPoint::other_axes) is given per level, or at the level an answer used.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "study/fit/study_fits.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

struct ModellingChoice {
  std::string key;    // JSON name, e.g. "rigid_penalty"
  std::string label;  // e.g. "rigid penalty K_P per quadrature point"
  std::string unit;   // e.g. "N/m"; "" when dimensionless
  std::string axis;   // the grid axis that sweeps it; "" when fixed
  // The value (fixed, or the axis level the answer used); empty when the axis has several
  // levels and no level was chosen: then `levels` lists them.
  std::optional<double> value;
  std::vector<double> levels;

  // "rigid damping zeta: 1 (axis damping)", "rigid damping zeta: per level of axis damping: 0, 1"
  std::string text() const;
};

// Every choice, in a fixed order; `levels_used` holds the axis levels of one answer (empty for
// a whole-study summary, where swept choices list their levels). Axes that are none of these
// choices (e.g. nu) are listed after them, by name. A grid over a scene: its axes and levels,
// by path (its fixed choices are those its template scene writes).
std::vector<ModellingChoice> modelling_choices(const GridSpec& spec,
                                               const AxisLevels& levels_used = {});

}  // namespace ccm::study
