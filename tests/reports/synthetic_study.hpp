// A small synthetic study written through the store API (fast: no simulation), with
// closed-form errors and runtimes so that the report's figures and maps can be checked:
//   ER in {1, 1e2, 1e4, 1e6}, RLS in {0.5, 1, 1.5}, KE in {10, 100} J (24 points);
//   artifact histories ramp from 0 at t = 0.1 s to their final value at t_f = 0.15 s; CCM's are
//   the rigid ones times (1 - a), a = 0.4 (1 - log10 ER / 6), so every final-state error
//   (eqs. 2.37-2.39) is exactly a;
//   ISTS_rigid = 1e-4 s, ISTS_ccm = 1e-4 / sqrt(ER) s, AIR_rigid = 1e-4 s, AIR_ccm = 2e-4 s,
//   so RTR = 2 sqrt(ER) (eq. 2.40).
// The rigid run of the point (ER 1e2, RLS 1, KE 10 J) is unstable at t = 0.12 s.
#pragma once

#include <filesystem>

#include "study/grid/grid_point.hpp"

namespace ccm::test {

inline constexpr int kSyntheticPoints = 24;
inline constexpr int kUnstablePointIndex =
    5;  // ER 1e2, RLS 1, KE 10 J (index = 12 KE_i + 4 RLS_i + ER_i)
inline constexpr const char* kUnstableReason = "energy-balance error 0.2 above 0.05";

// Final-state error of the rigid model against CCM at this ER: a = 0.4 (1 - log10 ER / 6).
double synthetic_final_error(double modulus_ratio);

// Writes the study (runs, metrics, fits) into `file`.
void write_synthetic_study(const std::filesystem::path& file);

}  // namespace ccm::test
