// What one figure shows, independent of the plotting program: 2-D series (points, lines) or
// 3-D series (scatter points, surface meshes), axis labels with units, log axes.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace ccm::reports {

enum class SeriesStyle {
  points,       // markers only
  lines,        // a polyline in data order
  linespoints,  // both
  squares,      // large filled squares
  cells,        // filled rectangles centred on the points, cell_dx x cell_dy half-sizes (maps)
  surface,      // 3-D: a mesh of `surface_columns` points per row, rows in data order
  thin_lines,   // a thin polyline in data order (e.g. one measured trial among several)
  band,         // 2-D: the area between y (lower) and z (upper) at each x, translucent
  marks,        // 2-D: a dashed vertical segment at each x, from y to z (event times)
};

struct Series {
  std::string title{};  // legend entry: names the model and the case
  SeriesStyle style = SeriesStyle::points;
  std::vector<double> x{}, y{}, z{};  // z only for 3-D plots, bands and marks (upper end)
  std::size_t surface_columns = 0;    // points per mesh row (SeriesStyle::surface)
  // Half-sizes of SeriesStyle::cells: cell_dx in decades when the x axis is logarithmic (the
  // cell spans x 10^-dx .. x 10^dx), else in x units; cell_dy in y units.
  double cell_dx = 0.0, cell_dy = 0.0;
  int color = 0;  // index into the colour-blind-safe palette of reports/plot/gnuplot.cpp
  bool empty() const { return x.empty(); }
};

struct PlotSpec {
  std::string title{};
  std::string x_label{}, y_label{}, z_label{};  // with units, e.g. "wall time [s]"
  bool log_x = false, log_y = false, log_z = false;
  bool three_d = false;
  bool integer_x = false;  // x is an index: tics on whole numbers only
  std::vector<Series> series{};
  int width = 720, height = 440;  // SVG size [px]
};

// True when every value is positive and the largest is at least 100 times the smallest, so
// the axis should be logarithmic.
bool spans_decades(std::span<const double> values);

// All the values of one coordinate over every series of a plot (0 = x, 1 = y, 2 = z).
std::vector<double> all_values(const PlotSpec& plot, int axis);

}  // namespace ccm::reports
