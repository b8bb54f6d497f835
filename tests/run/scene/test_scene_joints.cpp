// [[joints]] (docs/scene-file.md): a pin and a slide on nodes of deformable bodies, from a scene
// file through the run's one assembly path (run/scene/scene_run.hpp). A block on a slide under a
// tilted gravity follows the closed-form parabola along the slide; a stiff bar hung on a pin
// swings with the compound pendulum's period of its own lumped masses; a joint that cannot be
// built is refused with file, line and key.
#include <fmt/format.h>

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "run/scene/scene_file.hpp"
#include "run/scene/scene_run.hpp"
#include "tests/support/scene_fixtures.hpp"

using Catch::Contains;
using namespace ccm;

namespace {

// A 10 x 10 x 100 mm bar centred on the origin, turned by theta about +y (lines 1-20).
std::string tilted_bar(double end, double theta_deg) {
  return fmt::format(
      "[time]\nend = {}\noutput_interval = 1e-3\n[gravity]\nacceleration = [0.0, 0.0, -9.81]\n"
      "[[bodies]]\nname = \"bar\"\n[bodies.material]\nE = 2e7\nnu = 0.3\nrho = 1000.0\n"
      "[bodies.geometry]\nshape = \"box\"\nsize = [0.01, 0.01, 0.1]\ncentered = true\n"
      "mesh_size = 0.005\n[bodies.placement]\nrotate_axis = [0.0, 1.0, 0.0]\nrotate_deg = {}\n",
      end, theta_deg);
}

// The tilted bar hung at its top 10 mm on a pin along y through (pin_x, 0, pin_z), released at
// 3 degrees; `name_line` ("name = \"hinge\"\n" or empty) names the joint.
std::string pinned_bar(double end, const Vec3& pin, double theta0, const std::string& name_line) {
  return tilted_bar(end, 3.0) +
         fmt::format(
             "[[joints]]\n{}kind = \"pin\"\nbody = \"bar\"\npoint = [{}, 0.0, {}]\n"
             "axis = [0.0, 1.0, 0.0]\nplane = {{point = [{}, 0.0, {}], normal = [{}, 0.0, "
             "{}], tolerance = 0.0051}}\n",
             name_line, pin.x(), pin.z(), pin.x(), pin.z(), std::sin(theta0), std::cos(theta0));
}

}  // namespace

TEST_CASE("joints: nodes on a slide follow the closed-form parabola along it", "[scene][joints]") {
  // Every node of a cube on a slide along x, under gravity g (1, 0, -1) / sqrt 2: the cube
  // slides as a rigid body, x = X + g_x t^2 / 2 (the leapfrog is exact for a constant
  // acceleration), y and z stay.
  const double g = 9.81 / std::sqrt(2.0);
  const std::string text = test::kOneCubeScene +
                           fmt::format("[gravity]\nacceleration = [{}, 0.0, {}]\n", g, -g) +
                           "[[joints]]\nkind = \"slide\"\nbody = \"cube\"\n"
                           "box = {min = [-1.0, -1.0, -1.0], max = [1.0, 1.0, 1.0]}\n"
                           "direction = [2.0, 0.0, 0.0]\n";
  const SceneRun run = assemble_scene_run(parse_scene(text, "s.toml"));
  REQUIRE(run.joints.size() == 1);
  CHECK(run.joints[0]->name() == "slide");
  RunOptions opt = scene_run_options(run, nullptr);
  State last;
  opt.on_sample = [&](const State& s) { last = s; };
  const RunSummary summary = run_explicit(run.model, opt);
  REQUIRE(summary.verdict == Verdict::completed);
  const double t = last.t;
  double worst = 0.0;
  for (size_t i = 0; i < last.x.size(); ++i) {
    const Vec3 expected = last.X[i] + Vec3(0.5 * g * t * t, 0.0, 0.0);
    worst = std::max(worst, (last.x[i] - expected).norm());
  }
  // Round-off of the sums over 1e-3 s of steps, on displacements of 3.5 um: 1e-15 m.
  CHECK(worst < 1e-15);
  CHECK(last.x[0].x() - last.X[0].x() > 3e-6);
}

