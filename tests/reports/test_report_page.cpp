// `ccm report` on a synthetic study: every figure and table file, a self-contained page (no URL
// but in-page anchors), the provenance, and a headless-Chromium screenshot that is not blank.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "app/study_commands.hpp"
#include "records/provenance/version.hpp"
#include "tests/reports/csv_reader.hpp"
#include "tests/reports/png_size.hpp"
#include "tests/reports/synthetic_study.hpp"
#include "tests/reports/text_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

using test::read_text;

// Every value of `attribute="..."` in the page.
std::vector<std::string> attribute_values(const std::string& html, const std::string& attribute) {
  const std::regex re(attribute + R"(\s*=\s*["']([^"']*)["'])", std::regex::icase);
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), re); it != std::sregex_iterator();
       ++it)
    out.push_back((*it)[1]);
  return out;
}

// "://" only inside XML namespace declarations (xmlns="http://www.w3.org/..."), which name a
// vocabulary and are never fetched.
bool only_namespace_urls(const std::string& html) {
  const std::string without_namespaces =
      std::regex_replace(html, std::regex(R"(xmlns(:\w+)?\s*=\s*"[^"]*")"), "");
  return without_namespaces.find("://") == std::string::npos;
}

std::string chromium_path() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser"})
    if (fs::exists(p)) return p;
  return {};
}

// Headless Chromium screenshot of `page` (900 x 1000 px); true when it wrote the PNG.
bool screenshot(const std::string& chromium, const fs::path& page, const fs::path& png) {
  const std::string command =
      "timeout 120 " + chromium +
      " --headless --no-sandbox --disable-gpu --disable-background-networking "
      "--window-size=900,1000 --hide-scrollbars --screenshot=" +
      png.string() + " file://" + fs::absolute(page).string() + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::exists(png);
}

// One report of the synthetic study through the command, shared by the tests below (it runs
// gnuplot for 28 figures: built once per test process).
struct SharedReport {
  test::TempDir dir;
  fs::path out = dir.path / "report";
  std::string html;
  SharedReport() {
    test::write_synthetic_study(dir.path / "study.sqlite");
    REQUIRE(report_command({dir.path / "study.sqlite", out, 0.1}) == 0);
    html = read_text(out / "index.html");
  }
};

const SharedReport& shared_report() {
  static const SharedReport report;
  return report;
}

// Host name as gethostname reports it (the provenance's "machine").
std::string this_host() {
  std::array<char, 256> name{};
  return gethostname(name.data(), name.size() - 1) == 0 ? std::string(name.data()) : "unknown";
}

// The value column of a two-column provenance.csv row, by its item name.
std::string provenance_value(const test::CsvRows& rows, const std::string& item) {
  for (const auto& row : rows)
    if (row.size() == 2 && row[0] == item) return row[1];
  FAIL("provenance.csv has no row \"" << item << "\"");
  return {};
}

// One test case (sections share the one report built per process).
TEST_CASE("ccm report on the synthetic study: files, self-contained page, provenance",
          "[reports]") {
  const fs::path& out = shared_report().out;
  const std::string& html = shared_report().html;

  SECTION("every figure of the page is also its own SVG, every table a CSV") {
    const auto figure_ids = attribute_values(html, "<figure id");
    // 3 per-point timing figures, 4 corner histories, 6 errors, 2 NT with surfaces, 2 KE x 4
    // fits, error against RTR, 2 convergence figures, 2 recommendation maps (in the summary).
    CHECK(figure_ids.size() == 3 + 4 + 6 + 2 + 8 + 1 + 2 + 2);
    for (const auto& id : figure_ids) {
      INFO(id);
      CHECK(fs::exists(out / (id + ".svg")));
      CHECK(read_text(out / (id + ".svg")).find("<svg") != std::string::npos);
    }
    const auto table_ids = attribute_values(html, "<table id");
    CHECK(table_ids == std::vector<std::string>{"points", "impact", "stability", "fits",
                                                "convergence", "provenance"});
    for (const auto& id : table_ids) {
      INFO(id);
      CHECK(fs::exists(out / (id + ".csv")));
    }
    for (const char* figure :
         {"fig-recommendation-ke-100", "fig-ke-history-point-23",  // ER 1e6, RLS 1.5, KE 100 J
          "fig-normalised-runtime-ke-10", "fig-normalised-runtime-ke-100",
          "fig-convergence-error-vs-time", "fig-convergence-accuracy-per-second"}) {
      INFO(figure);
      CHECK(fs::exists(out / (std::string(figure) + ".svg")));
    }
    // header + one row per run, convergence runs included
    CHECK(test::read_csv(out / "stability.csv").size() ==
          1 + 2 * (test::kSyntheticPoints + test::kConvergencePoints));
    CHECK(test::read_csv(out / "convergence.csv").size() == 1 + 2 * test::kConvergencePoints);
    CHECK(test::read_csv(out / "points.csv").size() == 1 + test::kSyntheticPoints);
  }

  SECTION("the page leads with the answer: the rule, the maps and the per-point table first") {
    const auto section_ids = attribute_values(html, "<section id");
    REQUIRE_FALSE(section_ids.empty());
    CHECK(section_ids.front() == "summary");
    const auto summary = html.find("id=\"summary\"");
    const auto map = html.find("id=\"fig-recommendation-ke-10\"");
    const auto points = html.find("id=\"points\"");
    const auto first_thesis_figure = html.find("id=\"fig-final-u-mean\"");
    REQUIRE(map != std::string::npos);
    REQUIRE(first_thesis_figure != std::string::npos);
    CHECK(summary < map);
    CHECK(map < first_thesis_figure);
    CHECK(points < first_thesis_figure);
    CHECK(html.find("use the rigid model where its final-state error against CCM is within 0.1") <
          first_thesis_figure);
  }

  SECTION("no URL other than in-page anchors, no script") {
    const auto hrefs = attribute_values(html, "href");
    CHECK(hrefs.size() >= 7);  // the table of contents
    for (const auto& href : hrefs) CHECK(href.rfind('#', 0) == 0);
    CHECK(attribute_values(html, "src").empty());
    CHECK(html.find("<script") == std::string::npos);
    CHECK(html.find("<link") == std::string::npos);
    CHECK(html.find("url(") == std::string::npos);
    CHECK(only_namespace_urls(html));
  }

  SECTION("no rig run stored: the rig section says so; the unstable run's reason is shown") {
    CHECK(html.find("id=\"rig\"") != std::string::npos);
    CHECK(html.find("No benchtop rig run is stored in this database") != std::string::npos);
    CHECK(html.find(test::kUnstableReason) != std::string::npos);
  }

  SECTION("provenance: ccm version and git hash, dates, grid and scene hashes, machine") {
    const auto rows = test::read_csv(out / "provenance.csv");
    REQUIRE(rows.size() == 13);  // header + 12 items
    const std::string version = std::string(ccm_version()) + " (git " + git_hash() + ")";
    CHECK(provenance_value(rows, "study") == "synthetic");
    CHECK(provenance_value(rows, "grid file hash") == "gridhash0123");
    CHECK(provenance_value(rows, "runs: scene content hashes") == "ccmscenehash; rigidscenehash");
    CHECK(provenance_value(rows, "runs: ccm version (git hash)") == version);
    CHECK(provenance_value(rows, "report: ccm version") == version);
    CHECK(provenance_value(rows, "runs: machines") == this_host());
    CHECK(provenance_value(rows, "report: machine") == this_host());
    CHECK(provenance_value(rows, "runs: first started") == "2026-11-22T05:00:00.000Z");
    CHECK(provenance_value(rows, "runs: last ended") == "2026-11-22T05:01:00.000Z");
    // Written now by the store and the report: ISO 8601 UTC with milliseconds.
    const std::regex utc(R"(\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}\.\d{3}Z)");
    CHECK(std::regex_match(provenance_value(rows, "study created"), utc));
    CHECK(std::regex_match(provenance_value(rows, "report: generated"), utc));
    CHECK(html.find(version) != std::string::npos);
  }
}

TEST_CASE("ccm report: headless Chromium renders the page, and it is not blank", "[reports]") {
  const std::string chromium = chromium_path();
  INFO("chromium not found: it is a test dependency (scripts/install-deps.sh installs it)");
  REQUIRE_FALSE(chromium.empty());
  const auto& report = shared_report();
  const fs::path blank =
      report.dir.write("blank.html", "<!DOCTYPE html><html><body></body></html>");
  REQUIRE(screenshot(chromium, report.out / "index.html", report.dir.path / "report.png"));
  REQUIRE(screenshot(chromium, blank, report.dir.path / "blank.png"));
  const auto report_png = test::summarise_png(report.dir.path / "report.png");
  const auto blank_png = test::summarise_png(report.dir.path / "blank.png");
  REQUIRE(report_png);
  REQUIRE(blank_png);
  CHECK(report_png->width == 900);
  CHECK(report_png->height == 1000);
  // A uniform page compresses to almost nothing; text, tables and plots do not. Measured
  // (docs/report.md): blank 4.7 kB of IDAT, the report's first screen 102 kB. A
  // factor 10 leaves room for other fonts and Chromium versions.
  CHECK(report_png->idat_bytes > 10 * blank_png->idat_bytes);
}

}  // namespace
}  // namespace ccm
