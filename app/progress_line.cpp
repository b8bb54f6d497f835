#include "app/progress_line.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace ccm {

void ProgressLine::operator()(const Progress& p) {
  const double fraction = p.end_time > 0.0 ? p.t / p.end_time : 1.0;
  const double eta = fraction > 0.0 ? p.wall_seconds * (1.0 - fraction) / fraction : 0.0;
  fmt::print(stderr,
             "\r{}{:6.1f}%  t {:.4e} s  step {}  dt {:.3e} s  wall {:.1f} s  ETA {:.1f} s\x1b[K",
             label_.empty() ? "" : label_ + "  ", 100.0 * fraction, p.t, p.steps, p.dt,
             p.wall_seconds, eta);
  std::fflush(stderr);
  used_ = true;
}

void ProgressLine::finish() const {
  if (used_) fmt::print(stderr, "\r\x1b[K");
}

ProgressFn ProgressLine::on_terminal(bool quiet) {
  if (quiet || !isatty(STDERR_FILENO)) return {};
  return [this](const Progress& p) { (*this)(p); };
}

}  // namespace ccm
