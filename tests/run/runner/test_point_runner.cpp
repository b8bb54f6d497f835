// The point runner: one small point, both models, consistent RunRecords on the same sample times.
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "records/content_hash.hpp"
#include "run/runner/point_runner.hpp"
#include "run/scene/point_scene.hpp"
#include "study/grid/grid_file.hpp"
#include "tests/support/tolerance.hpp"

using ccm::test::relative_error;
using namespace ccm;
using namespace ccm::study;

namespace {

// A coarse point (a few hundred tets), contact from t_c = 5 ms to t_f = 20 ms.
constexpr std::string_view kTinyGrid = R"([axes]
ER = [1.0]
RLS = [0.5]
KE = [10.0]

[time]
contact_time = 0.005
end = 0.02
output_interval = 1e-3

[artifact]
length = 1.0
thickness = 0.25
E = 1000.0
nu = 0.49
rho = 1000.0
mesh_size = 0.25

[impactor]
nu = 0.49
rho = 1000.0
mesh_size_ratio = 0.4
)";

GridPoint tiny_point() {
  GridPoint p;
  p.index = 3;
  p.modulus_ratio = 1.0;
  p.length_ratio = 0.5;
  p.kinetic_energy = 10.0;
  return p;
}

void check_record(const RunRecord& r, const GridSpec& g, ImpactModel model) {
  INFO(to_string(model));
  CHECK(r.model == model);
  CHECK(r.point.index == 3);
  REQUIRE(r.completed());
  CHECK(r.reason.empty());
  CHECK(r.steps > 0);
  CHECK(r.initial_stable_dt > 0.0);
  CHECK(r.dt_min <= r.dt_max);
  CHECK(r.dt_min > 0.0);
  CHECK(r.average_iteration_seconds > 0.0);
  CHECK(r.max_energy_error < 0.05);  // the monitor's default tolerance
  CHECK(r.scene_hash == fnv1a64(point_scene_text(g, r.point, model)));
  CHECK(r.started_at <= r.ended_at);  // RFC 3339 UTC strings sort by time
  CHECK(r.started_at.size() == 24);
  const ArtifactHistory& h = r.artifact;
  REQUIRE(h.time.size() == 21);  // t = 0, 1 ms, ..., 20 ms
  CHECK(h.u_mean.size() == h.time.size());
  CHECK(h.u_max.size() == h.time.size());
  CHECK(h.kinetic_energy.size() == h.time.size());
  for (size_t i = 0; i < h.time.size(); ++i) {
    INFO("sample " << i << " at t = " << h.time[i]);
    CHECK(std::abs(h.time[i] - 1e-3 * static_cast<double>(i)) < 1e-15);
    CHECK(h.u_max[i] >= h.u_mean[i]);
    // Before first touch at t_c = 5 ms nothing acts on the artifact: at rest up to the
    // round-off of the internal forces at F = I (measured ~1e-28 J; 1e-12 KE_I = 1e-11 J).
    // DCR's persistent contacts hold a pair whose gap the next step would close, so contact may
    // begin one step early: the check stops one largest step before t_c.
    if (h.time[i] < 0.005 - r.dt_max - 1e-9) CHECK(h.kinetic_energy[i] < 1e-11);
  }
  CHECK(h.kinetic_energy.back() > 0.0);
  CHECK(h.kinetic_energy.back() < 10.0);  // less than the impactor brought
  // In the 15 ms after t_c the sphere travels at most d = v t = 0.5529 x 0.015 = 8.29 mm: no
  // point of the artifact can be pushed much farther (1.5 d allows the incompressible plate to
  // bulge beside the sphere).
  CHECK(h.u_max.back() > 0.0);
  CHECK(h.u_max.back() < 1.5 * 8.29e-3);
}

}  // namespace

TEST_CASE("both models of a small point run on the same artifact and sample times", "[runner]") {
  const GridSpec g = parse_grid(kTinyGrid, "tiny.toml");
  const GridPoint p = tiny_point();
  int calls = 0;
  PointRunOptions options;
  options.progress_seconds = 0.0;  // every step
  options.progress = [&](const GridPoint& at, ImpactModel, const Progress& pr) {
    CHECK(at.index == 3);
    CHECK(pr.end_time == 0.02);
    ++calls;
  };
  const RunRecord ccm_run = run_point(g, p, ImpactModel::ccm, options);
  CHECK(calls > 0);
  const RunRecord rigid = run_point(g, p, ImpactModel::rigid);
  check_record(ccm_run, g, ImpactModel::ccm);
  check_record(rigid, g, ImpactModel::rigid);
  CHECK(ccm_run.artifact.time == rigid.artifact.time);
  // The 65 kg rigid sphere is hardly slowed by the 1 kPa plate: the plate's surface follows it
  // for most of d = 8.29 mm (measured 5.8 mm: the penalty lets it sink a little, and the
  // plate's coarse surface triangles meet it late).
  CHECK(rigid.artifact.u_max.back() > 0.3 * 8.29e-3);
  CHECK(ccm_run.n_elements > rigid.n_elements);  // the meshed sphere
  CHECK(ccm_run.n_nodes > rigid.n_nodes);
  CHECK(ccm_run.scene_hash != rigid.scene_hash);
  // The ccm model adds a body to the same artifact (and the rigid sphere starts out of reach):
  // its initial stable step cannot be longer.
  CHECK(ccm_run.initial_stable_dt <= rigid.initial_stable_dt);
}

TEST_CASE("a point whose mesh Gmsh rejects is a scene error naming the point's scene", "[runner]") {
  const GridSpec g = parse_grid(kTinyGrid, "tiny.toml");
  GridPoint p = tiny_point();
  p.other_axes["mesh_scale"] = 2.0;  // impactor tet edge 0.4 > radius 0.25
  CHECK_THROWS_WITH(run_point(g, p, ImpactModel::ccm),
                    Catch::Contains("tiny.point3.ccm.toml") && Catch::Contains("impactor"));
}

TEST_CASE("a point's scene text runs unchanged with `ccm run`, which reports the same hash",
          "[runner]") {
  namespace fs = std::filesystem;
  const GridSpec g = parse_grid(kTinyGrid, "tiny.toml");
  const std::string text = point_scene_text(g, tiny_point(), ImpactModel::rigid);
  const fs::path dir = fs::temp_directory_path() / fmt::format("ccm-test-point-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "point.toml") << text;
  const std::string cmd = fmt::format("\"{}\" run \"{}\" --out \"{}\" --quiet", CCM_BINARY,
                                      (dir / "point.toml").string(), (dir / "out").string());
  const int status = std::system(cmd.c_str());
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  std::ifstream summary(dir / "out" / "summary.toml");
  std::stringstream content;
  content << summary.rdbuf();
  CHECK_THAT(content.str(), Catch::Contains(fmt::format("scene_fnv1a64 = \"{}\"", fnv1a64(text))));
  fs::remove_all(dir);
}
