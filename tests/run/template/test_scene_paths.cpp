// Paths into a scene's TOML document (run/template/scene_paths.hpp): bodies by name, array
// elements by index, numbers set in place, and the message for a path that leads nowhere.
#include <catch2/catch.hpp>

#include "config/strict_table.hpp"
#include "run/template/scene_paths.hpp"
#include "tests/support/scene_fixtures.hpp"

using namespace ccm;
using Catch::Contains;

namespace {
toml::table strike_document() { return parse_toml(test::kStrikeScene, "strike.toml"); }
}  // namespace

TEST_CASE("scene paths: a body by name, a vector component by index, a table key",
          "[template][paths]") {
  const toml::table doc = strike_document();
  CHECK(number_at_path(doc, "bodies.striker.material.E") == 1e7);
  CHECK(number_at_path(doc, "bodies.base.material.E") == 1e5);
  CHECK(number_at_path(doc, "bodies[1].material.E") == 1e7);
  CHECK(number_at_path(doc, "bodies.striker.initial_velocity[2]") == -1.0);
  CHECK(number_at_path(doc, "time.end") == 2e-3);
  CHECK(number_at_path(doc, "bodies.striker.initial_velocity") == 1.0);  // a vector's magnitude
  // Not numbers, or not there.
  CHECK_FALSE(number_at_path(doc, "contact.surfaces"));
  CHECK_FALSE(number_at_path(doc, "bodies.striker.name"));
  CHECK_FALSE(number_at_path(doc, "bodies.strikr.material.E"));
  CHECK_FALSE(number_at_path(doc, "bodies.striker.initial_velocity[3]"));
  CHECK_FALSE(number_at_path(doc, "time..end"));
  CHECK_FALSE(number_at_path(doc, "time.end[0"));
}

TEST_CASE("scene paths: every number's path is listed, and each leads to its number",
          "[template][paths]") {
  const toml::table doc = strike_document();
  const std::vector<std::string> paths = number_paths(doc);
  // time 2; base: material 3, size 1 + 3, mesh_size 1; striker: those 8 and velocity 1 + 3,
  // translate 1 + 3 (a vector, then its components).
  CHECK(paths.size() == 26);
  for (const std::string& p : paths) CHECK(number_at_path(doc, p).has_value());
  CHECK(std::find(paths.begin(), paths.end(), "bodies.striker.placement.translate[2]") !=
        paths.end());
}

TEST_CASE("scene paths: a number is set in place, an integer stays one or is refused",
          "[template][paths]") {
  toml::table doc = strike_document();
  set_number_at_path(doc, "bodies.striker.material.E", 2.5e8);
  set_number_at_path(doc, "bodies.striker.initial_velocity[2]", -3.0);
  CHECK(number_at_path(doc, "bodies.striker.material.E") == 2.5e8);
  CHECK(number_at_path(doc, "bodies.striker.initial_velocity[2]") == -3.0);
  CHECK(number_at_path(doc, "bodies.base.material.E") == 1e5);  // the other body is untouched

  toml::table steps = parse_toml("[time]\nend = 1.0\nmax_steps = 100\n", "s.toml");
  set_number_at_path(steps, "time.max_steps", 200.0);
  CHECK(steps["time"]["max_steps"].is_integer());
  CHECK(steps["time"]["max_steps"].value<long>() == 200);
  CHECK_THROWS_WITH(set_number_at_path(steps, "time.max_steps", 2.5),
                    Contains("is an integer in the scene; 2.5 is not"));
  CHECK_THROWS_WITH(set_number_at_path(steps, "time.start", 1.0),
                    Contains("no number at path \"time.start\""));
}

TEST_CASE("scene paths: a vector's path sets its magnitude, its direction kept",
          "[template][paths]") {
  toml::table doc = parse_toml("v = [3, 0, -4]\nzero = [0.0, 0.0]\n", "s.toml");
  CHECK(number_at_path(doc, "v") == 5.0);
  set_number_at_path(doc, "v", 10.0);
  CHECK(doc["v"][0].value<double>() == 6.0);
  CHECK(doc["v"][2].value<double>() == -8.0);
  CHECK(doc["v"][0].is_floating_point());  // integers become floats
  set_number_at_path(doc, "v", -5.0);      // reversed
  CHECK(doc["v"][0].value<double>() == -3.0);
  CHECK(doc["v"][2].value<double>() == 4.0);
  CHECK_THROWS_WITH(set_number_at_path(doc, "zero", 1.0),
                    Contains("\"zero\" is a zero vector in the scene") &&
                        Contains("sweep its components (\"zero[0]\""));
}

TEST_CASE("scene paths: a path that leads nowhere names the nearest path, or those under it",
          "[template][paths]") {
  const toml::table doc = strike_document();
  CHECK_THAT(path_problem(doc, "bodies.strikr.material.E"),
             Contains("did you mean \"bodies.striker.material.E\"?"));
  const std::string under = path_problem(doc, "bodies.striker.material.Young");
  CHECK_THAT(under, Contains("paths under \"bodies.striker.material\""));
  CHECK_THAT(under,
             Contains("bodies.striker.material.E") && Contains("bodies.striker.material.nu"));
  CHECK_THAT(path_problem(doc, "nothing.here.at.all"), Contains("its paths begin bodies.base."));
}
