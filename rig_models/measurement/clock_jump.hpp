// A logger clock glitch in a measured trial: a forward jump of the timestamps far larger than
// the trial's sampling interval (a clock stepped by NTP, a counter roll-over, a +1000 s
// offset from one row on). Time going backwards or repeating is refused row by row
// (trial_csv.hpp); a forward jump needs the whole file, because the interval it is measured
// against is the file's own.
//
// The yardstick is the median step between consecutive rows. Rows merge every sensor's
// samples, so in a healthy file the largest step is at most the slowest sensor's period and
// the median at least a fraction of the fastest's: the dev trials (100 Hz and 128 Hz sensors)
// have largest / median = 1.67. A step beyond kClockJumpFactor = 100 medians is refused:
// 60 times the dev trials' ratio, room for a logger that drops tens of samples in a row, while
// a jump of 1 s or more at these rates (median 4.7 ms) is 200 medians or more.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace ccm::rig {

inline constexpr double kClockJumpFactor = 100.0;

struct ClockJump {
  std::size_t row = 0;       // index of the row after the jump (0-based over the data rows)
  double step = 0.0;         // s, its time minus the previous row's
  double median_step = 0.0;  // s
};

// The first row whose step from the previous row exceeds `factor` x the median step; none when
// there is none or fewer than three rows (no median to speak of). `row_times` must increase.
std::optional<ClockJump> find_clock_jump(std::span<const double> row_times,
                                         double factor = kClockJumpFactor);

}  // namespace ccm::rig
