// A small synthetic study written through the store API (fast: no simulation), with
// closed-form errors and runtimes so that the report's figures, tables and maps can be checked.
// Main grid: ER in {1, 1e2, 1e4, 1e6}, RLS in {0.5, 1, 1.5}, KE in {10, 100} J (24 points);
//   artifact histories ramp from 0 at t = 0.1 s to their final value at t_f = 0.15 s; CCM's are
//   the rigid ones times (1 - a), a = 0.4 (1 - log10 ER / 6), so every final-state error
//   (eqs. 2.37-2.39) is exactly a.
// Timing at mesh scale s (1 on the main grid): ISTS_ccm = 1e-4 s / sqrt(ER), AIR_ccm = 2e-4 / s^2,
//   ISTS_rigid = 1e-4 s, AIR_rigid = 1e-4 2^RLS / s^2 [s]; steps = 0.15 s / ISTS, wall =
//   AIR steps. So NT_ccm = 2 sqrt(ER) / s^3, NT_rigid = 2^RLS / s^3 (eqs. 2.41-2.42), both
//   planes in log10 (log10 NT_ccm = log10 2 + x / 2, log10 NT_rigid = y log10 2 at s = 1, with
//   x = log10 ER, y = RLS), and RTR = 2 sqrt(ER) / 2^RLS (eq. 2.40).
// Convergence mode: the cases of kConvergenceCases at the mesh scales of kConvergenceScales
//   (points 24..29, in that order, as `ccm study run` numbers them); the CCM run at scale s is
//   the finest CCM run (s = 0.5) times (1 - 0.1 (s - 0.5)), the rigid run is as on the grid, so
//   the final-state errors against the finest CCM run are 0.1 (s - 0.5) (CCM) and a (rigid).
// The rigid run of the point (ER 1e2, RLS 1, KE 10 J) is unstable at t = 0.12 s.
// Impactor: 2 kg at 1 m/s along -z until t_c, then steadily to a rebound of 0.5 m/s (CCM) or
//   1 m/s (rigid) at t_f: peak forces 60 N and 80 N (IM.1), durations 0.05 s both, indentation
//   error a (the u_max histories), rebound error 0.5 (IM.5): the worst designer's error.
#pragma once

#include <array>
#include <filesystem>

#include "records/grid_point.hpp"

namespace ccm::test {

inline constexpr int kSyntheticPoints = 24;  // the main grid
inline constexpr int kUnstablePointIndex =
    5;  // ER 1e2, RLS 1, KE 10 J (index = 12 KE_i + 4 RLS_i + ER_i)
inline constexpr const char* kUnstableReason = "energy-balance error 0.2 above 0.05";
inline constexpr double kSyntheticImpactorMass = 2.0;                              // [kg]
inline constexpr double kSyntheticReboundCcm = 0.5, kSyntheticReboundRigid = 1.0;  // [m/s]

struct SyntheticCase {
  double modulus_ratio, length_ratio, kinetic_energy;
};
inline constexpr std::array<SyntheticCase, 2> kConvergenceCases = {SyntheticCase{1e2, 1.0, 100.0},
                                                                   SyntheticCase{1e4, 0.5, 10.0}};
inline constexpr std::array<double, 3> kConvergenceScales = {2.0, 1.0, 0.5};
inline constexpr int kConvergencePoints =
    static_cast<int>(kConvergenceCases.size() * kConvergenceScales.size());

// Final-state error of the rigid model against CCM at this ER: a = 0.4 (1 - log10 ER / 6).
double synthetic_final_error(double modulus_ratio);

// NT = AIR / ISTS of a model's run at a main-grid point (mesh scale 1) [s/s].
double synthetic_normalised_runtime(study::ImpactModel model, double modulus_ratio,
                                    double length_ratio);

// Wall time AIR * steps of a model's run at mesh scale `scale` [s].
double synthetic_wall_seconds(study::ImpactModel model, double modulus_ratio, double length_ratio,
                              double scale);

// Final-state error (any of the three quantities) of a convergence run against the finest CCM
// run of its case.
double synthetic_convergence_error(study::ImpactModel model, double modulus_ratio, double scale);

// Writes the study (runs, metrics, fits) into `file`.
void write_synthetic_study(const std::filesystem::path& file);

}  // namespace ccm::test
