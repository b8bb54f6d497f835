// A synthetic benchtop rig record (no simulation): three measured trials of case RX025 on
// 21 samples each (t = 0 ... 0.2 s), V_i = s t, theta_a = s t^2, P = 10 s kPa for
// 0.05 <= t <= 0.1 s, with s = 1, 1.1, 0.9; the simulation is trial 1 with its pressure
// times 1.5. Compared with the trials through rig::compare_case, as `ccm rig run` does.
#pragma once

#include <filesystem>

#include "db/store/rig_store.hpp"

namespace ccm::test {

db::RigRunRecord synthetic_rig_record();

// Writes the record (purpose 'run') and a calibration of it (two runs of purpose
// 'calibration', one parameter) into the store `file`; returns the run's id.
long long write_synthetic_rig(const std::filesystem::path& file);

}  // namespace ccm::test
