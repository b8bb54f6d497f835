// The project's own question on its own example (scenes/examples/pad_on_limb_dcr.toml): the same
// scene run by `ccm run` with its pad deformable and with `kind = "rigid"` added to the pad, as a
// user would. Both complete; the rigid pad's history holds its pose and the contact's impulse on
// it, and that impulse is exactly the momentum the pad lost (m dv_z, to the CSV's 17 digits and
// the round-off of 2,000 steps: 1e-9). [heavy]: 17 s under the sanitizers; the rigid pad's code
// runs there in tests/engine/body/test_rigid_contact.cpp.
#include <fmt/format.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "tests/support/temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

int ccm_run(const fs::path& scene, const fs::path& out) {
  const std::string command = fmt::format("'{}' run '{}' --out '{}' --quiet > /dev/null 2>&1",
                                          CCM_BINARY, scene.string(), out.string());
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

// The last row of a history.csv, by column name.
std::map<std::string, double> last_row(const fs::path& csv) {
  std::ifstream in(csv);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::map<std::string, double> row;
  std::stringstream h(header), v(last);
  std::string name, value;
  while (std::getline(h, name, ',') && std::getline(v, value, ',')) row[name] = std::stod(value);
  return row;
}

}  // namespace

TEST_CASE("ccm run: the pad-on-limb example with its pad deformable and rigid",
          "[rigid-body][cli][heavy]") {
  ccm::test::TempDir dir;
  const fs::path example = fs::path(CCM_SOURCE_DIR) / "scenes/examples/pad_on_limb_dcr.toml";
  std::stringstream whole;
  whole << std::ifstream(example).rdbuf();
  std::string text = whole.str();
  const std::string pad = "name = \"pad\"\n";
  const auto at = text.find(pad);
  REQUIRE(at != std::string::npos);
  text.insert(at + pad.size(), "kind = \"rigid\"\n");
  const fs::path copy = dir.write("pad_rigid.toml", text);  // the example uses no relative path

  REQUIRE(ccm_run(example, dir.path / "deformable") == 0);
  REQUIRE(ccm_run(copy, dir.path / "rigid") == 0);
  const auto d = last_row(dir.path / "deformable" / "history.csv");
  const auto r = last_row(dir.path / "rigid" / "history.csv");
  REQUIRE(r.count("pad.vz"));
  REQUIRE(r.count("pad.contact_impulse_z"));
  CHECK_FALSE(d.count("pad.qw"));  // a deformable pad has no pose columns
  REQUIRE(d.count("pad.vz"));      // but its centre-of-mass velocity
  const double mass = 1200.0 * 0.04 * 0.03 * 0.008, v0 = -1.0;
  CHECK(std::abs(mass * (r.at("pad.vz") - v0) - r.at("pad.contact_impulse_z")) <
        1e-9 * std::abs(r.at("pad.contact_impulse_z")));
  // The pad was stopped and thrown back by the limb in both runs.
  CHECK(r.at("pad.vz") > 0.0);
  CHECK(d.at("pad_centre.vz") > 0.0);
  CHECK(d.at("pad.vz") > 0.0);
}