TEST_CASE("joints: a track's friction stops a sliding cube at the closed-form time and distance",
          "[scene][joints]") {
  // A 1 g cube launched at 1 m/s along x, every node on a track along x with N = 0.1 N and
  // mu_k = 0.5 (no gravity): it decelerates at a = mu_k N / M = 50 m/s^2 (TF.3 takes mu_k N dt
  // from its momentum every step: exact for the mean velocity to round-off), stops at v0 / a =
  // 20 ms after v0^2 / (2 a) = 10 mm (within a dt^2 / 2 of the last step, 1e-7 m at dt < 6e-5 s),
  // then sticks (TF.2) with no force.
  const std::string text = test::kOneCubeScene;
  std::string scene = text;
  scene.replace(scene.find("end = 1e-3"), 10, "end = 0.03\noutput_interval = 1e-3");
  scene.insert(scene.find("[bodies.material]"), "initial_velocity = [1.0, 0.0, 0.0]\n");
  scene +=
      "[[joints]]\nname = \"rails\"\nkind = \"track\"\nbody = \"cube\"\n"
      "box = {min = [-1.0, -1.0, -1.0], max = [1.0, 1.0, 1.0]}\ndirection = [1.0, 0.0, 0.0]\n"
      "normal_force = 0.1\nmu_s = 0.5\nmu_k = 0.5\n";
  const SceneRun run = assemble_scene_run(parse_scene(scene, "s.toml"));
  REQUIRE(run.joints.size() == 1);
  CHECK(run.joints[0]->name() == "track_friction");
  REQUIRE(run.joint_histories.size() == 1);
  CHECK(run.joint_histories[0]->history_columns() ==
        std::vector<std::string>{"rails.force", "rails.sticking"});
  RunOptions opt = scene_run_options(run, nullptr);
  double M = 0.0;
  std::vector<std::array<double, 4>> samples;  // t, mean v_x, mean u_x, sticking
  opt.on_sample = [&](const State& s) {
    double p = 0.0, u = 0.0;
    M = 0.0;
    for (size_t i = 0; i < s.v.size(); ++i) {
      M += s.m_lumped[i];
      p += s.m_lumped[i] * s.v[i].x();
      u += s.m_lumped[i] * (s.x[i].x() - s.X[i].x());
    }
    std::vector<double> row;
    run.joint_histories[0]->append_history(s, row);
    samples.push_back({s.t, p / M, u / M, row[1]});
  };
  const RunSummary summary = run_explicit(run.model, opt);
  REQUIRE(summary.verdict == Verdict::completed);
  REQUIRE(M == Approx(1e-3).epsilon(1e-12));
  const double a = 0.5 * 0.1 / M;
  for (const auto& [t, v, u, sticking] : samples) {
    INFO("t = " << t);
    if (t < 0.019) {
      CHECK(std::abs(v - (1.0 - a * t)) < 1e-12);
      CHECK(sticking == 0.0);
    } else if (t > 0.021) {
      CHECK(std::abs(v) < 1e-15);
      CHECK(std::abs(u - 1.0 / (2.0 * a)) < 1e-7);
      CHECK(sticking == 1.0);
    }
  }
  CHECK(samples.back()[0] == Approx(0.03));
}

TEST_CASE("joints: a stiff bar on a pin swings with the compound pendulum's period",
          "[scene][joints][heavy]") {
  // The bar, turned by 3 degrees and released, on a pin along y through its top 10 mm (the
  // nodes of that slab turn as one ring, engine/bc/pin_joint.hpp). Closed form from the bar's own
  // lumped masses m_i at X_i: T = 2 pi sqrt(J / (M g d)) (1 + theta0^2 / 16), J = sum m_i |r_i|^2,
  // M d = |sum m_i r_i|, r_i the part of X_i - p normal to the axis. The bar is stiff for its
  // weight (E = 20 MPa: its sag strain rho g L / E is 5e-5, its bending mode 30 times the
  // swing's frequency), so it swings as the rigid body those masses make. Tolerance 0.1 % (the
  // issue's; measured 2.5e-5): the elastic bar's compliance changes the lever by its sag strain,
  // and the samples every 1 ms interpolate the crossings to 1e-6 of the period.
  const double theta0 = 3.0 * std::numbers::pi / 180.0;
  const Vec3 pin(0.045 * std::sin(theta0), 0.0, 0.045 * std::cos(theta0));
  const std::string text = pinned_bar(0.8, pin, theta0, "");
  const SceneRun run = assemble_scene_run(parse_scene(text, "s.toml"));
  REQUIRE(run.joints.size() == 1);
  RunOptions opt = scene_run_options(run, nullptr);
  double J = 0.0, Md = 0.0;
  std::vector<double> t, phi;
  opt.on_sample = [&](const State& s) {
    Vec3 first = Vec3::Zero(), centre = Vec3::Zero();
    double m = 0.0;
    for (size_t i = 0; i < s.x.size(); ++i) {
      m += s.m_lumped[i];
      centre += s.m_lumped[i] * s.x[i];
      if (t.empty()) {
        const Vec3 r = s.X[i] - pin;
        const Vec3 normal(r.x(), 0.0, r.z());
        J += s.m_lumped[i] * normal.squaredNorm();
        first += s.m_lumped[i] * normal;
      }
    }
    if (t.empty()) Md = first.norm();
    const Vec3 d = centre / m - pin;
    t.push_back(s.t);
    phi.push_back(std::atan2(-d.x(), -d.z()));
  };
  const RunSummary summary = run_explicit(run.model, opt);
  INFO(summary.instability.reason);
  REQUIRE(summary.verdict == Verdict::completed);
  std::vector<double> crossings;  // zero crossings of phi, half a period apart
  for (size_t k = 1; k < phi.size(); ++k)
    if ((phi[k - 1] < 0.0) != (phi[k] < 0.0))
      crossings.push_back(t[k - 1] + (t[k] - t[k - 1]) * -phi[k - 1] / (phi[k] - phi[k - 1]));
  REQUIRE(crossings.size() >= 3);
  const double period = 2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  const double closed =
      2.0 * std::numbers::pi * std::sqrt(J / (Md * 9.81)) * (1.0 + theta0 * theta0 / 16.0);
  CHECK(period == Approx(closed).epsilon(1e-3));
}

