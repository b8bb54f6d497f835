// Writing the report folder: a re-run replaces it whole, a file in the way is refused.
#include <catch2/catch.hpp>
#include <fstream>

#include "reports/report_error.hpp"
#include "reports/write/report_writer.hpp"
#include "tests/reports/text_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm::reports {
namespace {

namespace fs = std::filesystem;

ReportContent one_figure_report(const std::string& figure_id) {
  Section s{.id = "s", .title = "S"};
  s.figures.push_back(Figure{
      .id = figure_id, .caption = "caption", .svg = "<?xml version=\"1.0\"?>\n<svg></svg>\n"});
  s.tables.push_back(Table{"t-" + figure_id, "caption", {"a"}, {{"1"}}});
  return ReportContent{.title = "T", .sections = {s}};
}

TEST_CASE("write_report replaces the folder whole and leaves no staging folder", "[reports]") {
  test::TempDir dir;
  const fs::path out = dir.path / "report";
  write_report(one_figure_report("first"), out);
  CHECK(fs::exists(out / "first.svg"));
  CHECK(fs::exists(out / "t-first.csv"));
  std::ofstream(out / "stale.txt") << "old";
  write_report(one_figure_report("second"), out);
  CHECK(fs::exists(out / "second.svg"));
  CHECK(fs::exists(out / "t-second.csv"));
  CHECK_FALSE(fs::exists(out / "first.svg"));
  CHECK_FALSE(fs::exists(out / "stale.txt"));
  // The page inlines the SVG element without its XML prolog.
  const std::string html = test::read_text(out / "index.html");
  CHECK(html.find("<svg></svg>") != std::string::npos);
  CHECK(html.find("<?xml") == std::string::npos);
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir.path)) entries += e.path() != out;
  CHECK(entries == 0);  // no ".report.staging-*" or ".report.old-*" left beside it
}

TEST_CASE("write_report refuses an output path that is a file, and keeps the file", "[reports]") {
  test::TempDir dir;
  const fs::path out = dir.write("report", "a file, not a folder");
  CHECK_THROWS_AS(write_report(one_figure_report("x"), out), ReportError);
  CHECK_THROWS_WITH(write_report(one_figure_report("x"), out), Catch::Contains("not a folder"));
  CHECK(fs::is_regular_file(out));
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir.path)) entries += e.path() != out;
  CHECK(entries == 0);
}

}  // namespace
}  // namespace ccm::reports
