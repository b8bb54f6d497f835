// A fitted polynomial surface (study/fit) as figure series and text: its mesh, its samples, its
// equation and its quality. Used by the weighting-function figures (thesis Fig. 2-29, App. B)
// and the normalised-runtime figures (Fig. 2-28).
#pragma once

#include <string>

#include "reports/plot/plot_spec.hpp"
#include "study/fit/polynomial_surface.hpp"
#include "study/fit/surface_fit.hpp"

namespace ccm::reports {

// Surface mesh resolution per axis.
inline constexpr int kSurfaceMeshLines = 21;

// The surface evaluated on kSurfaceMeshLines x kSurfaceMeshLines points over its samples'
// (x, y) range, x = log10 ER, y = RLS; z = z_of(surface) when z_of is given (10^z for a
// surface fitted in log10).
Series surface_mesh(const study::SurfaceFit& fit, std::string title, int color,
                    double (*z_of)(double) = nullptr);

// The samples the surface was fitted to, as 3-D points.
Series surface_samples(const study::SurfaceFit& fit, std::string title, int color);

// A coefficient at most this fraction of the largest one is rounding noise of the least-squares
// solve (an exact plane fitted in floating point), left out of the written equation.
inline constexpr double kNegligibleCoefficient = 1e-12;

// "z = 0.12 + 0.034 x - 0.5 x^2 y" with x = log10 ER, y = RLS; terms in stored order, those
// below kNegligibleCoefficient of the largest left out; "z = 0" when none is left.
std::string surface_equation(const study::PolynomialSurface& surface, const std::string& z);

// "R^2 = 0.9876, leave-one-out RMSE = 0.0123, 12 points".
std::string fit_quality(const study::SurfaceFit& fit);

}  // namespace ccm::reports
