// Issue 34 item 1: thin-walled pipes crushed by a ball (scripts/crush-family.py, which writes the
// scenes and runs them with the ccm under test; docs/hard-scenes.md, "A thin wall crushed onto its
// support"). Every member must complete with its energy balance within 1 % (the script exits 1
// when one does not, and prints each member's line). The unit suite runs the issue's own scene (a
// 1 mm wall at 3 mm tets, held along its lowest line, 8 m/s, friction 0.3: 5.2 % and `unstable`
// before the projection's step bound, eq. PJ.1, docs/time-step.md; 0.33 % after it), [heavy]
// for its 9 s; [validation] runs it with 14 members spread over the axes (wall 1/3-2 mesh
// sizes, fixed or anvil, 2-20 m/s, friction 0-0.5; about 6 minutes), and 6 members of other
// pipes, balls and rubbers struck off-centre and off the vertical (`--unseen 6 --seed 1`: pipe
// radius 10-30 mm, ball radius 5-15 mm, tilt up to 30 degrees; about a minute).
#include <catch2/catch.hpp>
#include <string>

#include "tests/app/cli_shell.hpp"

namespace {

// unseen: members drawn beyond the family's geometry (--unseen, seed 1).
ccm::test::CommandOutput crush_family(int spread_members, int unseen = 0) {
  ccm::test::TempDir dir;
  return ccm::test::run_command(
      fmt::format("/usr/bin/python3 '{}/scripts/crush-family.py' --members {} --unseen {} "
                  "--seed 1 --ccm '{}' --out '{}'",
                  CCM_SOURCE_DIR, spread_members, unseen, CCM_BINARY,
                  (dir.path / "family").string()),
      dir);
}

}  // namespace

TEST_CASE("crush family: the issue's thin wall crushed at 8 m/s completes within 1 %",
          "[crush_family][heavy]") {
  const ccm::test::CommandOutput r = crush_family(0);
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(r.out.find("1 of 1 members complete within 1 %") != std::string::npos);
}

TEST_CASE("crush family: 15 members complete within 1 %", "[crush_family][validation]") {
  const ccm::test::CommandOutput r = crush_family(14);
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(r.out.find("15 of 15 members complete within 1 %") != std::string::npos);
}

TEST_CASE("crush family: 6 members beyond the family's geometry complete within 1 %",
          "[crush_family][validation]") {
  const ccm::test::CommandOutput r = crush_family(0, 6);
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(r.out.find("7 of 7 members complete within 1 %") != std::string::npos);
}
