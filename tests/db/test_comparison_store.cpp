// `ccm compare`'s records in the store (db/store/comparison_store.hpp, schema step 6) and the
// report's section of them (reports/figures/comparison_section.hpp): a record reads back field
// for field, a store before step 6 is migrated to take one, and the section counts how often the
// prediction held.
#include <catch2/catch.hpp>

#include "db/store/comparison_store.hpp"
#include "db/store/study_store.hpp"
#include "reports/figures/comparison_section.hpp"
#include "tests/db/scratch_dir.hpp"

using namespace ccm;

namespace {

db::ComparisonRow row(std::string answer, std::string predicted, std::optional<bool> agrees) {
  db::ComparisonRow r;
  r.scene = "scenes/examples/pad_on_limb_dcr.toml";
  r.deformable_hash = "a1";
  r.rigid_hash = "b2";
  r.rigid_bodies = "pad";
  r.observables = "limb.u_mean,limb.u_max,limb.kinetic_energy";
  r.max_error = 0.1;
  r.worst_error = 0.0226;
  r.cost_ratio = 1.3;
  r.answer = std::move(answer);
  r.predicted = std::move(predicted);
  r.agrees = agrees;
  r.document = "{}";
  return r;
}

}  // namespace

TEST_CASE("comparison store: a record reads back, and the report counts the predictions that held",
          "[compare][store]") {
  test::ScratchDir dir("comparisons");
  const auto file = dir / "s.sqlite";
  { db::StudyStore create(file); }  // an empty store at the latest schema
  CHECK_THROWS_AS(db::record_comparison(dir / "none.sqlite", row("rigid", "", {})), db::StoreError);
  CHECK(db::record_comparison(file, row("rigid", "deformable", false)) == 1);
  CHECK(db::record_comparison(file, row("rigid", "rigid", true)) == 2);
  db::StudyStore store(file, db::Access::read_only);
  const std::vector<db::ComparisonRow> rows = db::load_comparisons(store.connection());
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].scene == "scenes/examples/pad_on_limb_dcr.toml");
  CHECK(rows[0].worst_error == 0.0226);
  CHECK(rows[0].cost_ratio == 1.3);
  CHECK(rows[0].answer == "rigid");
  CHECK(rows[0].predicted == "deformable");
  CHECK(rows[0].agrees == false);
  CHECK(rows[1].agrees == true);
  CHECK(!rows[0].recorded_at.empty());

  const reports::Section s = reports::comparison_section(rows);
  REQUIRE(s.tables.size() == 1);
  CHECK(s.tables[0].rows.size() == 2);
  CHECK_THAT(s.paragraphs.at(0), Catch::Contains("held in 1 of the 2"));
  CHECK_THAT(reports::comparison_section({}).paragraphs.at(0),
             Catch::Contains("No design compared yet"));
}
