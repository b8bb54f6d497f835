// The report's benchtop rig section: a store with a study and one synthetic rig run (and a
// calibration) gets the rig's channel figures (files, referenced from index.html, legends and
// axes), its metrics CSV holds the stored numbers; a store without a rig run says so.
#include <catch2/catch.hpp>

#include "app/study_commands.hpp"
#include "db/store/rig_reader.hpp"
#include "db/store/study_store.hpp"
#include "reports/data/report_loader.hpp"
#include "reports/figures/rig_section.hpp"
#include "reports/write/report_writer.hpp"
#include "tests/reports/csv_reader.hpp"
#include "tests/reports/synthetic_rig.hpp"
#include "tests/reports/synthetic_study.hpp"
#include "tests/reports/text_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm::reports {
namespace {

namespace fs = std::filesystem;

const char* const kRigFigures[] = {"fig-rig-rx025-open-loop-velocity",
                                   "fig-rig-rx025-open-loop-angle",
                                   "fig-rig-rx025-open-loop-pressure"};

ReportData load(const fs::path& file) {
  db::StudyStore store(file);
  REQUIRE(store.open_existing_study());
  return load_report_data(store);
}

const Section& rig_of(const ReportContent& content) {
  for (const Section& s : content.sections)
    if (s.id == "rig") return s;
  FAIL("no rig section");
  return content.sections.front();
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST_CASE("report: a store without a rig run says so in the rig section", "[reports]") {
  test::TempDir dir;
  test::write_synthetic_study(dir.path / "study.sqlite");
  const ReportData data = load(dir.path / "study.sqlite");
  CHECK(data.rig.empty());
  const ReportContent content = plan_report(data, {}, current_stamp());
  const Section& rig = rig_of(content);
  REQUIRE(rig.paragraphs.size() == 1);
  CHECK(rig.paragraphs[0] ==
        "No benchtop rig run is stored in this database; run `ccm rig run CASE --data DIR --db "
        "FILE` to add one.");
  CHECK(rig.figures.empty());
  CHECK(rig.tables.empty());
}

TEST_CASE("report: the rig section's planned figures draw the stored run and trials", "[reports]") {
  test::TempDir dir;
  const fs::path file = dir.path / "study.sqlite";
  test::write_synthetic_study(file);
  const long long id = test::write_synthetic_rig(file);
  const ReportData data = load(file);
  REQUIRE(data.rig.runs.size() == 1);  // the calibration's runs are not shown as runs
  CHECK(data.rig.runs[0].id == id);
  REQUIRE(data.rig.calibrations.size() == 1);
  const ReportContent content = plan_report(data, {}, current_stamp());
  const Section& rig = rig_of(content);
  REQUIRE(rig.figures.size() == 3);
  const db::RigRunRecord expected = test::synthetic_rig_record();
  for (size_t i = 0; i < 3; ++i) {
    const Figure& f = rig.figures[i];
    INFO(f.id);
    CHECK(f.id == kRigFigures[i]);
    CHECK(f.plot.x_label == "trial time [s]");
    CHECK(f.plot.y_label.back() == ']');
    CHECK_FALSE(f.plot.log_x);
    CHECK_FALSE(f.plot.log_y);
    int bands = 0, trials = 0, simulated = 0, marks = 0;
    for (const Series& s : f.plot.series) {
      if (s.empty()) continue;
      INFO(s.title);
      CHECK(contains(s.title, "RX025"));
      bands += s.style == SeriesStyle::band;
      trials += s.style == SeriesStyle::thin_lines;
      marks += s.style == SeriesStyle::marks;
      if (s.style == SeriesStyle::lines) {
        ++simulated;
        CHECK(contains(s.title, "ccm rig model, open-loop drive"));
        CHECK(s.x.size() == 21);
      }
    }
    CHECK(bands == 1);
    CHECK(trials == 3);
    CHECK(simulated == 1);
    CHECK(marks == 2);  // measured and simulated contact
  }
  // The pressure band is mean +/- sd of 10, 11, 9 kPa during contact: 10 +/- 1.
  const Series& band = rig.figures[2].plot.series[0];
  REQUIRE(band.style == SeriesStyle::band);
  CHECK(band.y[7] == Approx(9.0));
  CHECK(band.z[7] == Approx(11.0));
  // The simulation's pressure as stored.
  for (const Series& s : rig.figures[2].plot.series)
    if (s.style == SeriesStyle::lines) CHECK(s.y == expected.channels.pressure_kpa.value);
}

TEST_CASE("report: ccm report writes the rig figures and tables with the stored numbers",
          "[reports]") {
  test::TempDir dir;
  const fs::path file = dir.path / "study.sqlite";
  test::write_synthetic_study(file);
  const long long id = test::write_synthetic_rig(file);
  const fs::path out = dir.path / "report";
  REQUIRE(report_command({file, out, 0.1}) == 0);
  const std::string html = test::read_text(out / "index.html");
  for (const char* f : kRigFigures) {
    INFO(f);
    CHECK(fs::file_size(out / (std::string(f) + ".svg")) > 1000);
    CHECK(contains(html, std::string("<figure id=\"") + f + "\">"));
  }
  CHECK_FALSE(contains(html, "No benchtop rig run"));
  CHECK_FALSE(contains(html, "have not landed"));

  db::Connection c(file);
  const db::StoredRigRun stored = db::load_rig_run(c, id);
  REQUIRE(stored.record.comparison);
  const rig::CaseComparison& k = *stored.record.comparison;
  const test::CsvRows metrics = test::read_csv(out / "rig-metrics.csv");
  REQUIRE(metrics.size() == 4);
  CHECK(metrics[0][0] == "case");
  const rig::ChannelAgainstTrials* channels[] = {&k.velocity, &k.angle, &k.pressure};
  const char* names[] = {"V_i", "theta_a", "P"};
  for (size_t i = 0; i < 3; ++i) {
    const auto& row = metrics[i + 1];
    INFO(names[i]);
    REQUIRE(row.size() == 10);
    CHECK(row[0] == "RX025 (open-loop drive)");
    CHECK(row[1] == names[i]);
    CHECK(row[3] == "3");
    CHECK(row[4] == cell(channels[i]->rmse.mean));
    CHECK(row[6] == cell(channels[i]->peak_error.mean));
    CHECK(row[7] == cell(channels[i]->peak_time_error.mean));
  }
  // The simulated pressure is trial 1's times 1.5 through the sensor's low-pass: peak 15 kPa
  // (14.999) against 10, 11, 9.
  CHECK(metrics[3][6] == cell(k.pressure.peak_error.mean));
  CHECK(k.pressure.peak_error.mean == Approx(5.0).epsilon(1e-3));
  REQUIRE(k.onset_error);
  CHECK(metrics[3][8] == cell(k.onset_error->mean));
  CHECK(metrics[3][9] == cell(k.duration_error->mean));

  const test::CsvRows runs = test::read_csv(out / "rig-runs.csv");
  REQUIRE(runs.size() == 2);
  CHECK(runs[1][0] == std::to_string(id));
  CHECK(runs[1][3] == "3121");
  CHECK(runs[1][4] == "1000");
  CHECK(runs[1][5] == cell(4e-7));
  CHECK(runs[1][8] == cell(0.012));
  CHECK(runs[1][9] == "completed");

  const test::CsvRows calibrations = test::read_csv(out / "rig-calibrations.csv");
  REQUIRE(calibrations.size() == 2);
  CHECK(calibrations[1][2] == "pin_damping");
  CHECK(calibrations[1][5] == cell(0.5));
  CHECK(calibrations[1][6] == cell(1.25));
  CHECK(calibrations[1][7] == cell(0.25));  // the spread's half-width
  CHECK(calibrations[1][9] == cell(0.4));
  CHECK(calibrations[1][10] == cell(0.25));
  const test::CsvRows left_out = test::read_csv(out / "rig-left-out.csv");
  REQUIRE(left_out.size() == 3);
  CHECK(left_out[1][0] == "RX025 (open-loop drive)");
  CHECK(left_out[1][1] == "pin_damping");
  CHECK(left_out[1][2] == "RX050");
  CHECK(left_out[1][3] == cell(0.5));
  CHECK(left_out[1][4] == cell(0.3));
  // The fitted case's trial 3, left out of the fit (--fit-trials 1); trial 1 was fitted.
  CHECK(left_out[2][2] == "RX025 trial 3");
  CHECK(left_out[2][3] == cell(0.45));
  CHECK(left_out[2][4] == cell(0.35));
}

}  // namespace
}  // namespace ccm::reports
