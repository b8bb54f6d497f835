// `ccm study run` on a tiny grid with a damping axis and a convergence point: the stored runtime
// ratio is the measured CPU-time ratio of the stored runs at every point, the thesis's estimate
// is stored beside it, and each distinct scene is simulated once and stored for every point that
// repeats it (run reuse).
#include <fmt/format.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "db/sqlite/statement.hpp"
#include "db/store/study_store.hpp"
#include "records/content_hash.hpp"
#include "run/scene/point_scene.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "tests/study/grid/grid_fixtures.hpp"
#include "tests/support/temp_dir.hpp"

using namespace ccm;
namespace fs = std::filesystem;

namespace {

// 2 ER x 2 damping = 4 points, and one convergence point at two mesh scales: 12 planned runs.
// The rigid model does not read ER, the ccm model does not read the damping, and the
// convergence point at scale 1 repeats grid point (ER 1, damping 1): 6 distinct scenes.
// Coarse meshes, 30 ms: each run well under a second.
const std::string kReuseGrid = R"(title = "cost"
[axes]
ER = [1.0, 100.0]
RLS = [0.5]
KE = [0.001]
damping = [0.5, 1.0]
[time]
contact_time = 0.02
end = 0.03
output_interval = 1e-3
)" + std::string(test::kTinyGridBodies) +
                               R"(damping = 1.0
[convergence]
points = [{ ER = 1.0, RLS = 0.5, KE = 0.001 }]
mesh_scales = [1.0, 0.8]
)";

constexpr double kEndTime = 0.03;

// One row of the runs table with the columns the checks need.
struct RunRow {
  long long id = 0;
  int point_index = 0;
  std::string model, status, scene_hash;
  long long steps = 0, steps_structure = 0, steps_contact = 0, steps_max_dt = 0, steps_landing = 0;
  double cpu = 0.0, air = 0.0, ists = 0.0, dt_first = 0.0, dt_mean = 0.0, dt_min = 0.0,
         dt_max = 0.0;
  std::optional<long long> reuses;
};

std::vector<RunRow> stored_runs(db::Connection& c) {
  db::Statement q(c, R"sql(
    SELECT r.id, gp.point_index, r.model, r.status, r.scene_hash, r.steps, r.steps_structure,
           r.steps_contact, r.steps_max_dt, r.steps_landing, r.step_cpu_seconds,
           r.average_iteration_seconds, r.initial_stable_dt, r.dt_first, r.dt_mean, r.dt_min,
           r.dt_max, r.reuses_run_id
    FROM runs r JOIN grid_points gp ON gp.id = r.grid_point_id ORDER BY r.id)sql");
  std::vector<RunRow> out;
  while (q.step()) {
    RunRow r;
    r.id = q.column_int(0);
    r.point_index = static_cast<int>(q.column_int(1));
    r.model = q.column_text(2);
    r.status = q.column_text(3);
    r.scene_hash = q.column_text(4);
    r.steps = q.column_int(5);
    r.steps_structure = q.column_int(6);
    r.steps_contact = q.column_int(7);
    r.steps_max_dt = q.column_int(8);
    r.steps_landing = q.column_int(9);
    r.cpu = q.column_double(10);
    r.air = q.column_double(11);
    r.ists = q.column_double(12);
    r.dt_first = q.column_double(13);
    r.dt_mean = q.column_double(14);
    r.dt_min = q.column_double(15);
    r.dt_max = q.column_double(16);
    if (!q.is_null(17)) r.reuses = q.column_int(17);
    out.push_back(r);
  }
  return out;
}

const RunRow& row_of(const std::vector<RunRow>& rows, int point_index, const std::string& model) {
  for (const RunRow& r : rows)
    if (r.point_index == point_index && r.model == model) return r;
  FAIL("no " << model << " run of point " << point_index);
  return rows.front();
}

}  // namespace

