// The report's parts on hand-made inputs: equations, CSV, log-axis choice, gnuplot scripts,
// the stability table, the corner points and the recommendation map of the synthetic study.
#include <catch2/catch.hpp>

#include "db/store/study_store.hpp"
#include "reports/data/report_loader.hpp"
#include "reports/figures/impact_table.hpp"
#include "reports/figures/recommendation_map.hpp"
#include "reports/figures/stability_section.hpp"
#include "reports/figures/summary_section.hpp"
#include "reports/figures/surface_series.hpp"
#include "reports/figures/trade_study_section.hpp"
#include "reports/plot/gnuplot.hpp"
#include "reports/tables/table.hpp"
#include "tests/reports/synthetic_study.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm::reports {
namespace {

TEST_CASE("surface_equation writes every term with its sign and powers", "[reports]") {
  study::PolynomialSurface s{{1, 2},
                             {{0, 0, 1.5}, {0, 1, 0.25}, {0, 2, -3e-5}, {1, 0, -2.0}, {1, 1, 4.0}}};
  CHECK(surface_equation(s, "w") == "w = 1.5 + 0.25 y - 3e-05 y^2 - 2 x + 4 x y");
  s.terms = {{0, 0, -0.5}};
  CHECK(surface_equation(s, "z") == "z = -0.5");
  // Rounding noise of an exact fit (below 1e-12 of the largest coefficient) is left out.
  s.terms = {{0, 0, 3e-17}, {0, 1, 0.30103}, {1, 0, -2e-13}};
  CHECK(surface_equation(s, "z") == "z = 0.301 y");
  s.terms = {{0, 0, 3e-13}, {0, 1, 0.1}};
  CHECK(surface_equation(s, "z") == "z = 3e-13 + 0.1 y");
  s.terms.clear();
  CHECK(surface_equation(s, "z") == "z = 0");
}

TEST_CASE("tables are written as RFC 4180 CSV and escaped HTML", "[reports]") {
  const Table t{"t", "caption <b>", {"a", "b [m]"}, {{"1,5", "say \"hi\""}, {"x", "<y>"}}};
  CHECK(to_csv(t) == "a,b [m]\n\"1,5\",\"say \"\"hi\"\"\"\nx,<y>\n");
  const std::string html = to_html(t);
  CHECK(html.find("caption &lt;b&gt;") != std::string::npos);
  CHECK(html.find("<td class=\"nw\">&lt;y&gt;</td>") != std::string::npos);
  CHECK(html.find("<y>") == std::string::npos);
  // Short cells stay on one line, long ones (a reason, a list of hashes) may wrap.
  const Table wide{"w", "c", {"h"}, {{"ER 100, RLS 1, KE 100 J"}, {std::string(40, 'a')}}};
  CHECK(to_html(wide).find("<td class=\"nw\">ER 100, RLS 1, KE 100 J</td>") != std::string::npos);
  CHECK(to_html(wide).find("<td>" + std::string(40, 'a') + "</td>") != std::string::npos);
}

TEST_CASE("an axis is logarithmic when positive values span two decades", "[reports]") {
  CHECK(spans_decades(std::vector<double>{1.0, 100.0}));
  CHECK_FALSE(spans_decades(std::vector<double>{1.0, 99.0}));
  CHECK_FALSE(spans_decades(std::vector<double>{0.0, 1.0, 1e6}));  // zero: no log axis
  CHECK_FALSE(spans_decades(std::vector<double>{}));
}

TEST_CASE("gnuplot scripts label axes, name series and quote text", "[reports]") {
  PlotSpec plot{.title = "say \"x\"", .x_label = "time [s]", .y_label = "KE [J]", .log_y = true};
  plot.series = {Series{.title = "CCM", .x = {0, 1}, .y = {1, 2}}, Series{.title = "empty"},
                 Series{.title = "rigid", .style = SeriesStyle::lines, .x = {0}, .y = {1}}};
  const std::string script = gnuplot_script(plot, "/tmp/f.svg");
  CHECK(script.find("set title \"say \\\"x\\\"\"") != std::string::npos);
  CHECK(script.find("set xlabel \"time [s]\"") != std::string::npos);
  CHECK(script.find("set logscale y") != std::string::npos);
  CHECK(script.find("set logscale x") == std::string::npos);
  CHECK(script.find("'series-0.dat' using 1:2") != std::string::npos);
  CHECK(script.find("series-1.dat") == std::string::npos);  // empty series left out
  CHECK(script.find("'series-2.dat' using 1:2 with lines") != std::string::npos);
  CHECK(script.find("title \"rigid\"") != std::string::npos);
  CHECK(script.find("set key below Left reverse box height 1") != std::string::npos);
  CHECK(script.find("set xlabel \"time [s]\" offset 0,0.3") != std::string::npos);
  CHECK(script.find("set xtics") == std::string::npos);
}

TEST_CASE("gnuplot scripts: whole-number tics on an index axis, map cells as boxes", "[reports]") {
  PlotSpec index{.x_label = "index [-]", .y_label = "t [s]", .integer_x = true};
  index.series = {Series{.title = "a", .x = {0, 1, 2, 3}, .y = {1, 2, 3, 4}}};
  CHECK(gnuplot_script(index, "f.svg").find("set xtics 1\n") != std::string::npos);
  index.series[0].x = {0, 35};
  CHECK(gnuplot_script(index, "f.svg").find("set xtics 4\n") != std::string::npos);
  // Cells of half a decade by 0.1 on a log x axis: x 10^-0.5 .. x 10^0.5, y - 0.1 .. y + 0.1.
  PlotSpec map{.x_label = "ER [-]", .y_label = "RLS [-]", .log_x = true};
  map.series = {Series{.title = "use CCM at KE 1 J",
                       .style = SeriesStyle::cells,
                       .x = {1.0},
                       .y = {1.0},
                       .cell_dx = 0.5,
                       .cell_dy = 0.1}};
  const std::string script = gnuplot_script(map, "f.svg");
  CHECK(script.find("using 1:2:($1*10**(-0.5)):($1*10**(0.5)):($2-0.10000000000000001):($2+"
                    "0.10000000000000001) with boxxyerror fs solid") != std::string::npos);
}

TEST_CASE("rendering a plot without data is an error naming the figure", "[reports]") {
  PlotSpec plot{.title = "nothing here"};
  plot.series = {Series{.title = "empty"}};
  CHECK_THROWS_WITH(render_svg(plot), Catch::Contains("nothing here"));
}

TEST_CASE("corner points: lowest and highest ER by lowest and highest RLS at the highest KE",
          "[reports]") {
  std::vector<study::GridPoint> grid;
  for (double ke : {10.0, 100.0})
    for (double rls : {0.5, 1.0, 1.5})
      for (double er : {1.0, 1e3, 1e6}) grid.push_back({int(grid.size()), er, rls, ke, {}});
  const auto corners = corner_points(grid);
  REQUIRE(corners.size() == 4);
  // index = 9 KE_i + 3 RLS_i + ER_i: (1e6, 0.5), (1e6, 1.5), (1, 0.5), (1, 1.5) at KE 100.
  CHECK(corners[0].index == 9 + 0 + 2);
  CHECK(corners[1].index == 9 + 6 + 2);
  CHECK(corners[2].index == 9 + 0 + 0);
  CHECK(corners[3].index == 9 + 6 + 0);
}

TEST_CASE("synthetic study: stability table and recommendation map against closed forms",
          "[reports]") {
  test::TempDir dir;
  test::write_synthetic_study(dir.path / "study.sqlite");
  db::StudyStore store(dir.path / "study.sqlite");
  REQUIRE(store.open_existing_study());
  const ReportData data = load_report_data(store);
  constexpr int kPoints = test::kSyntheticPoints + test::kConvergencePoints;
  REQUIRE(data.status.size() == kPoints);
  REQUIRE(data.runs.size() == 2 * kPoints);
  REQUIRE(data.grid.size() == test::kSyntheticPoints);
  REQUIRE(data.convergence.size() == test::kConvergencePoints);

  SECTION("one row per run; the unstable run with its reason, time and step range") {
    const Table t = stability_table(data);
    REQUIRE(t.rows.size() == 2 * kPoints);
    CHECK(t.header == std::vector<std::string>{
                          "point", "case", "model", "verdict", "reason", "dt min [s]", "dt max [s]",
                          "max energy-balance error [-]", "steps", "unstable at [s]"});
    const auto& row = t.rows[2 * test::kUnstablePointIndex + 1];  // its rigid run
    CHECK(row[2] == "rigid");
    CHECK(row[3] == "unstable");
    CHECK(row[4] == test::kUnstableReason);
    CHECK(row[5] == "9e-05");  // dt_min = 0.9 ISTS_rigid
    CHECK(row[6] == "0.0001");
    CHECK(row[7] == "0.2");
    CHECK(row[8] == "1200");  // 0.12 s / 1e-4 s
    CHECK(row[9] == "0.12");
    // A convergence run's case names its mesh scale: its row is not the grid point's twin.
    const auto& convergence = t.rows[2 * test::kSyntheticPoints];  // point 24, its CCM run
    CHECK(convergence[0] == "24");
    CHECK(convergence[1] == "ER 100, RLS 1, KE 100 J, mesh_scale 2");
    CHECK(t.rows[2 * 17][1] == "ER 100, RLS 1, KE 100 J");  // the grid point of that case
  }

  SECTION("rigid exactly where the final-state error 0.4 (1 - log10 ER / 6) is below 0.1") {
    // Errors are linear in log10 ER, so the fitted surfaces reproduce them (to rounding) and
    // rigid is recommended for log10 ER > 4.5. Cells at log10 ER = 0.2 i, i = 0..30: rigid
    // for i >= 23 (4.6, error 0.0933), CCM for i <= 22 (4.4, error 0.1067): 8 of 31 columns.
    for (double ke : {10.0, 100.0}) {
      const auto cells = recommendation_cells(data.fits, data.grid, {}, ke, 0.1);
      REQUIRE(cells.size() == std::size_t(kMapCells * kMapCells));
      int rigid = 0;
      for (const MapCell& c : cells) {
        const bool expect_rigid = test::synthetic_final_error(c.modulus_ratio) < 0.1;
        CHECK((c.model == study::ImpactModel::rigid) == expect_rigid);
        // The boundary lies between cell columns 22 and 23 (errors 0.107 and 0.093), far
        // beyond the exact fits' leave-one-out error (rounding): every cell is reliable.
        CHECK(c.reliable);
        rigid += c.model == study::ImpactModel::rigid;
      }
      CHECK(rigid == 8 * kMapCells);
    }
  }

  SECTION("the summary's per-point table: measured errors, RTR, w, the rule, no flag") {
    const Table t = points_table(data, 0.1);
    REQUIRE(t.rows.size() == std::size_t(test::kSyntheticPoints));
    REQUIRE(t.header.size() == 17);
    CHECK(t.header[8] == "RTR measured [-]");
    CHECK(t.header[9] == "RTR thesis estimate [-]");
    for (const auto& row : t.rows) {
      REQUIRE(row.size() == t.header.size());
      const int index = std::stoi(row[0]);
      if (index == test::kUnstablePointIndex) {
        CHECK(row[16] == data.grid[static_cast<std::size_t>(index)].excluded_reason);
        continue;
      }
      const double er = std::stod(row[1]);
      // Rigid exactly at ER 1e6 (error 0 <= 0.1, RTR 2000 / 2^RLS > 1), CCM elsewhere.
      CHECK(row[13] == (er > 1e5 ? "rigid" : "ccm"));
      CHECK(row[14] == row[13]);
      CHECK(row[15] == "ok");
      const study::PointMetrics& m = data.grid[static_cast<std::size_t>(index)];
      CHECK(std::stod(row[8]) == Approx(m.runtime_ratio).epsilon(5e-4));  // cells keep 4 digits
      CHECK(std::stod(row[9]) == Approx(m.runtime_ratio_thesis_estimate).epsilon(5e-4));
      CHECK(std::stod(row[6]) == Approx(test::synthetic_final_error(er)).margin(1e-3));
    }
  }

  SECTION("the designer's metrics: a table of every usable point, a sentence, closed forms") {
    const auto t = impact_table(data);
    REQUIRE(t);
    REQUIRE(t->rows.size() == std::size_t(test::kSyntheticPoints - 1));  // not the unstable one
    REQUIRE(t->header.size() == 18);
    for (const auto& row : t->rows) {
      REQUIRE(row.size() == t->header.size());
      const double er = std::stod(row[1]);
      CHECK(std::stod(row[5]) == Approx(60.0).epsilon(5e-4));  // 2 kg x 1.5 m/s / 0.05 s
      CHECK(std::stod(row[6]) == Approx(80.0).epsilon(5e-4));  // 2 kg x 2 m/s / 0.05 s
      CHECK(std::stod(row[7]) == Approx(0.25).epsilon(5e-4));
      CHECK(std::stod(row[10]) == Approx(test::synthetic_final_error(er)).margin(1e-3));
      CHECK(std::stod(row[11]) == Approx(0.05).epsilon(5e-4));
      CHECK(std::stod(row[13]) == Approx(0.0).margin(1e-9));
      CHECK(std::stod(row[14]) == Approx(test::kSyntheticReboundCcm).epsilon(5e-4));
      CHECK(std::stod(row[16]) == Approx(0.5).epsilon(5e-4));
      CHECK(std::stod(row[17]) == Approx(0.5).epsilon(5e-4));
    }
    const auto sentence = impact_sentence(data, 0.1);
    REQUIRE(sentence);
    CHECK_THAT(*sentence, Catch::Contains("within 0.1 on all four at 0 of 23 points") &&
                              Catch::Contains("most often the rebound speed (23 points)"));
    CHECK(impact_sentence(data, 0.5)->find("at 23 of 23 points") != std::string::npos);
  }

  SECTION("the summary's sentences are generated from the measured points") {
    const auto sentences = summary_sentences(data, 0.1);
    REQUIRE(sentences.size() == 2);
    // 6 points at ER 1e6 (3 RLS x 2 KE) of 23 usable; RTR = 2 sqrt(ER) / 2^RLS is below 1 only
    // at ER 1, RLS 1.5 (and 1 to rounding at RLS 1).
    CHECK(sentences[0].find("The rule recommends the rigid model at 6 of 23 measured points, "
                            "all at ER >= 1e+06") != std::string::npos);
    CHECK(sentences[0].find("point(s), up to ER 1, CCM is not dearer") != std::string::npos);
    CHECK(sentences[0].find("The fitted surfaces give the measured answer at 23 of 23 points; 0 "
                            "differ and 0 more are unreliable") != std::string::npos);
    CHECK(sentences[1].find("1 grid point(s) are left out") != std::string::npos);
  }
}

}  // namespace
}  // namespace ccm::reports