TEST_CASE("joints: what cannot be a joint is refused with file, line and key", "[scene][joints]") {
  const std::string cube = test::kOneCubeScene;  // lines 1-12
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"hinge\"\n"),
             Contains("s.toml:14: joints[0].kind") && Contains("\"pin\", \"slide\", \"track\""));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"track\"\ndirection = [1.0, 0.0, "
                                            "0.0]\nnode_set = \"cube/boundary\"\nnormal_force = "
                                            "-1.0\n"),
             Contains("s.toml:17: joints[0].normal_force") && Contains(">= 0 (got -1)"));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"track\"\ndirection = [1.0, 0.0, "
                                            "0.0]\nnode_set = \"cube/boundary\"\n"),
             Contains("joints[0].normal_force") && Contains("required"));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"track\"\ndirection = [1.0, 0.0, "
                                            "0.0]\nnode_set = \"cube/boundary\"\nnormal_force = "
                                            "1.0\nmu_s = 0.1\nmu_k = 0.3\n"),
             Contains("joints[0].mu_k") && Contains("at most mu_s"));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"slide\"\ndirection = [1.0, 0.0, "
                                            "0.0]\nbox = {min = [5.0, 5.0, 5.0], max = [6.0, 6.0, "
                                            "6.0]}\n"),
             Contains("joints[0].box") && Contains("selects no node"));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"slide\"\ndirection = [0.0, 0.0, "
                                            "0.0]\nnode_set = \"cube/boundary\"\n"),
             Contains("joints[0].direction"));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"pin\"\npoint = [0.0, 0.0, 0.0]\n"
                                            "axis = [0.0, 1.0, 0.0]\nmu_s = 0.1\nmu_k = 0.2\n"
                                            "node_set = \"cube/boundary\"\n"),
             Contains("joints[0].mu_k") && Contains("at most mu_s"));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"pin\"\npoint = [0.0, 0.0, 0.0]\n"
                                            "axis = [0.0, 1.0, 0.0]\nstiffness = -5.0\n"
                                            "node_set = \"cube/boundary\"\n"),
             Contains("s.toml:17: joints[0].stiffness") && Contains(">= 0 (got -5)"));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"pin\"\npoint = [0.0, 0.0, 0.0]\n"
                                            "axis = [0.0, 1.0, 0.0]\ndamping = nan\n"
                                            "node_set = \"cube/boundary\"\n"),
             Contains("joints[0].damping"));
  CHECK_THAT(
      test::assembly_error_of(cube + "[[joints]]\nkind = \"slide\"\ndirection = [1.0, 0.0, "
                                     "0.0]\nnode_set = \"cube/boundary\"\nstiffness = 1.0\n"),
      Contains("unknown key 'stiffness'"));
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"slide\"\ndirection = [1.0, 0.0, "
                                            "0.0]\nnode_set = \"cube/boundary\"\naxis = [1.0, 0.0, "
                                            "0.0]\n"),
             Contains("unknown key 'axis'"));
  // A pin whose nodes all lie on its axis has no ring to turn.
  CHECK_THAT(test::assembly_error_of(cube + "[[joints]]\nkind = \"pin\"\npoint = [0.0, 0.0, 0.0]\n"
                                            "axis = [0.0, 1.0, 0.0]\nbox = {min = [-1e-6, -1.0, "
                                            "-1e-6], max = [1e-6, 1.0, 1e-6]}\n"),
             Contains("joints[0].box"));
  // A rigid body's nodes: its pin is its motion.
  std::string rigid = cube;
  rigid.insert(rigid.find("[bodies.material]"), "kind = \"rigid\"\n");
  CHECK_THAT(test::assembly_error_of(rigid + "[[joints]]\nkind = \"slide\"\ndirection = [1.0, 0.0, "
                                             "0.0]\nnode_set = \"cube/boundary\"\n"),
             Contains("rigid body 'cube'") && Contains("motion = \"pinned\""));
}

