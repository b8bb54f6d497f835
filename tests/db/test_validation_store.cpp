// `ccm validate`'s records in the store (db/store/validation_store.hpp, schema step 9) and the
// report's section of them (reports/figures/validation_section.hpp): a record reads back field
// for field with its scores and curves, and the section draws one figure per channel from the
// stored curves.
#include <fmt/format.h>

#include <catch2/catch.hpp>

#include "db/store/study_store.hpp"
#include "db/store/validation_store.hpp"
#include "reports/figures/validation_section.hpp"
#include "tests/app/cli_shell.hpp"
#include "tests/db/scratch_dir.hpp"
#include "tests/reports/synthetic_study.hpp"

using namespace ccm;

namespace {

db::ValidationRow validation() {
  db::ValidationRow r;
  r.scene = "drop.toml";
  r.data = "bench/drop";
  r.document = "{}";
  r.scores = {
      {"load", "t1.csv", false, 80, 0.05, 2000.0, 2100.0, 1e-4, 0.9, 1.0, 0.8, 0.9, 0.9, "good"},
      {"load", "mean", false, 80, std::nullopt, 2000.0, 2100.0, 0.0, 1.0, 1.0, 0.95, 0.95, 0.98,
       "excellent"}};
  r.curves = {{"load", "N", "time,simulated,mean,low,high\n0,1,1,0.9,1.1\n1e-4,2,2.1,2,2.2\n"}};
  return r;
}

}  // namespace

TEST_CASE("validation store: a record reads back, and the report draws it", "[bench_test][store]") {
  test::ScratchDir dir("validations");
  const auto file = dir / "s.sqlite";
  { db::StudyStore create(file); }  // an empty store at the latest schema
  CHECK_THROWS_AS(db::record_validation(dir / "none.sqlite", validation()), db::StoreError);
  CHECK(db::record_validation(file, validation()) == 1);
  db::StudyStore store(file, db::Access::read_only);
  const std::vector<db::ValidationRow> rows = db::load_validations(store.connection());
  REQUIRE(rows.size() == 1);
  CHECK(rows[0].scene == "drop.toml");
  CHECK(!rows[0].recorded_at.empty());
  REQUIRE(rows[0].scores.size() == 2);
  CHECK(rows[0].scores[0].nrmse == 0.05);
  CHECK_FALSE(rows[0].scores[1].nrmse);
  CHECK(rows[0].scores[1].grade == "excellent");
  CHECK(rows[0].scores[0].peak_simulated == 2100.0);
  REQUIRE(rows[0].curves.size() == 1);
  CHECK(rows[0].curves[0].unit == "N");

  const reports::Section s = reports::validation_section(rows);
  REQUIRE(s.tables.size() == 1);
  CHECK(s.tables[0].rows.size() == 2);
  CHECK(s.tables[0].rows[0][3] == "+5.0 %");  // (2100 - 2000) / 2000
  REQUIRE(s.figures.size() == 1);
  REQUIRE(s.figures[0].plot.series.size() == 3);  // band, mean, simulated
  CHECK(s.figures[0].plot.series[0].z == std::vector<double>{1.1, 2.2});
  CHECK(s.figures[0].plot.series[2].y == std::vector<double>{1, 2});
  CHECK_THAT(reports::validation_section({}).paragraphs.at(0),
             Catch::Contains("No bench test validated yet"));
}

TEST_CASE("validation store: `ccm report` shows the rating table and draws each channel",
          "[bench_test][store][cli]") {
  test::TempDir dir;
  const auto file = dir.path / "study.sqlite";
  test::write_synthetic_study(file);
  db::record_validation(file, validation());
  const auto r = test::run_ccm(
      fmt::format("report --db '{}' --out '{}'", file.string(), (dir.path / "rep").string()), dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::string html = test::file_text(dir.path / "rep" / "index.html");
  CHECK_THAT(html, Catch::Contains("Your bench tests") && Catch::Contains("t1.csv") &&
                       Catch::Contains("excellent"));
  const std::string svg = test::file_text(dir.path / "rep" / "fig-validation-1-load.svg");
  CHECK_THAT(svg, Catch::Contains("<svg") && Catch::Contains("simulated (drop.toml)"));
}
