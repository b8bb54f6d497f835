// A report table: written as CSV into the report folder and as HTML into index.html.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace ccm::reports {

struct Table {
  std::string id{};                   // file stem and HTML anchor, e.g. "stability"
  std::string caption{};              // one sentence: what a row is
  std::vector<std::string> header{};  // column names with units
  std::vector<std::vector<std::string>> rows{};
};

// RFC 4180 CSV: fields with a comma, quote or line break are quoted, quotes doubled.
std::string to_csv(const Table& table);

// Body cells up to this many characters (labels, numbers, short equations) are kept on one line
// (class "nw"); longer ones (reasons, lists of hashes) wrap. Headers always wrap.
inline constexpr std::size_t kNoWrapCellLength = 32;

// An HTML <table> with its caption, text escaped.
std::string to_html(const Table& table);

// `text` with &, <, >, " escaped for HTML text and attribute values.
std::string html_escape(const std::string& text);

// A number for a table cell: 4 significant digits, "-" for NaN.
std::string cell(double value);

}  // namespace ccm::reports
