// `ccm mesh info FILE [--json]` run as a user would: figures of a real file, JSON that parses,
// exit 2 with the file, line and dataset for a bad file.
#include <fmt/format.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
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
