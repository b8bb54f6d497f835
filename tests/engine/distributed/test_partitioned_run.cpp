// `mpiexec -n 2 ccm run SCENE` against the serial `ccm run SCENE` on the two contact scenes of
// scenes/examples, shortened to just past the first contact (docs/parallel.md "Distributed
// memory"). The partitioned run differs from the serial one only in the order of the floating-
// point additions at the nodes its two subdomains share; over ~150 steps that round-off stays
// within 1.1e-13 of the energies and the displacements (measured), so 1e-12 and 1e-10 of each
// column's largest magnitude leave margins of about 10 and 1000.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>

#include "tests/support/temp_dir.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

std::string file_text(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

// The start of an mpiexec command line, bounded in time (a hang ends as exit 124). The project's
// set-up installs mpiexec (scripts/install-deps.sh): its absence is a failure. Open MPI's own
// allocations are not ours to leak-check under the sanitizer build.
std::string mpiexec() {
  REQUIRE(shell("command -v mpiexec > /dev/null 2>&1") == 0);
  return "ASAN_OPTIONS=detect_leaks=0 timeout 600 mpiexec --allow-run-as-root --oversubscribe";
}

struct History {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

History read_history(const fs::path& file) {
  std::ifstream in(file);
  REQUIRE(in.good());
  History h;
  std::string line, cell;
  std::getline(in, line);
  std::istringstream header(line);
  while (std::getline(header, cell, ',')) h.columns.push_back(cell);
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::vector<double>& r = h.rows.emplace_back();
    while (std::getline(row, cell, ',')) r.push_back(std::stod(cell));
    REQUIRE(r.size() == h.columns.size());
  }
  return h;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The example scene with its end time and output interval replaced (and its restitution, if
// restitution is not empty).
fs::path short_scene(const test::TempDir& tmp, const std::string& example, double end,
                     double interval, const std::string& restitution,
                     const std::function<std::string(std::string)>& edit = {}) {
  std::istringstream in(file_text(fs::path(CCM_SOURCE_DIR) / "scenes/examples" / example));
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.rfind("end = ", 0) == 0) line = "end = " + std::to_string(end);
    if (line.rfind("output_interval = ", 0) == 0)
      line = "output_interval = " + std::to_string(interval);
    if (!restitution.empty() && line.rfind("restitution = ", 0) == 0)
      line = "restitution = " + restitution;
    text += line + "\n";
  }
  return tmp.write(example, edit ? edit(text) : text);
}

// The DCR example cut to 0.3 ms (past the first contact), in tmp.
fs::path short_dcr_scene(const test::TempDir& tmp) {
  return short_scene(tmp, "ball_on_plate_dcr.toml", 3e-4, 5e-5, "");
}

// What a comparison varies: the scene's edits, the ranks, the column that shows the contact acted
// (a pair's work, or the analytic sphere's force), and columns compared beside the energies and
// tracked displacements (a rigid body's pose, velocities and impulses, held to the displacements'
// 1e-10).
struct SameRun {
  std::string restitution;
  std::function<std::string(std::string)> edit;
  int ranks = 2;
  std::string contact_column = "contact.work";
  std::vector<std::string> also;

  SameRun with_restitution(std::string e) && {
    restitution = std::move(e);
    return std::move(*this);
  }
  SameRun with_edit(std::function<std::string(std::string)> f) && {
    edit = std::move(f);
    return std::move(*this);
  }
  SameRun on_ranks(int n) && {
    ranks = n;
    return std::move(*this);
  }
  SameRun contact_in(std::string column) && {
    contact_column = std::move(column);
    return std::move(*this);
  }
  SameRun comparing(std::vector<std::string> columns) && {
    also = std::move(columns);
    return std::move(*this);
  }
};

double summary_number(const fs::path& summary, const std::string& key) {
  std::istringstream in(file_text(summary));
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + " = ", 0) == 0) return std::stod(line.substr(key.size() + 3));
  FAIL("no " << key << " in " << summary);
  return 0.0;
}

// The scene text with the lines from the table `from` (a line of its own, not a comment naming it)
// up to the table `to` replaced by `with`.
std::string replace_tables(const std::string& text, const std::string& from, const std::string& to,
                           const std::string& with) {
  const auto at = text.find("\n" + from) + 1;
  const auto end = text.find("\n" + to) + 1;
  REQUIRE(at > 0);
  REQUIRE(end > at);
  return text.substr(0, at) + with + text.substr(end);
}

