// The one safety factor of the explicit step: the step taken is dt_safety times the stable
// step (eq. CT.1, engine/contact/contact_model.hpp; docs/time-step.md). Its default, written
// once for the engine, the scene files and the grid files.
#pragma once

namespace ccm {

inline constexpr double kDefaultDtSafety = 0.9;

}  // namespace ccm
