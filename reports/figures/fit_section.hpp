// Weighting functions and runtime ratio with their fitted surfaces and equations (thesis
// Fig. 2-29, Appendix B), the table of every fit, and error against runtime: for every grid
// point, and from the convergence mode, each model's accuracy per second.
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"
#include "study/fit/polynomial_surface.hpp"

namespace ccm::reports {

Section fit_section(const ReportData& data);
Section error_runtime_section(const ReportData& data);

// "z = 0.12 + 0.034 x - 0.5 x^2 y" with x = log10 ER, y = RLS; terms in stored order.
std::string surface_equation(const study::PolynomialSurface& surface, const std::string& z);

}  // namespace ccm::reports
