// Where a study's answer changes (study/refine/boundary_refinement.hpp), on decisions made up
// here: lines, boundaries and their widths, the order of the splits, and the refinement loop
// against a known boundary: it locates it to one fine step with fewer runs than the fine grid.
#include <catch2/catch.hpp>
#include <cmath>
#include <deque>

#include "study/refine/boundary_refinement.hpp"

using namespace ccm::study;

namespace {

struct Decisions {
  std::deque<PointMetrics> metrics;  // stable addresses
  std::vector<PointDecision> decisions;

  void add(double er, double rls, ImpactModel answer, bool flagged = false) {
    PointMetrics& m = metrics.emplace_back();
    m.point.index = static_cast<int>(metrics.size()) - 1;
    m.point.modulus_ratio = er;
    m.point.length_ratio = rls;
    m.point.kinetic_energy = 10.0;
    PointDecision d;
    d.point = &m;
    d.measured.model = answer;
    d.measured.rigid_within_error = answer == ImpactModel::rigid;  // an error boundary
    d.measured.rigid_cheaper = true;
    if (flagged) {
      d.fitted = Recommendation{};
      d.fitted->reliability.reliable = false;
    }
    decisions.push_back(d);
  }
};

constexpr auto kCcm = ImpactModel::ccm;
constexpr auto kRigid = ImpactModel::rigid;

}  // namespace

TEST_CASE("refine plan: each line's boundary, its width in decades, widest split first",
          "[refine]") {
  Decisions d;
  for (double er : {1.0, 1e2, 1e4, 1e6}) d.add(er, 0.5, er >= 1e4 ? kRigid : kCcm);
  for (double er : {1e6, 1.0, 1e2}) d.add(er, 1.5, er >= 1e6 ? kRigid : kCcm);  // any order
  const RefinePlan plan = plan_refinement(d.decisions, "ER", 0.25);
  REQUIRE(plan.boundaries.size() == 2);
  const RefineInterval& a = plan.boundaries[0];  // lines in name order: RLS 0.5 first
  CHECK(a.line == "RLS 0.5, KE 10");
  CHECK(a.lo_x == 1e2);
  CHECK(a.hi_x == 1e4);
  CHECK(a.lo_answer == kCcm);
  CHECK(a.hi_answer == kRigid);
  CHECK(a.width == Approx(2.0));
  CHECK(a.middle() == Approx(1e3));
  CHECK(plan.boundaries[1].width == Approx(4.0));
  REQUIRE(plan.to_split.size() == 2);
  CHECK(plan.to_split[0].line == "RLS 1.5, KE 10");  // the wider boundary first
  CHECK(boundary_text(a, "ER", 0.25) ==
        "RLS 0.5, KE 10: ccm at ER 100, rigid at ER 10000 (2 decades; tolerance 0.25: not "
        "resolved; the errors change)");
  CHECK(a.errors_change);
  CHECK_FALSE(a.cost_changes);
}

TEST_CASE("refine plan: a resolved boundary is not split, a flagged neighbour is once all are",
          "[refine]") {
  Decisions d;
  d.add(1.0, 0.5, kCcm, true);
  d.add(1e2, 0.5, kCcm);
  d.add(1e2 * std::pow(10.0, 0.2), 0.5, kRigid);
  const RefinePlan plan = plan_refinement(d.decisions, "ER", 0.25);
  REQUIRE(plan.boundaries.size() == 1);
  CHECK(plan.boundaries[0].width == Approx(0.2));
  REQUIRE(plan.to_split.size() == 1);  // only the uncertain interval [1, 100]
  CHECK_FALSE(plan.to_split[0].boundary);
  CHECK(plan.to_split[0].uncertain);
  CHECK(plan.to_split[0].hi_x == 1e2);
}

TEST_CASE("refine plan: an axis that changes sign is split arithmetically", "[refine]") {
  Decisions d;
  d.add(-1.0, 0.5, kCcm);
  d.add(3.0, 0.5, kRigid);
  const RefinePlan plan = plan_refinement(d.decisions, "ER", 0.5);
  REQUIRE(plan.to_split.size() == 1);
  CHECK_FALSE(plan.to_split[0].geometric);
  CHECK(plan.to_split[0].width == 4.0);
  CHECK(plan.to_split[0].middle() == 1.0);
}

// The answer is rigid from ER* on. The fine grid: every 1/8 decade from ER 1 to 1e6 (49 points);
// the coarse grid: every 2 decades (4 points). Refining the coarse grid to a tolerance of one
// fine step locates ER* within one fine step with a fraction of the fine grid's points.
TEST_CASE("refine loop: the boundary located to one fine step with under half the fine grid",
          "[refine]") {
  for (const double boundary_decade : {0.3, 2.55, 4.9, 5.95}) {
    const double er_star = std::pow(10.0, boundary_decade);
    const auto answer = [&](double er) { return er >= er_star ? kRigid : kCcm; };
    Decisions d;
    for (double er : {1.0, 1e2, 1e4, 1e6}) d.add(er, 0.5, answer(er));
    const double fine_step = 0.125;
    for (int round = 0; round < 50; ++round) {
      const RefinePlan plan = plan_refinement(d.decisions, "ER", fine_step);
      if (plan.to_split.empty()) break;
      for (const RefineInterval& i : plan.to_split) d.add(i.middle(), 0.5, answer(i.middle()));
    }
    const RefinePlan done = plan_refinement(d.decisions, "ER", fine_step);
    REQUIRE(done.boundaries.size() == 1);
    const RefineInterval& b = done.boundaries[0];
    CHECK(b.lo_x < er_star);
    CHECK(b.hi_x >= er_star);
    CHECK(std::abs(std::log10(b.middle() / er_star)) <= fine_step);
    CHECK(d.metrics.size() <= 49 / 2);
  }
}
