// `ccm mesh info FILE [--json]` run as a user would: figures of a real file, JSON that parses,
// exit 2 with the file, line and dataset for a bad file.
#include <fmt/format.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "tests/engine/mesh/readers/mesh_test_files.hpp"

using Catch::Contains;

namespace {

struct MeshInfoOutput {
  int exit_code;
  std::string out, err;
};

MeshInfoOutput mesh_info(const ccm::test::TempDir& dir, const std::string& args) {
  const auto out = dir.path / "out.txt", err = dir.path / "err.txt";
  const std::string command =
      fmt::format("'{}' mesh info {} > '{}' 2> '{}'", CCM_BINARY, args, out.string(), err.string());
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  return {WEXITSTATUS(status), ccm::test::file_text(out), ccm::test::file_text(err)};
}

}  // namespace

TEST_CASE("ccm mesh info: a UNV file's counts, groups and quality", "[mesh][cli]") {
  ccm::test::TempDir dir;
  const std::string box = ccm::test::mesh_data("elmer_box.unv").string();
  const MeshInfoOutput text = mesh_info(dir, "'" + box + "'");
  CHECK(text.exit_code == 0);
  CHECK(text.err.empty());
  CHECK_THAT(text.out, Contains("  nodes           554\n  tets            2308\n"));
  CHECK_THAT(text.out, Contains("  volume          8e+06\n"));
  CHECK_THAT(text.out, Contains("x [0, 200]  y [0, 200]  z [0, 200]"));
  CHECK_THAT(text.out, Contains("  surface         side: 94 triangles, 62 nodes\n"));

  const MeshInfoOutput json = mesh_info(dir, "'" + box + "' --json");
  REQUIRE(json.exit_code == 0);
  const auto j = nlohmann::json::parse(json.out);
  CHECK(j["tets"] == 2308);
  CHECK(j["nodes"] == 554);
  CHECK(j["surfaces"]["top"]["triangles"] == 94);
  CHECK(j["bounding_box"]["max"] == nlohmann::json({200.0, 200.0, 200.0}));
  CHECK(j["volume"].get<double>() == Approx(8e6).epsilon(1e-12));
  const double min_angle = j["dihedral_angle_deg"]["min"],
               max_angle = j["dihedral_angle_deg"]["max"];
  CHECK(0 < min_angle);
  CHECK(min_angle < 70.53);  // no tet mesh of a box is all regular tets
  CHECK(max_angle > 70.53);
  CHECK(max_angle < 180);
  CHECK(j["smallest_h_e"]["value"].get<double>() > 0);
}

TEST_CASE("ccm mesh info: bad files exit 2 naming the file, line and dataset", "[mesh][cli]") {
  ccm::test::TempDir dir;
  const std::string mixed = ccm::test::mesh_data("unv2ccx_mixed.unv").string();
  const MeshInfoOutput wedge = mesh_info(dir, "'" + mixed + "'");
  CHECK(wedge.exit_code == 2);
  CHECK(wedge.out.empty());
  CHECK_THAT(wedge.err, Contains("ccm: error: " + mixed + ":303: dataset 2412 (elements)"));

  const std::string text = ccm::test::file_text(ccm::test::mesh_data("abaqusreader_cube_tet4.inp"));
  const std::string element_12 = "        12,         1,";  // cut inside element 12
  const size_t at = text.find(element_12);
  REQUIRE(at != std::string::npos);
  const auto cut = dir.write("cut.inp", text.substr(0, at + element_12.size()));
  const MeshInfoOutput truncated = mesh_info(dir, fmt::format("'{}'", cut.string()));
  CHECK(truncated.exit_code == 2);
  CHECK(truncated.err == "ccm: error: " + cut.string() +
                             ":24: *ELEMENT: element data ends after 2 of the 5 fields of a "
                             "C3D4\n");
  CHECK(mesh_info(dir, "").exit_code == 2);  // FILE is required
}

