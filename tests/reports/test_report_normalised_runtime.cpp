// Normalised runtime surfaces (thesis Fig. 2-28): `ccm study run` stores fits of log10 NT per
// model and KE; on the synthetic study (NT_ccm = 2 sqrt(ER), NT_rigid = 2^RLS) they recover the
// closed forms, and the figure draws each model's surface with its data, equations and R^2 in
// the caption.
#include <catch2/catch.hpp>
#include <cmath>

#include "db/store/study_store.hpp"
#include "reports/data/report_loader.hpp"
#include "reports/write/report_writer.hpp"
#include "tests/reports/synthetic_study.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm::reports {
namespace {

using study::ImpactModel;
using study::Metric;

const Figure* find_figure(const ReportContent& content, const std::string& id) {
  for (const Section& s : content.sections)
    for (const Figure& f : s.figures)
      if (f.id == id) return &f;
  return nullptr;
}

TEST_CASE("NT surfaces: the stored log10 NT fits recover the synthetic closed forms", "[reports]") {
  test::TempDir dir;
  test::write_synthetic_study(dir.path / "study.sqlite");
  db::StudyStore store(dir.path / "study.sqlite");
  REQUIRE(store.open_existing_study());
  const ReportData data = load_report_data(store);
  const double log2 = std::log10(2.0);
  for (double ke : {10.0, 100.0}) {
    INFO("KE " << ke << " J");
    const study::MetricFit* ccm = data.fits.find(Metric::log10_nt_ccm, ke);
    const study::MetricFit* rigid = data.fits.find(Metric::log10_nt_rigid, ke);
    REQUIRE(ccm);
    REQUIRE(rigid);
    // 12 points per KE; at 10 J the unstable point is left out.
    CHECK(ccm->fit.samples.size() == (ke == 10.0 ? 11u : 12u));
    // Planes in log10: degree chosen by leave-one-out error, fewest terms among exact fits.
    CHECK(ccm->fit.surface.degree == study::SurfaceDegree{1, 0});
    CHECK(rigid->fit.surface.degree == study::SurfaceDegree{0, 1});
    CHECK(ccm->fit.r_squared == Approx(1.0).margin(1e-12));
    CHECK(rigid->fit.r_squared == Approx(1.0).margin(1e-12));
    // Everywhere over the studied range, not only at the samples (rounding only: 1e-10).
    for (double x = 0.0; x <= 6.0; x += 0.5)
      for (double y = 0.5; y <= 1.5; y += 0.25) {
        CHECK(ccm->fit.surface(x, y) == Approx(log2 + 0.5 * x).margin(1e-10));
        CHECK(rigid->fit.surface(x, y) == Approx(y * log2).margin(1e-10));
      }
    for (const auto& s : ccm->fit.samples)
      CHECK(std::pow(10.0, s.z) ==
            Approx(test::synthetic_normalised_runtime(ImpactModel::ccm, std::pow(10.0, s.x), s.y))
                .epsilon(1e-12));
  }
}

TEST_CASE(
    "NT figure (Fig. 2-28): both models' fitted surfaces and data, equations and R^2 in "
    "the caption",
    "[reports]") {
  test::TempDir dir;
  test::write_synthetic_study(dir.path / "study.sqlite");
  db::StudyStore store(dir.path / "study.sqlite");
  REQUIRE(store.open_existing_study());
  const ReportData data = load_report_data(store);
  const ReportContent content = plan_report(data, {}, current_stamp());
  const Figure* f = find_figure(content, "fig-normalised-runtime-ke-100");
  REQUIRE(f);
  const PlotSpec& plot = f->plot;
  REQUIRE(plot.series.size() == 4);  // per model: fitted surface, data
  CHECK(plot.series[0].style == SeriesStyle::surface);
  CHECK(plot.series[0].title == "CCM (meshed sphere, DCR), KE 100 J: fitted surface");
  CHECK(plot.series[1].title == "CCM (meshed sphere, DCR), KE 100 J: data");
  CHECK(plot.series[2].style == SeriesStyle::surface);
  CHECK(plot.series[3].title == "rigid (analytic sphere, penalty), KE 100 J: data");
  // The surface is drawn as NT = 10^(fitted log10 NT): on the mesh, 2 sqrt(ER) and 2^RLS.
  for (std::size_t m : {0u, 2u})
    for (std::size_t i = 0; i < plot.series[m].x.size(); ++i) {
      const double x = plot.series[m].x[i], y = plot.series[m].y[i];
      const double nt = m == 0 ? 2.0 * std::pow(10.0, x / 2) : std::pow(2.0, y);
      CHECK(plot.series[m].z[i] == Approx(nt).epsilon(1e-9));
    }
  CHECK(plot.series[0].x.size() == 21u * 21u);
  CHECK(plot.series[1].z.size() == 12u);
  CHECK(plot.log_z);  // NT from 1.41 (rigid) to 2000 (CCM at ER 1e6)
  CHECK_THAT(f->caption, Catch::Contains("log10 NT_CCM = 0.301 + 0.5 x"));
  CHECK_THAT(f->caption, Catch::Contains("log10 NT_rigid = 0.301 y"));
  CHECK_THAT(f->caption, Catch::Contains("R^2 = 1.0000"));
  CHECK_THAT(f->caption, Catch::Contains("Fig. 2-28"));
}

TEST_CASE("NT figure of a store without NT fits: the data points, and the caption says why",
          "[reports]") {
  test::TempDir dir;
  test::write_synthetic_study(dir.path / "study.sqlite");
  db::StudyStore store(dir.path / "study.sqlite");
  REQUIRE(store.open_existing_study());
  ReportData data = load_report_data(store);
  std::erase_if(data.fits.fits, [](const study::MetricFit& f) {
    return f.metric == Metric::log10_nt_ccm || f.metric == Metric::log10_nt_rigid;
  });
  const ReportContent content = plan_report(data, {}, current_stamp());
  const Figure* f = find_figure(content, "fig-normalised-runtime-ke-10");
  REQUIRE(f);
  REQUIRE(f->plot.series.size() == 2);  // the data of both models
  CHECK(f->plot.series[0].title == "CCM (meshed sphere, DCR), KE 10 J: data");
  CHECK(f->plot.series[0].z.size() == 11u);  // 12 points at 10 J, the unstable one left out
  CHECK_THAT(f->caption, Catch::Contains("no fitted surface stored"));
}

}  // namespace
}  // namespace ccm::reports
