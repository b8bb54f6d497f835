#include "reports/figures/report_content.hpp"

#include "reports/plot/gnuplot.hpp"

namespace ccm::reports {

Figure make_figure(std::string id, std::string caption, const PlotSpec& plot) {
  return Figure{std::move(id), std::move(caption), render_svg(plot)};
}

}  // namespace ccm::reports
