// Scenes whose bodies come from .inp and .unv files: the files' named sets and surfaces select
// fixed nodes and loaded faces, and `ccm run` moves a free UNV body as a rigid body.
#include <fmt/format.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <sstream>

#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "tests/engine/mesh/readers/mesh_test_files.hpp"

using namespace ccm;

namespace {

std::string body_from(const std::string& file, const std::string& extra = "") {
  return fmt::format(
      "[time]\nend = 1e-3\n[[bodies]]\nname = \"cube\"\n{}[bodies.material]\nE = 1e5\nnu = 0.3\n"
      "rho = 1000.0\n[bodies.geometry]\nshape = \"mesh\"\nfile = \"{}\"\n",
      extra, test::mesh_data(file).string());
}

}  // namespace

TEST_CASE("scene: an .inp body's node sets and surfaces are selectable by name", "[scene][inp]") {
  test::TempDir dir;
  const auto scene =
      dir.write("s.toml", body_from("abaqusreader_cube_tet4.inp") +
                              "[[fixed]]\nbody = \"cube\"\nnode_set = \"SYM12\"\n"
                              "[[surface_loads]]\nbody = \"cube\"\nsurface = \"LOAD\"\n"
                              "direction = [0, 0, -1]\nforce = [[0, 1]]\n");
  const Model model = build_model(parse_scene_file(scene));
  CHECK(model.mesh.n_elements() == 17);
  // SYM12: the four corners of the face z = 0, now held.
  REQUIRE(model.bcs.fixed_nodes.size() == 4);
  for (int n : model.bcs.fixed_nodes) CHECK(model.mesh.X[static_cast<size_t>(n)].z() == 0.0);
  CHECK(model.mesh.surfaces.at("cube/LOAD").triangles.size() == 2);
  CHECK(model.mesh.node_sets.at("cube/LOAD").size() == 4);
  CHECK(model.mesh.node_sets.at("cube/SYM23").size() == 4);
}

TEST_CASE("ccm run: a free UNV body keeps its kinetic energy 1/2 rho V v^2", "[scene][unv][cli]") {
  test::TempDir dir;
  // ElmerGrid's box [0, 200]^3 flying at 1 m/s: no force acts, so every node keeps v and the
  // kinetic energy is 1/2 rho V v^2 = 0.5 * 1000 * 8e6 * 1 = 4e9 J at every step (lumped mass
  // sums to rho V; the tets stay undeformed, so round-off only).
  const auto scene =
      dir.write("s.toml", body_from("elmer_box.unv", "initial_velocity = [0, 0, 1]\n"));
  const auto out = dir.path / "out";
  const std::string command =
      fmt::format("'{}' run '{}' --out '{}' --quiet 2> '{}'", CCM_BINARY, scene.string(),
                  out.string(), (dir.path / "err.txt").string());
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  INFO(test::file_text(dir.path / "err.txt"));
  REQUIRE(WEXITSTATUS(status) == 0);
  std::istringstream history(test::file_text(out / "history.csv"));
  std::string header, row, last;
  std::getline(history, header);
  REQUIRE(header.rfind("time,cube.kinetic_energy", 0) == 0);
  int rows = 0;
  while (std::getline(history, row)) {
    if (row.empty()) continue;
    ++rows;
    const double energy = std::stod(row.substr(row.find(',') + 1));
    CHECK(energy == Approx(4e9).epsilon(1e-9));
  }
  CHECK(rows >= 2);
}

TEST_CASE("scene: scale turns a mesh in millimetres into metres", "[scene][inp]") {
  test::TempDir dir;
  // The 10-unit cube read with scale = 0.001: the cube [0, 0.01]^3.
  const auto scene =
      dir.write("s.toml", body_from("abaqusreader_cube_tet4.inp") + "scale = 0.001\n");
  const Model model = build_model(parse_scene_file(scene));
  Vec3 top = Vec3::Zero();
  for (const Vec3& x : model.mesh.X) top = top.cwiseMax(x);
  CHECK(top.isApprox(Vec3::Constant(0.01), 1e-15));
  const auto bad = dir.write("bad.toml", body_from("abaqusreader_cube_tet4.inp") + "scale = 0\n");
  std::string message = "(no error)";
  try {
    parse_scene_file(bad);
  } catch (const ConfigError& e) {
    message = e.what();
  }
  CHECK(message == bad.string() + ":12: bodies[0].geometry.scale: must be > 0 (got 0)");
}
