// The rules for every figure of the report (checked on the planned figures, before
// gnuplot): axes labelled with units, log axes where values span decades, legends that name the
// model and the case; and no figure without data, even for a study with few results.
#include <catch2/catch.hpp>
#include <cmath>

#include "db/store/study_store.hpp"
#include "reports/data/report_loader.hpp"
#include "reports/write/report_writer.hpp"
#include "tests/reports/synthetic_study.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm::reports {
namespace {

// "wall time [s]", "RLS [-]": a unit (or [-]) in brackets at the end.
bool has_unit(const std::string& label) {
  return label.size() > 3 && label.back() == ']' && label.find(" [") != std::string::npos;
}

bool names_model(const std::string& legend) {
  return legend.find("CCM") != std::string::npos || legend.find("rigid") != std::string::npos;
}

// The case: a KE level (with ER and RLS where the series is one point), or every case.
bool names_case(const std::string& legend) {
  return legend.find("KE ") != std::string::npos ||
         legend.find("every usable case") != std::string::npos;
}

void check_figure_rules(const ReportContent& content) {
  int figures = 0;
  for (const Section& section : content.sections)
    for (const Figure& f : section.figures) {
      ++figures;
      INFO("figure " << f.id);
      const PlotSpec& p = f.plot;
      CHECK(has_unit(p.x_label));
      CHECK(has_unit(p.y_label));
      if (p.three_d) CHECK(has_unit(p.z_label));
      CHECK_FALSE(all_values(p, 0).empty());  // gnuplot would refuse an empty figure
      const bool log_axis[] = {p.log_x, p.log_y, p.log_z};
      for (int axis = 0; axis < (p.three_d ? 3 : 2); ++axis) {
        INFO("axis " << axis);
        const auto values = all_values(p, axis);
        if (spans_decades(values)) CHECK(log_axis[axis]);
        if (log_axis[axis])
          for (double v : values) CHECK(v > 0.0);  // a log axis drops non-positive values
      }
      for (const Series& s : p.series) {
        if (s.empty()) continue;
        INFO("legend \"" << s.title << "\"");
        CHECK(names_model(s.title));
        CHECK(names_case(s.title));
      }
    }
  CHECK(figures > 0);
}

ReportData synthetic_data(const test::TempDir& dir) {
  test::write_synthetic_study(dir.path / "study.sqlite");
  db::StudyStore store(dir.path / "study.sqlite");
  REQUIRE(store.open_existing_study());
  return load_report_data(store);
}

TEST_CASE(
    "every figure: axes with units, log axes where values span decades, legends that "
    "name model and case",
    "[reports]") {
  test::TempDir dir;
  ReportData data = synthetic_data(dir);
  const ReportStamp stamp = current_stamp();

  SECTION("the whole synthetic study") { check_figure_rules(plan_report(data, {}, stamp)); }

  SECTION("only the convergence runs finished, no metrics or fits yet: no empty figure") {
    std::erase_if(data.runs, [](const auto& r) { return !is_convergence_point(r.point); });
    data.grid.clear();
    data.fits = {};
    const ReportContent content = plan_report(data, {}, stamp);
    check_figure_rules(content);
    int figures = 0;
    for (const Section& s : content.sections) figures += int(s.figures.size());
    CHECK(figures == 2);  // the two convergence figures
  }

  SECTION("only CCM runs finished: the per-point figures show them, no error figure") {
    std::erase_if(data.runs, [](const auto& r) { return r.model == study::ImpactModel::rigid; });
    data.grid.clear();
    data.fits = {};
    const ReportContent content = plan_report(data, {}, stamp);
    check_figure_rules(content);
    for (const Section& s : content.sections)
      for (const Figure& f : s.figures) {
        INFO(f.id);
        CHECK(f.id.find("fig-final") == std::string::npos);
      }
  }
}

}  // namespace
}  // namespace ccm::reports
