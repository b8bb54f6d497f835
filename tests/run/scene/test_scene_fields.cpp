// `[output] fields` and `field_interval` in a scene file (docs/scene-file.md, docs/fields.md):
// the names of the field catalogue are accepted, anything else is refused naming the file, the
// line and the entry, with the closest name when one is near.
#include <catch2/catch.hpp>
#include <string>

#include "run/scene/scene_file.hpp"
#include "tests/support/scene_fixtures.hpp"

using namespace ccm;

namespace scene_fields_test {

// The one-cube scene (lines 1-12) with an [output] table from line 13.
std::string with_output(const std::string& output) {
  return test::kOneCubeScene + "[output]\n" + output;
}

}  // namespace scene_fields_test

using namespace scene_fields_test;

TEST_CASE("Scene fields: the catalogue's names, the interval defaulting to the output's",
          "[fields][scene]") {
  const Scene none = parse_scene(test::kOneCubeScene, "s.toml");
  CHECK(none.output.fields.empty());
  CHECK(none.output.field_interval == none.time.output_interval);  // end / 100

  const Scene s =
      parse_scene(with_output("fields = [\"displacement\", \"velocity\", \"J\", \"von_mises\", "
                              "\"contact_pressure\", \"body_id\"]\nfield_interval = 3e-5\n"),
                  "s.toml");
  CHECK(s.output.fields == std::vector<FieldKind>{FieldKind::displacement, FieldKind::velocity,
                                                  FieldKind::J, FieldKind::von_mises,
                                                  FieldKind::contact_pressure, FieldKind::body_id});
  CHECK(s.output.field_interval == 3e-5);
}

TEST_CASE("Scene fields: bad names and intervals are refused with file, line and entry",
          "[fields][scene]") {
  using test::scene_error_of;
  CHECK(scene_error_of(with_output("fields = [\"displacement\", \"von_mise\"]\n")) ==
        "s.toml:14: output.fields[1]: must be one of \"displacement\", \"velocity\", \"J\", "
        "\"von_mises\", \"contact_pressure\", \"body_id\" (got \"von_mise\"; did you mean "
        "\"von_mises\"?)");
  CHECK(scene_error_of(with_output("fields = [\"stress\"]\n")) ==
        "s.toml:14: output.fields[0]: must be one of \"displacement\", \"velocity\", \"J\", "
        "\"von_mises\", \"contact_pressure\", \"body_id\" (got \"stress\")");
  CHECK(scene_error_of(with_output("fields = [\"J\", \"J\"]\n")) ==
        "s.toml:14: output.fields[1]: field 'J' is listed twice");
  CHECK(scene_error_of(with_output("fields = \"J\"\n")) ==
        "s.toml:14: output.fields: expected an array of field names, got a string");
  CHECK(scene_error_of(with_output("fields = [1]\n")) ==
        "s.toml:14: output.fields[0]: expected a string, got an integer");
  CHECK(scene_error_of(with_output("fields = [\"J\"]\nfield_interval = 2.5e-5\n")) ==
        "s.toml:15: output.field_interval: must be a whole multiple of the output interval 1e-05 "
        "s (got 2.5e-05 s)");
  CHECK(scene_error_of(with_output("fields = [\"J\"]\nfield_interval = 5e-6\n")) ==
        "s.toml:15: output.field_interval: must be a whole multiple of the output interval 1e-05 "
        "s (got 5e-06 s)");
  CHECK(scene_error_of(with_output("fields = [\"J\"]\nfield_interval = -1.0\n")) ==
        "s.toml:15: output.field_interval: must be > 0 (got -1)");
  CHECK(scene_error_of(with_output("field_interval = 1e-5\n")) ==
        "s.toml:14: output.field_interval: applies only with fields = [...]");
  CHECK(scene_error_of(with_output("feilds = [\"J\"]\n")) ==
        "s.toml:14: output.feilds: unknown key 'feilds' (did you mean 'fields'?)");
}
