// index.html: one self-contained page (inline CSS and SVG, no script, no external resource),
// with a table of contents of in-page anchors.
#pragma once

#include <string>

#include "reports/figures/report_content.hpp"

namespace ccm::reports {

std::string html_page(const ReportContent& content);

// The <svg ...>...</svg> element of an SVG document (its XML prolog and DOCTYPE removed), for
// inlining into HTML.
std::string inline_svg(const std::string& svg_document);

}  // namespace ccm::reports
