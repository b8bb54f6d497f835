// A sensor deadband: readings below the threshold read 0 (thesis 3.3.3, the Novel Pliance
// pressure sensor "would report a value of zero for pressure below a specific threshold").
#pragma once

#include "rig_models/signal/time_series.hpp"

namespace ccm::rig {

// Every value < threshold becomes 0; values >= threshold are kept as they are.
// Throws std::invalid_argument unless threshold >= 0 and finite.
TimeSeries apply_deadband(const TimeSeries& signal, double threshold);

}  // namespace ccm::rig