// Returns the serial run's history.
History require_same_run(const std::string& example, double end, double interval,
                         const SameRun& how = {}) {
  const std::string mpi = mpiexec();
  test::TempDir tmp;
  const fs::path scene = short_scene(tmp, example, end, interval, how.restitution, how.edit);
  const fs::path serial = tmp.path / "serial", ranks = tmp.path / "ranks";
  REQUIRE(shell(fmt::format("'{}' run '{}' --out '{}' --quiet", CCM_BINARY, scene.string(),
                            serial.string())) == 0);
  REQUIRE(shell(fmt::format("{} -n {} '{}' run '{}' --out '{}' --quiet > '{}' 2>&1", mpi, how.ranks,
                            CCM_BINARY, scene.string(), ranks.string(),
                            (tmp.path / "mpi.log").string())) == 0);
  INFO(file_text(tmp.path / "mpi.log"));
  // Written once, by rank 0: the same three files as a serial run, and it was partitioned.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(ranks)) ++files;
  CHECK(files == 3);
  CHECK(file_text(ranks / "summary.toml").find("[partition]") != std::string::npos);
  CHECK(file_text(ranks / "summary.toml").find(fmt::format("ranks = {}", how.ranks)) !=
        std::string::npos);
  // The energy balance sums every term once whatever the partition (a rigid body's gravity work
  // and loads are stepped on every rank and counted once): its error agrees to 1e-6 of itself.
  const double balance = summary_number(serial / "summary.toml", "energy_balance_error");
  CHECK(std::abs(summary_number(ranks / "summary.toml", "energy_balance_error") - balance) <=
        1e-6 * balance);

  const History a = read_history(serial / "history.csv");
  const History b = read_history(ranks / "history.csv");
  REQUIRE(a.columns == b.columns);
  REQUIRE(a.rows.size() == b.rows.size());
  const auto column = [&](const std::string& name) {
    return static_cast<size_t>(std::find(a.columns.begin(), a.columns.end(), name) -
                               a.columns.begin());
  };
  // Contact acted within the window: cross-partition contact is exercised.
  REQUIRE(column(how.contact_column) < a.columns.size());
  double contact_acted = 0.0;
  for (const auto& r : a.rows)
    contact_acted = std::max(contact_acted, std::abs(r[column(how.contact_column)]));
  REQUIRE(contact_acted > 0.0);
  // The energies are held to 1e-12 of the run's energy scale (the largest energy of any column,
  // as the energy balance scales its error): a body's stored energy is a sum over its elements
  // that the partition adds in another order, so its round-off is n eps of its own size, and a
  // body that stores little of the run's energy (the plate here, 1e-4 of the ball's kinetic
  // energy) read 1.4e-12 of its own peak under the sanitizer build's -O1 (1.1e-15 J).
  double energy_scale = 0.0;
  for (size_t c = 0; c < a.columns.size(); ++c)
    if (ends_with(a.columns[c], "_energy"))
      for (const auto& r : a.rows) energy_scale = std::max(energy_scale, std::abs(r[c]));
  int compared = 0;
  for (size_t c = 0; c < a.columns.size(); ++c) {
    const std::string& name = a.columns[c];
    const bool energy = ends_with(name, "_energy");
    // The contact work sums impulse terms of both signs: its round-off is that of its gross
    // terms, up to 1e-12 of its net value (7.5e-13 measured on the DCR scene), so it is held to
    // the displacements' 1e-10.
    const bool tracked = ends_with(name, ".ux") || ends_with(name, ".uy") ||
                         ends_with(name, ".uz") || name == how.contact_column ||
                         std::find(how.also.begin(), how.also.end(), name) != how.also.end();
    if (!energy && !tracked) continue;
    double scale = 0.0, diff = 0.0;
    for (size_t i = 0; i < a.rows.size(); ++i) {
      scale = std::max(scale, std::abs(a.rows[i][c]));
      diff = std::max(diff, std::abs(a.rows[i][c] - b.rows[i][c]));
    }
    if (energy) scale = energy_scale;
    INFO(name << ": largest difference " << diff << " of scale " << scale);
    CHECK(diff <= (energy ? 1e-12 : 1e-10) * scale);
    ++compared;
  }
  CHECK(compared >= 6 + static_cast<int>(how.also.size()));  // per body KE and IE, contact
                                                             // work, a tracked node's u
  return a;
}

}  // namespace

TEST_CASE("mpiexec -n 2 ccm run equals the serial run: DCR ball on a clamped plate",
          "[distributed][mpi][cli]") {
  require_same_run("ball_on_plate_dcr.toml", 6e-4, 5e-5);
}