TEST_CASE(
    "ccm study run: RTR is the measured CPU-time ratio at every point, the thesis "
    "estimate beside it, each distinct scene runs once",
    "[study][cli][cost]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("cost.toml", kReuseGrid), db = tmp.path / "s.sqlite";
  const std::string command = fmt::format("'{}' study run '{}' --db '{}' --quiet > /dev/null",
                                          CCM_BINARY, grid.string(), db.string());
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);

  const study::GridSpec spec = study::parse_grid_file(grid);
  std::vector<study::GridPoint> points = study::expand_grid(spec);
  for (const auto& p : study::expand_convergence(spec)) points.push_back(p);
  REQUIRE(points.size() == 6);

  db::StudyStore store(db);
  REQUIRE(store.open_existing_study());
  const std::vector<RunRow> rows = stored_runs(store.connection());
  REQUIRE(rows.size() == 12);  // every point has both runs

  {  // every run: its cost is measured and its limiter counts add up
    for (const RunRow& r : rows) {
      INFO("point " << r.point_index << " " << r.model);
      CHECK(r.status == "completed");
      CHECK(r.cpu > 0.0);
      CHECK(r.steps_structure + r.steps_contact + r.steps_max_dt + r.steps_landing == r.steps);
      CHECK(r.dt_first >= r.dt_min);
      CHECK(r.dt_first <= r.dt_max);
      // steps x mean step = t_f (1e-12: the mean is one division of the time reached)
      CHECK(static_cast<double>(r.steps) * r.dt_mean == Approx(kEndTime).epsilon(1e-12));
      // AIR = stepping CPU seconds / steps (eq. 2.41 with the measured time)
      CHECK(r.air * static_cast<double>(r.steps) == Approx(r.cpu).epsilon(1e-12));
    }
  }

  {  // every point: RTR = TR_ccm / TR_rigid measured; the thesis estimate beside it
    const auto metrics = store.load_metrics();
    REQUIRE(metrics.size() == points.size());
    db::Statement q(store.connection(), R"sql(
      SELECT gp.point_index, m.rtr, m.rtr_thesis_estimate, m.tr_ccm, m.tr_rigid,
             m.tr_ccm_thesis_estimate, m.tr_rigid_thesis_estimate, m.t_final, m.final_u_max,
             m.w_u_max
      FROM metrics m JOIN grid_points gp ON gp.id = m.grid_point_id ORDER BY gp.point_index)sql");
    int n = 0;
    while (q.step()) {
      ++n;
      const int index = static_cast<int>(q.column_int(0));
      INFO("point " << index);
      REQUIRE_FALSE(q.is_null(1));
      REQUIRE_FALSE(q.is_null(2));
      const RunRow& c = row_of(rows, index, "ccm");
      const RunRow& r = row_of(rows, index, "rigid");
      // Rounding: one division each side (1e-12).
      CHECK(q.column_double(1) == Approx(c.cpu / r.cpu).epsilon(1e-12));
      CHECK(q.column_double(3) == Approx(c.cpu).epsilon(1e-12));
      CHECK(q.column_double(4) == Approx(r.cpu).epsilon(1e-12));
      // Thesis: NT = AIR / ISTS (2.41-2.42), TR = t_f NT (2.43), RTR = NT_ccm / NT_rigid (2.40)
      const double t_f = q.column_double(7);
      CHECK(t_f == Approx(kEndTime).epsilon(1e-12));
      CHECK(q.column_double(2) == Approx((c.air / c.ists) / (r.air / r.ists)).epsilon(1e-12));
      CHECK(q.column_double(5) == Approx(t_f * c.air / c.ists).epsilon(1e-12));
      CHECK(q.column_double(6) == Approx(t_f * r.air / r.ists).epsilon(1e-12));
      // w = final-state error / measured RTR
      CHECK(q.column_double(9) == Approx(q.column_double(8) / q.column_double(1)).epsilon(1e-12));
    }
    CHECK(n == 6);
  }

  {  // each distinct scene was simulated once and stored for every point that repeats it
    std::map<long long, const RunRow*> by_id;
    for (const RunRow& r : rows) by_id[r.id] = &r;
    std::set<std::pair<std::string, std::string>> simulated, distinct;
    for (const RunRow& r : rows) {
      distinct.insert({r.model, r.scene_hash});
      if (!r.reuses) {
        CHECK(simulated.insert({r.model, r.scene_hash}).second);  // never twice
        continue;
      }
      REQUIRE(by_id.count(*r.reuses) == 1);
      const RunRow& source = *by_id[*r.reuses];
      INFO("point " << r.point_index << " " << r.model << " reuses point " << source.point_index);
      CHECK_FALSE(source.reuses);  // the simulated run itself
      CHECK(source.model == r.model);
      CHECK(source.scene_hash == r.scene_hash);
      CHECK(source.steps == r.steps);
      CHECK(source.cpu == r.cpu);
    }
    CHECK(distinct.size() == 6);
    CHECK(simulated == distinct);
    // The scene texts behind the hashes: the same model and hash means the same text, and the
    // rigid runs differ by damping only, the ccm runs by ER only (and the 0.8 mesh scale).
    for (const RunRow& r : rows) {
      const study::GridPoint& p = points.at(static_cast<std::size_t>(r.point_index));
      const auto model = r.model == "ccm" ? study::ImpactModel::ccm : study::ImpactModel::rigid;
      CHECK(study::fnv1a64(study::point_scene_text(spec, p, model)) == r.scene_hash);
    }
    // The histories of a reused run are the simulated run's, bit for bit.
    for (const RunRow& r : rows) {
      if (!r.reuses) continue;
      const RunRow& source = *by_id[*r.reuses];
      const auto model = r.model == "ccm" ? study::ImpactModel::ccm : study::ImpactModel::rigid;
      const auto a = store.load_run(points.at(static_cast<std::size_t>(r.point_index)), model);
      const auto b = store.load_run(points.at(static_cast<std::size_t>(source.point_index)), model);
      REQUIRE(a);
      REQUIRE(b);
      CHECK(a->reuses_point == source.point_index);
      CHECK(a->artifact.u_max == b->artifact.u_max);
      CHECK(a->artifact.kinetic_energy == b->artifact.kinetic_energy);
    }
  }
}
