#include "reports/figures/report_content.hpp"

#include "reports/plot/gnuplot.hpp"

namespace ccm::reports {

Figure make_figure(std::string id, std::string caption, PlotSpec plot) {
  return Figure{.id = std::move(id), .caption = std::move(caption), .plot = std::move(plot)};
}

void render_figures(ReportContent& content) {
  for (Section& s : content.sections)
    for (Figure& f : s.figures) f.svg = render_svg(f.plot);
}

}  // namespace ccm::reports
