// The report as a document: sections of prose, figures and tables, in order. Built by the
// section builders (no rendering: each figure keeps its PlotSpec, so its axes and legends can
// be checked), rendered by render_figures (gnuplot), written by reports/write/report_writer.
#pragma once

#include <string>
#include <vector>

#include "reports/plot/plot_spec.hpp"
#include "reports/tables/table.hpp"

namespace ccm::reports {

struct Figure {
  std::string id;         // file stem (DIR/<id>.svg) and HTML anchor
  std::string caption{};  // what is plotted, with the thesis figure it reproduces
  PlotSpec plot{};        // what is drawn
  std::string svg{};      // the SVG document, filled by render_figures
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

// A figure of `plot`, not yet rendered.
Figure make_figure(std::string id, std::string caption, PlotSpec plot);

// Renders every figure's plot to SVG (reports/plot/gnuplot.hpp). Throws ReportError when
// gnuplot is missing or fails.
void render_figures(ReportContent& content);

}  // namespace ccm::reports
