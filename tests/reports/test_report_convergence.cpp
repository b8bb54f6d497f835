// The convergence mode in the report (error against runtime, accuracy per second): the
// synthetic study's convergence runs (two cases at mesh scales 2, 1, 0.5) against their closed
// forms, in the figures' data and in the convergence.csv the report writes.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "db/store/study_store.hpp"
#include "reports/data/report_loader.hpp"
#include "reports/write/report_writer.hpp"
#include "tests/reports/csv_reader.hpp"
#include "tests/reports/synthetic_study.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm::reports {
namespace {

namespace fs = std::filesystem;
using study::ImpactModel;

ReportData synthetic_data(const test::TempDir& dir) {
  test::write_synthetic_study(dir.path / "study.sqlite");
  db::StudyStore store(dir.path / "study.sqlite");
  REQUIRE(store.open_existing_study());
  return load_report_data(store);
}

// A table cell holds 4 significant digits: within half a unit of the 4th digit.
bool cell_equals(const std::string& text, double expected) {
  const double value = std::stod(text);
  return std::abs(value - expected) <= 5e-4 * std::abs(expected) + 1e-15;
}

const Figure& find_figure(const ReportContent& content, const std::string& id) {
  for (const Section& s : content.sections)
    for (const Figure& f : s.figures)
      if (f.id == id) return f;
  FAIL("no figure " << id);
  throw std::logic_error("unreachable");
}

struct ClosedForm {
  double error, wall, accuracy_per_second;
};

// Point index 24 + 3 c + k is case c at mesh scale k (test::kConvergenceCases, ...Scales).
ClosedForm closed_form(int point_index, ImpactModel model) {
  const int i = point_index - test::kSyntheticPoints;
  const auto& c = test::kConvergenceCases.at(std::size_t(i) / test::kConvergenceScales.size());
  const double scale =
      test::kConvergenceScales.at(std::size_t(i) % test::kConvergenceScales.size());
  const double error = test::synthetic_convergence_error(model, c.modulus_ratio, scale);
  const double wall = test::synthetic_wall_seconds(model, c.modulus_ratio, c.length_ratio, scale);
  return {error, wall, (1.0 - error) / wall};
}

TEST_CASE(
    "convergence.csv: every run's errors, wall time and accuracy per second equal the "
    "closed forms",
    "[reports]") {
  test::TempDir dir;
  const ReportData data = synthetic_data(dir);
  // Planned, not rendered: the CSV tables and the page are written without gnuplot.
  write_report(plan_report(data, {}, current_stamp()), dir.path / "report");
  const test::CsvRows rows = test::read_csv(dir.path / "report" / "convergence.csv");
  REQUIRE(rows.size() == 1 + 2 * test::kConvergencePoints);
  const std::vector<std::string> header = {"point",
                                           "case",
                                           "model",
                                           "role",
                                           "mesh scale [-]",
                                           "elements",
                                           "wall time [s]",
                                           "final-state u_mean error [-]",
                                           "final-state u_max error [-]",
                                           "final-state KE error [-]",
                                           "accuracy per second [1/s]"};
  REQUIRE(rows[0] == header);
  std::set<std::pair<int, std::string>> seen;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    INFO("row " << r << ": point " << row[0] << ", " << row[2] << ", scale " << row[4]);
    REQUIRE(row.size() == header.size());
    const int point = std::stoi(row[0]);
    const ImpactModel model = row[2] == "ccm" ? ImpactModel::ccm : ImpactModel::rigid;
    CHECK(seen.insert({point, row[2]}).second);
    const ClosedForm expected = closed_form(point, model);
    for (int column : {7, 8, 9}) CHECK(cell_equals(row[std::size_t(column)], expected.error));
    CHECK(cell_equals(row[6], expected.wall));
    CHECK(cell_equals(row[10], expected.accuracy_per_second));
    const bool finest_ccm = model == ImpactModel::ccm && row[4] == "0.5";
    CHECK(row[3] == (finest_ccm ? "reference (finest CCM)" : "compared"));
  }
  CHECK(seen.size() == 2 * std::size_t(test::kConvergencePoints));
  // The first case's CCM runs, coarsest last after sorting by scale: 0.5, 1, 2.
  CHECK(rows[1][1] == "ER 100, RLS 1, KE 100 J");
  CHECK(rows[1][4] == "0.5");
}

TEST_CASE(
    "convergence figures: error against wall time and accuracy per second, one series "
    "per model and case",
    "[reports]") {
  test::TempDir dir;
  const ReportData data = synthetic_data(dir);
  const ReportContent content = plan_report(data, {}, current_stamp());
  const Figure& error = find_figure(content, "fig-convergence-error-vs-time");
  const Figure& accuracy = find_figure(content, "fig-convergence-accuracy-per-second");
  for (const Figure* f : {&error, &accuracy}) {
    INFO(f->id);
    REQUIRE(f->plot.series.size() == 4);  // 2 models x 2 cases
    for (const Series& s : f->plot.series) CHECK(s.x.size() == test::kConvergenceScales.size());
  }
  // Wall times span 0.027 s (rigid at RLS 0.5, scale 2) to 240 s (CCM at ER 1e4, scale 0.5).
  CHECK(error.plot.log_x);
  CHECK(error.plot.series[0].title == "CCM (meshed sphere, DCR), ER 100, RLS 1, KE 100 J");
  // Every point of the accuracy figure is (mesh scale, closed-form accuracy per second).
  for (const Series& s : accuracy.plot.series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const bool ccm = s.title.rfind("CCM", 0) == 0;
      const bool first_case = s.title.find("ER 100,") != std::string::npos;
      const auto& c = test::kConvergenceCases[first_case ? 0 : 1];
      const ImpactModel m = ccm ? ImpactModel::ccm : ImpactModel::rigid;
      const double err = test::synthetic_convergence_error(m, c.modulus_ratio, s.x[i]);
      const double wall = test::synthetic_wall_seconds(m, c.modulus_ratio, c.length_ratio, s.x[i]);
      INFO(s.title << " at scale " << s.x[i]);
      CHECK(s.y[i] == Approx((1.0 - err) / wall).epsilon(1e-12));
    }
}

}  // namespace
}  // namespace ccm::reports