// The body-pair restitution reads and changes every node of the ball when the episode begins and
// ends; the partitioned run gathers the nodes beyond the contact region only then
// (engine/contact/whole_bodies.hpp). e = 0.1 is below the ball's elastic rebound, so the
// correction acts at separation (about 3.5 ms): the contact work falls from -1.9e-4 J (the elastic
// exchange, e = 1) to -4.4e-3 J (measured, serial).
TEST_CASE("mpiexec -n 2 ccm run equals the serial run: DCR with a body-pair restitution",
          "[distributed][mpi][cli][restitution]") {
  const History serial =
      require_same_run("ball_on_plate_dcr.toml", 4e-3, 1e-4, SameRun{}.with_restitution("0.1"));
  const auto work =
      static_cast<size_t>(std::find(serial.columns.begin(), serial.columns.end(), "contact.work") -
                          serial.columns.begin());
  REQUIRE(work < serial.columns.size());
  CHECK(serial.rows.back()[work] < -2e-3);  // the restitution acted within the window
}

TEST_CASE("mpiexec -n 2 ccm run equals the serial run: rigid sphere (penalty) on a plate",
          "[distributed][mpi][cli]") {
  require_same_run("sphere_on_plate.toml", 8e-4, 5e-5, SameRun{}.contact_in("ball.contact_force"));
}

// Two contact pairs in one partitioned run (a ContactSet replicated on every rank): the DCR
// example's ball on its plate (the pair named "contact", whose columns the check reads) and an
// analytic pebble on the penalty dropped on the plate's other corner.
TEST_CASE("mpiexec -n 2 ccm run equals the serial run: DCR and penalty pairs in one scene",
          "[distributed][mpi][cli][contact]") {
  const auto pairs = [](const std::string& text) {
    return replace_tables(
        text, "[contact]\n", "[output]\n",
        "[[contact.pairs]]\nname = \"contact\"\nmodel = \"dcr\"\nsurfaces = [\"ball\", "
        "\"plate\"]\n\n[[contact.pairs]]\nname = \"drop\"\nmodel = \"rigid_penalty\"\n"
        "body = \"plate\"\npenalty = 1e4\n[contact.pairs.sphere]\nname = \"pebble\"\n"
        "radius = 0.003\nmass = 0.001\ncenter = [0.01, 0.01, 0.0115]\n"
        "velocity = [0.0, 0.0, -3.0]\n\n");
  };
  const History serial =
      require_same_run("ball_on_plate_dcr.toml", 6e-4, 5e-5, SameRun{}.with_edit(pairs));
  // The pebble (0.5 mm above the plate at 3 m/s) struck it within the window: both pairs acted.
  const auto force = static_cast<size_t>(
      std::find(serial.columns.begin(), serial.columns.end(), "pebble.contact_force") -
      serial.columns.begin());
  REQUIRE(force < serial.columns.size());
  double largest = 0.0;
  for (const auto& r : serial.rows) largest = std::max(largest, std::abs(r[force]));
  CHECK(largest > 0.0);
}

// A rigid body in a partitioned run is whole on every rank (rank 0 owns its nodes, the others
// hold replicas) and stepped alike from the same complete forces (engine/distributed/
// subdomain.hpp). The columns compared beside the energies: its pose, velocities and the contact
// impulse it took.
const std::vector<std::string> kRigidBallColumns = {"ball.x",
                                                    "ball.z",
                                                    "ball.vx",
                                                    "ball.vz",
                                                    "ball.wx",
                                                    "ball.wy",
                                                    "ball.contact_impulse_z",
                                                    "ball.contact_force_z"};

std::string rigid_ball(std::string text) {
  const std::string velocity = "initial_velocity = [0.0, 0.0, -3.0]   # m/s\n";
  const auto at = text.find(velocity);
  REQUIRE(at != std::string::npos);
  return text.insert(at + velocity.size(), "kind = \"rigid\"\n");
}

// A surface load on the rigid ball, pushing it along x and down from t = 0: the replicas carry it,
// rank 0 alone counts its work.
std::string pushed(std::string text) {
  const auto at = text.find("\n[contact]\n") + 1;
  REQUIRE(at > 0);
  return text.insert(at,
                     "[[surface_loads]]\nname = \"push\"\nbody = \"ball\"\nplane = { point = "
                     "[0.03, 0.03, 0.0185], normal = [1.0, 0.0, 0.0], tolerance = 0.011 }\n"
                     "direction = [1.0, 0.0, -1.0]\nforce = [[0.0, 0.0], [3e-4, 40.0]]\n\n");
}

