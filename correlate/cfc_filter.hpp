// The channel frequency class (CFC) filters of impact testing, SAE J211-1 Appendix C (ISO 6487
// uses the same filter with a slightly different design frequency): a two-pole Butterworth
// low-pass run forward and then backward over the record, so four poles and no phase shift
// (a symmetric pulse keeps its peak time). Design, with T the sample interval (docs/correlation.md,
// CFC.1–CFC.3):
//
//   w_d = 2 pi CFC 2.0775,   w_a = tan(w_d T / 2),   D = 1 + sqrt(2) w_a + w_a^2        (CFC.1)
//   a0 = w_a^2 / D,  a1 = 2 a0,  a2 = a0,
//   b1 = -2 (w_a^2 - 1) / D,  b2 = (-1 + sqrt(2) w_a - w_a^2) / D                          (CFC.2)
//   y_n = a0 x_n + a1 x_{n-1} + a2 x_{n-2} + b1 y_{n-1} + b2 y_{n-2}                       (CFC.3)
//
// The forward-backward pass squares the two-pole gain: -3 dB at about 1.67 CFC (1,650 Hz for
// CFC 1000), -0.45 dB at the class frequency itself.
#pragma once

#include <span>
#include <vector>

namespace ccm::correlate {

struct CfcCoefficients {
  double a0 = 0.0, a1 = 0.0, a2 = 0.0, b1 = 0.0, b2 = 0.0;
};

// The classes the standards name; any positive class is accepted by the functions below.
inline constexpr int kStandardCfcClasses[] = {60, 180, 600, 1000};

// CFC.1–CFC.2. Throws std::invalid_argument unless cfc > 0, sample_interval > 0 and the design
// frequency 2.0775 CFC lies below the Nyquist frequency 1 / (2 T) (at 10 kHz: CFC <= 2,400).
CfcCoefficients design_cfc(double cfc, double sample_interval);

// The record filtered forward and backward with CFC.3. The ends are padded by odd reflection
// about the end values (a straight line or a constant passes unchanged) and the filter starts in
// its steady state at the padded first value, so no start-up transient enters the record.
// Throws std::invalid_argument as design_cfc, or for a record of fewer than 3 samples or a
// non-finite value.
std::vector<double> cfc_filter(std::span<const double> samples, double cfc, double sample_interval);

}  // namespace ccm::correlate
