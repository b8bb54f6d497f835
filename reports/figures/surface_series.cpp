#include "reports/figures/surface_series.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ccm::reports {

Series surface_mesh(const study::SurfaceFit& fit, std::string title, int color,
                    double (*z_of)(double)) {
  Series s{.title = std::move(title),
           .style = SeriesStyle::surface,
           .surface_columns = kSurfaceMeshLines,
           .color = color};
  for (int i = 0; i < kSurfaceMeshLines; ++i)
    for (int j = 0; j < kSurfaceMeshLines; ++j) {
      const double x = fit.x_min + (fit.x_max - fit.x_min) * i / (kSurfaceMeshLines - 1);
      const double y = fit.y_min + (fit.y_max - fit.y_min) * j / (kSurfaceMeshLines - 1);
      s.x.push_back(x);
      s.y.push_back(y);
      const double z = fit.surface(x, y);
      s.z.push_back(z_of != nullptr ? z_of(z) : z);
    }
  return s;
}

Series surface_samples(const study::SurfaceFit& fit, std::string title, int color) {
  Series s{.title = std::move(title), .color = color};
  for (const auto& p : fit.samples) {
    s.x.push_back(p.x);
    s.y.push_back(p.y);
    s.z.push_back(p.z);
  }
  return s;
}

std::string surface_equation(const study::PolynomialSurface& surface, const std::string& z) {
  double largest = 0.0;
  for (const auto& t : surface.terms) largest = std::max(largest, std::abs(t.coefficient));
  std::string out = z + " =";
  bool first = true;
  for (const auto& t : surface.terms) {
    const double c = t.coefficient;
    if (std::abs(c) <= kNegligibleCoefficient * largest) continue;  // rounding noise
    std::string monomial;
    if (t.power_x > 0) monomial += t.power_x == 1 ? " x" : fmt::format(" x^{}", t.power_x);
    if (t.power_y > 0) monomial += t.power_y == 1 ? " y" : fmt::format(" y^{}", t.power_y);
    out += fmt::format(" {}{:.4g}{}", first ? (c < 0 ? "-" : "") : (c < 0 ? "- " : "+ "),
                       std::abs(c), monomial);
    first = false;
  }
  return first ? out + " 0" : out;
}

std::string fit_quality(const study::SurfaceFit& fit) {
  return fmt::format("R^2 = {:.4f}, leave-one-out RMSE = {:.3g}, {} points", fit.r_squared,
                     fit.loo_rmse, fit.samples.size());
}

}  // namespace ccm::reports
