#include "reports/html/html_page.hpp"

#include <fmt/format.h>

namespace ccm::reports {
namespace {

// Readable on a laptop screen: one column at most 1100 px wide, figures scaled to fit, wide
// tables scroll inside their box.
constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", sans-serif; margin: 0 auto; max-width: 1100px;
       padding: 1em 1.5em; color: #222; background: #fff; line-height: 1.4; }
h1 { font-size: 1.6em; border-bottom: 2px solid #0072B2; }
h2 { font-size: 1.3em; margin-top: 2em; border-bottom: 1px solid #ccc; }
nav ul { columns: 2; }
figure { margin: 1.5em 0; }
figure svg { max-width: 100%; height: auto; }
figcaption { font-size: 0.9em; color: #444; }
.table-box { overflow-x: auto; margin: 1em 0; }
table { border-collapse: collapse; font-size: 0.85em; }
caption { text-align: left; font-weight: bold; padding: 0.3em 0; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: left; }
th { background: #eef4fa; }
td.nw { white-space: nowrap; }
)css";

std::string section_html(const Section& s) {
  std::string out =
      fmt::format("<section id=\"{}\">\n<h2>{}</h2>\n", html_escape(s.id), html_escape(s.title));
  for (const auto& p : s.paragraphs) out += "<p>" + html_escape(p) + "</p>\n";
  for (const auto& f : s.figures)
    out += fmt::format("<figure id=\"{}\">\n{}\n<figcaption>{}</figcaption>\n</figure>\n",
                       html_escape(f.id), inline_svg(f.svg), html_escape(f.caption));
  for (const auto& t : s.tables) out += "<div class=\"table-box\">\n" + to_html(t) + "</div>\n";
  return out + "</section>\n";
}

}  // namespace

std::string inline_svg(const std::string& svg_document) {
  const auto start = svg_document.find("<svg");
  return start == std::string::npos ? std::string() : svg_document.substr(start);
}

std::string html_page(const ReportContent& content) {
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>{0}</title>\n<style>{1}</style>\n</head>\n<body>\n<h1>{0}</h1>\n<nav><ul>\n",
      html_escape(content.title), kStyle);
  for (const auto& s : content.sections)
    out +=
        fmt::format("<li><a href=\"#{}\">{}</a></li>\n", html_escape(s.id), html_escape(s.title));
  out += "</ul></nav>\n";
  for (const auto& s : content.sections) out += section_html(s);
  return out + "</body>\n</html>\n";
}

}  // namespace ccm::reports
