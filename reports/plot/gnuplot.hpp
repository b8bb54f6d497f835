// Renders a PlotSpec to SVG with gnuplot (Debian gnuplot-nox) run as a child process: the data
// and the script go through a private temporary folder, the SVG comes back as text.
#pragma once

#include <string>

#include "reports/plot/plot_spec.hpp"

namespace ccm::reports {

// The gnuplot executable on PATH; throws ReportError with the package to install when absent.
std::string find_gnuplot();

// The gnuplot script that draws `plot` from the files series-<i>.dat into `svg_file`.
std::string gnuplot_script(const PlotSpec& plot, const std::string& svg_file);

// The SVG document gnuplot writes for `plot`. Throws ReportError when gnuplot is missing,
// fails (its error output is in the message) or when the plot has no data.
std::string render_svg(const PlotSpec& plot);

}  // namespace ccm::reports