std::string rigid_ball_pushed(std::string text) { return pushed(rigid_ball(std::move(text))); }

TEST_CASE("mpiexec -n 2 ccm run equals the serial run: a free rigid ball (DCR) pushed onto a plate",
          "[distributed][mpi][cli][rigid]") {
  const History serial =
      require_same_run("ball_on_plate_dcr.toml", 6e-4, 5e-5,
                       SameRun{}.with_edit(rigid_ball_pushed).comparing(kRigidBallColumns));
  // The ball took the plate's impulses: the DCR's impulses reached the body.
  const auto impulse = static_cast<size_t>(
      std::find(serial.columns.begin(), serial.columns.end(), "ball.contact_impulse_z") -
      serial.columns.begin());
  REQUIRE(impulse < serial.columns.size());
  CHECK(serial.rows.back()[impulse] > 1e-3);  // N s, of 0.0147 kg x 3 m/s = 0.044 N s
}

// The penalty pair against a free meshed rigid ball under gravity: the springs' reaction on the
// replicas, the body's gravity work counted once.
TEST_CASE("mpiexec -n 2 ccm run equals the serial run: a free rigid ball on the penalty",
          "[distributed][mpi][cli][rigid]") {
  const auto penalty = [](std::string text) {
    return replace_tables(
        rigid_ball(std::move(text)), "[contact]\n", "[output]\n",
        "[contact]\nmodel = \"rigid_penalty\"\nbody = \"plate\"\nrigid = \"ball\"\n"
        "penalty = 2.0e4\ndamping = 0.1\n\n[gravity]\nacceleration = [0.0, 0.0, -9.81]\n\n");
  };
  require_same_run("ball_on_plate_dcr.toml", 6e-4, 5e-5,
                   SameRun{}.with_edit(penalty).comparing(
                       {"ball.z", "ball.vz", "ball.wx", "ball.wy", "contact.rigid_force_z"}));
}

// The example with a DCR pair (pad on limb) and a penalty pair against a fixed rigid table, on the
// linear tet (a partitioned run refuses the nodal-pressure tet, below).
TEST_CASE("mpiexec -n 2 ccm run equals the serial run: pad on limb on a rigid table",
          "[distributed][mpi][cli][rigid]") {
  const auto linear_tets = [](std::string text) {
    const std::string element = "element = \"nodal_pressure\"";
    const auto at = text.find(element);
    REQUIRE(at != std::string::npos);
    return text.erase(at, element.size());
  };
  require_same_run("pad_limb_table_pairs.toml", 2e-3, 1e-4,
                   SameRun{}.with_edit(linear_tets).contact_in("pad_limb.work"));
}

// Joints across partitions (engine/distributed/replicated_constraint.hpp): the DCR example's
// plate hinged on a frictional, clamped pin along its x = 0 edge instead of clamped, and the
// ball's nodes on a slide along z. Every rank gathers a joint's nodes and applies it alike; the
// replicated contact takes the joints' nodes from their owners at the end of each step. The
// flap swings within the window (its angle and rate are compared).
std::string hinged(const std::string& text) {
  return replace_tables(
      text, "[[fixed]]", "[contact]\n",
      "[[joints]]\nname = \"hinge\"\nkind = \"pin\"\nbody = \"plate\"\n"
      "plane = { point = [0.0, 0.0, 0.0], normal = [1.0, 0.0, 0.0] }\n"
      "point = [0.0, 0.03, 0.004]\naxis = [0.0, 1.0, 0.0]\nmu_s = 0.3\nmu_k = 0.2\n"
      "stiffness = 20.0\ndamping = 0.002\n\n"
      "[[joints]]\nname = \"track\"\nkind = \"slide\"\nbody = \"ball\"\n"
      "box = { min = [0.0, 0.0, 0.0], max = [0.06, 0.06, 0.04] }\n"
      "direction = [0.0, 0.0, 1.0]\n\n");
}

TEST_CASE("mpiexec -n 2 ccm run equals the serial run: a plate on a pin and a ball on a slide",
          "[distributed][mpi][cli][joints]") {
  const History serial =
      require_same_run("ball_on_plate_dcr.toml", 1.5e-3, 5e-5,
                       SameRun{}.with_edit(hinged).comparing(
                           {"hinge.angle", "hinge.angular_velocity", "ball.vz", "plate.vz"}));
  const auto angle =
      static_cast<size_t>(std::find(serial.columns.begin(), serial.columns.end(), "hinge.angle") -
                          serial.columns.begin());
  REQUIRE(angle < serial.columns.size());
  CHECK(std::abs(serial.rows.back()[angle]) > 1e-3);  // rad: the flap turned on its pin
}

