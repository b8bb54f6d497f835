// The report as a document: sections of prose, figures (rendered SVG) and tables, in order.
// Built by the section builders, written by reports/write/report_writer.
#pragma once

#include <string>
#include <vector>

#include "reports/plot/plot_spec.hpp"
#include "reports/tables/table.hpp"

namespace ccm::reports {

struct Figure {
  std::string id;         // file stem (DIR/<id>.svg) and HTML anchor
  std::string caption{};  // what is plotted, with the thesis figure it reproduces
  std::string svg{};      // the SVG document
};

struct Section {
  std::string id{}, title{};
  std::vector<std::string> paragraphs{};  // plain text, escaped on output
  std::vector<Figure> figures{};
  std::vector<Table> tables{};
};

struct ReportContent {
  std::string title{};
  std::vector<Section> sections{};
};

// Renders `plot` (reports/plot/gnuplot.hpp) into a figure.
Figure make_figure(std::string id, std::string caption, const PlotSpec& plot);

}  // namespace ccm::reports