TEST_CASE("joints: a pin's angle and angular velocity are history columns, consistent",
          "[scene][joints]") {
  // The bar of the pendulum test above, released at 3 degrees, for 0.15 s: the pin's columns
  // <name>.angle and <name>.angular_velocity. The angle is the integral of the rate: the
  // trapezoid over the 1 ms samples of the 0.5 s swing would err by 1e-5 of it, but the ring's
  // rate also carries the bar's elastic vibration (its bending mode, 30 times the swing's
  // frequency), which samples every 1 ms alias: 1 % of the largest angle (measured 0.15 %). The
  // angle moves as the bar's centre of mass does about the pin (the ring turns with the bar; its
  // elastic sag changes that by its strain, 5e-5): 1 % of the swing.
  const double theta0 = 3.0 * std::numbers::pi / 180.0;
  const Vec3 pin(0.045 * std::sin(theta0), 0.0, 0.045 * std::cos(theta0));
  const std::string text = pinned_bar(0.15, pin, theta0, "name = \"hinge\"\n");
  const SceneRun run = assemble_scene_run(parse_scene(text, "s.toml"));
  HistoryRecorder history(run.model.mesh, run.output);
  RunOptions opt = scene_run_options(run, &history);
  std::vector<double> com_angle;
  opt.on_sample = [&](const State& s) {
    Vec3 centre = Vec3::Zero();
    double m = 0.0;
    for (size_t i = 0; i < s.x.size(); ++i) {
      m += s.m_lumped[i];
      centre += s.m_lumped[i] * s.x[i];
    }
    const Vec3 d = centre / m - pin;
    com_angle.push_back(std::atan2(-d.x(), -d.z()));
  };
  REQUIRE(run_explicit(run.model, opt).verdict == Verdict::completed);
  const auto& columns = history.columns();
  const auto at = [&](const std::string& name) {
    const auto it = std::find(columns.begin(), columns.end(), name);
    REQUIRE(it != columns.end());
    return static_cast<size_t>(it - columns.begin());
  };
  const size_t angle = at("hinge.angle"), rate = at("hinge.angular_velocity"), time = at("time");
  const auto& rows = history.rows();
  REQUIRE(rows.size() == com_angle.size());
  double integral = 0.0, largest = 0.0, worst_integral = 0.0, worst_com = 0.0;
  for (size_t k = 1; k < rows.size(); ++k) {
    integral += 0.5 * (rows[k][rate] + rows[k - 1][rate]) * (rows[k][time] - rows[k - 1][time]);
    largest = std::max(largest, std::abs(rows[k][angle]));
    worst_integral = std::max(worst_integral, std::abs(rows[k][angle] - integral));
    // The centre's angle atan2(-x, -z) about the pin turns with the ring's, sign for sign.
    worst_com = std::max(worst_com, std::abs(rows[k][angle] - (com_angle[k] - com_angle[0])));
  }
  CHECK(largest > 0.5 * theta0);  // it swung
  CHECK(worst_integral < 1e-2 * largest);
  CHECK(worst_com < 1e-2 * largest);
  // A joint's name is a history prefix: a body's name is refused, the default is joint<k>.
  CHECK_THAT(test::assembly_error_of(test::kOneCubeScene +
                                     "[[joints]]\nname = \"cube\"\nkind = \"slide\"\n"
                                     "direction = [1.0, 0.0, 0.0]\nnode_set = \"cube\"\n"),
             Contains("joints[0].name: 'cube' is also the name of a body"));
  const SceneRun unnamed = assemble_scene_run(parse_scene(
      test::kOneCubeScene + "[[joints]]\nkind = \"slide\"\ndirection = [1.0, 0.0, 0.0]\n"
                            "node_set = \"cube\"\n",
      "s.toml"));
  CHECK(unnamed.scene.joints.at(0).name == "joint1");
}