// Three ranks: a rigid body's replicas on two of them, and a pin's ring over three subdomains.
// [heavy]: the optimised pass only (CI's time).
TEST_CASE("mpiexec -n 3 ccm run equals the serial run: a rigid ball and a pinned plate",
          "[distributed][mpi][cli][rigid][joints][heavy]") {
  require_same_run("ball_on_plate_dcr.toml", 6e-4, 5e-5,
                   SameRun{}.with_edit(rigid_ball_pushed).on_ranks(3).comparing(kRigidBallColumns));
  require_same_run(
      "ball_on_plate_dcr.toml", 1.5e-3, 5e-5,
      SameRun{}.with_edit(hinged).on_ranks(3).comparing({"hinge.angle", "hinge.angular_velocity"}));
}

TEST_CASE("mpiexec: a partitioned run refuses the nodal-pressure tet before any step",
          "[distributed][mpi][cli]") {
  const std::string mpi = mpiexec();
  test::TempDir tmp;
  const fs::path scene = short_scene(tmp, "pad_limb_table_pairs.toml", 2e-3, 1e-4, "");
  const fs::path out = tmp.path / "out", log = tmp.path / "mpi.log";
  const int code = shell(fmt::format("{} -n 2 '{}' run '{}' --out '{}' --quiet > '{}' 2>&1", mpi,
                                     CCM_BINARY, scene.string(), out.string(), log.string()));
  INFO(file_text(log));
  CHECK(code == 2);  // exit_code::bad_input, not an internal error
  CHECK(file_text(log).find("nodal_pressure") != std::string::npos);
  CHECK(file_text(log).find("'limb'") != std::string::npos);
  CHECK(!fs::exists(out));
}

// Under mpiexec only rank 0 has the standard input: a scene piped to `ccm run -` is read by rank
// 0 and passed on, so the ranks prepare the same scene (before, rank 1 met an empty scene, rank 0
// went on into the run's first collective and the job hung). The run equals the same scene read
// from its file by two ranks.
TEST_CASE("mpiexec -n 2 ccm run - reads the scene from stdin on every rank",
          "[distributed][mpi][cli]") {
  const std::string mpi = mpiexec() + " -n 2";
  test::TempDir tmp;
  const fs::path scene = short_dcr_scene(tmp);
  const fs::path piped = tmp.path / "piped", named = tmp.path / "named";
  REQUIRE(shell(fmt::format("{} '{}' run - --out '{}' --quiet < '{}' > '{}' 2>&1", mpi, CCM_BINARY,
                            piped.string(), scene.string(), (tmp.path / "piped.log").string())) ==
          0);
  REQUIRE(shell(fmt::format("{} '{}' run '{}' --out '{}' --quiet > /dev/null 2>&1", mpi, CCM_BINARY,
                            scene.string(), named.string())) == 0);
  CHECK(file_text(piped / "summary.toml").find("ranks = 2") != std::string::npos);
  CHECK(file_text(piped / "history.csv") == file_text(named / "history.csv"));
}

// A rank that cannot prepare the scene while the others can (here, by mpiexec's one-program-per-
// rank form, a file that exists for rank 0 and not for rank 1; on a cluster, a file missing on one
// machine) ends the whole job with the bad-input code and that rank's message, before anything
// is written; the ranks that could prepare it do not wait for it in a collective.
TEST_CASE("mpiexec: a scene one rank cannot prepare ends every rank and writes nothing",
          "[distributed][mpi][cli]") {
  const std::string mpi = mpiexec();
  test::TempDir tmp;
  const fs::path scene = short_dcr_scene(tmp);
  const fs::path missing = tmp.path / "missing.toml", out = tmp.path / "out";
  const fs::path log = tmp.path / "mpi.log";
  for (const auto& [first, second] : {std::pair{scene, missing}, std::pair{missing, scene}}) {
    const int code = shell(fmt::format(
        "{5} -n 1 '{0}' run '{1}' --out '{3}' --quiet : -n 1 '{0}' run '{2}' --out '{3}' --quiet "
        "> '{4}' 2>&1",
        CCM_BINARY, first.string(), second.string(), out.string(), log.string(), mpi));
    INFO(file_text(log));
    CHECK(code == 2);  // exit_code::bad_input (124 would be the timeout: a hang)
    CHECK(file_text(log).find("missing.toml") != std::string::npos);
    CHECK(!fs::exists(out));
  }
}

}  // namespace ccm