TEST_CASE("ccm mesh info: a sliver is named with its h_e and the stable step it implies",
          "[mesh][cli]") {
  ccm::test::TempDir dir;
  // Tet 1: the unit right tet, h_e = det D / sqrt(sum_f |n_f|^2) = 1 / sqrt(3 + 3) (three faces of
  // |n_f| = 1, the slanted one sqrt 3). Tet 2: a sliver, its apex eps above the centroid of its
  // base: |n_base| = 1, each side face |n_f| = 1/3 + O(eps^2), so h_e = eps / sqrt(4/3) to
  // relative O(eps^2) = 1e-6.
  const double eps = 1e-3;
  const auto file =
      dir.write("sliver.inp", fmt::format("*NODE\n1, 2, 0, 0\n2, 3, 0, 0\n3, 2, 1, 0\n"
                                          "4, 2, 0, 1\n5, 0, 0, 0\n6, 1, 0, 0\n"
                                          "7, 0, 1, 0\n8, {}, {}, {}\n"
                                          "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n"
                                          "2, 5, 6, 7, 8\n",
                                          1.0 / 3.0, 1.0 / 3.0, eps));
  // E 5 MPa, nu 0.4, rho 1000: c_d = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho)).
  const double c_d = std::sqrt(5e6 * 0.6 / (1.4 * 0.2 * 1000.0));
  const MeshInfoOutput out =
      mesh_info(dir, "'" + file.string() + "' --json --material 5e6,0.4,1000");
  REQUIRE(out.exit_code == 0);
  const auto j = nlohmann::json::parse(out.out);
  const double h_sliver = eps / std::sqrt(4.0 / 3.0), h_regular = 1.0 / std::sqrt(6.0);
  REQUIRE(j["worst_tets"].size() == 2);
  CHECK(j["worst_tets"][0]["tet"] == 2);
  CHECK(j["worst_tets"][0]["h_e"].get<double>() == Approx(h_sliver).epsilon(1e-5));
  CHECK(j["worst_tets"][0]["stable_step_s"].get<double>() == Approx(h_sliver / c_d).epsilon(1e-5));
  CHECK(j["median_h_e"].get<double>() == Approx(h_regular).epsilon(1e-12));
  CHECK(j["wave_speed_mps"].get<double>() == Approx(c_d).epsilon(1e-12));
  REQUIRE(j["notes"].size() == 1);
  CHECK_THAT(j["notes"][0].get<std::string>(), Contains("tet 2 is nearly degenerate"));
  // The regular tet alone: no note.
  const auto good = dir.write("one.inp",
                              "*NODE\n1, 2, 0, 0\n2, 3, 0, 0\n3, 2, 1, 0\n4, 2, 0, 1\n"
                              "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n");
  CHECK(
      nlohmann::json::parse(mesh_info(dir, "'" + good.string() + "' --json").out)["notes"].empty());
  // A material that is none: exit 2 naming the option, nothing on stdout.
  const MeshInfoOutput bad = mesh_info(dir, "'" + file.string() + "' --material 5e6,0.5,1000");
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Contains("--material E,NU,RHO: nu"));
  CHECK(bad.out.empty());
}

// Gmsh's library is loaded on first use (engine/mesh/gmsh_api.hpp): the dynamic loader's own
// report (LD_DEBUG=files, on stderr) names every library a process loads.
TEST_CASE("ccm loads Gmsh only when a command uses it", "[mesh][cli][gmsh]") {
  ccm::test::TempDir dir;
  const auto loads_gmsh = [&](const std::string& file) {
    const auto err = dir.path / "loader.txt";
    const std::string command = fmt::format(
        "LD_DEBUG=files '{}' mesh info '{}' > /dev/null 2> '{}'", CCM_BINARY, file, err.string());
    const int status = std::system(command.c_str());
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    const std::string loader = ccm::test::file_text(err);
    REQUIRE_THAT(loader, Contains("calling init:"));  // the report is there
    return loader.find("libgmsh") != std::string::npos;
  };
  CHECK_FALSE(loads_gmsh(ccm::test::mesh_data("elmer_box.unv").string()));
  CHECK(loads_gmsh(ccm::test::mesh_data("gmsh_t16.geo").string()));
}
