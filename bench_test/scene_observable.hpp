// A channel's observable in a scene's history (docs/bench-test.md, "Observables"): a history
// column by its name ("plate.kinetic_energy"), or a vector by the prefix of its three columns
// ("tip.v" for tip.vx, tip.vy, tip.vz; "ball.contact_force" for ball.contact_force_x, _y, _z)
// projected on the channel's axis; "<point>.a" is the rate of "<point>.v" (a tracked point's
// acceleration), as is any observable with derivative = true. The rate of a sampled history is
// its difference quotient over each output interval, placed at the interval's middle: the mean
// rate over the interval, as a momentum exchanged over an interval is a mean force.
#pragma once

#include <string>
#include <vector>

#include "bench_test/bench_mapping.hpp"
#include "rig_models/signal/time_series.hpp"

namespace ccm::bench {

struct ResolvedObservable {
  std::vector<std::size_t> columns;  // one (a scalar) or three (a vector's x, y, z)
  std::vector<double> weights;       // 1, or the axis's components
  bool derivative = false;
};

// Where `channel`'s observable is among `columns` (a history's header). Throws ConfigError naming
// the mapping file, the channel's line and the key when it names nothing there (with the nearest
// column), when a vector has no axis, or a scalar has one.
ResolvedObservable resolve_observable(const ChannelSpec& channel,
                                      const std::vector<std::string>& columns,
                                      const std::filesystem::path& mapping_file);

// The channel's simulated curve from a history's rows (column 0 is time), in SI, scaled.
rig::TimeSeries simulated_curve(const ChannelSpec& channel, const ResolvedObservable& observable,
                                const std::vector<std::vector<double>>& rows);

}  // namespace ccm::bench
