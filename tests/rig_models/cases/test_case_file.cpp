// The rig's case file rig_models/cases.toml: the 12 cases of thesis Table 3.2 with their
// parameters and sources, E_s from eq. 3.1, the printed table; bad input named by file, line
// and key.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "rig_models/cases/case_file.hpp"
#include "rig_models/cases/case_table.hpp"
#include "rig_models/core/rig_error.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::rig;
using ccm::test::relative_error;

namespace {

const std::filesystem::path kCaseFile =
    std::filesystem::path(CCM_SOURCE_DIR) / "rig_models" / "cases.toml";

std::string case_file_text() {
  std::ifstream in(kCaseFile);
  std::ostringstream s;
  s << in.rdbuf();
  REQUIRE(!s.str().empty());
  return s.str();
}

// The 1-based line of the character at `at` in `text`.
int line_at(const std::string& text, size_t at) {
  REQUIRE(at != std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

// The 1-based line of the first occurrence of `what` in `text`.
int line_of(const std::string& text, const std::string& what) {
  return line_at(text, text.find(what));
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& text) {
  try {
    parse_case_table(text, "cases.toml");
  } catch (const RigInputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("rig cases: the 12 cases of Table 3.2 in order, with speed and configuration", "[rig]") {
  const RigCaseTable table = read_case_table(kCaseFile);
  REQUIRE(table.cases.size() == 12);
  const char* codes[] = {"RX025", "RX050", "RX100", "FX025", "FX050", "FX100",
                         "RF025", "RF050", "RF100", "FF025", "FF050", "FF100"};
  const double speeds[] = {0.25, 0.50, 1.00};
  for (size_t i = 0; i < 12; ++i) {
    const RigCase& c = table.cases[i];
    INFO(c.code);
    CHECK(c.number == static_cast<int>(i) + 1);
    CHECK(c.code == codes[i]);
    CHECK(c.target_speed.value == speeds[i % 3]);
    CHECK(c.impactor == (i / 3 % 2 == 0 ? ImpactorKind::rigid : ImpactorKind::flexible));
    CHECK(c.artifact == (i < 6 ? ArtifactKind::fixed : ArtifactKind::free));
    CHECK(c.pivot_friction.has_value() == (i >= 6));
    CHECK(&table.find(codes[i]) == &c);
  }
  // thesis 3.4.2 and 3.4.4
  CHECK(table.find("RF025").pivot_friction->mu_s == 0.2);
  CHECK(table.find("RF025").pivot_friction->mu_k == 0.1);
  CHECK(table.find("FF025").pivot_friction->mu_s == 0.4);
  CHECK(table.find("FF025").pivot_friction->mu_k == 0.7);
  CHECK_THROWS_AS(table.find("XX000"), std::out_of_range);
}

TEST_CASE("rig cases: the thesis's numbers, and E_s = K_s L / A (eq. 3.1)", "[rig]") {
  const RigCaseTable table = read_case_table(kCaseFile);
  const RigParameters& r = table.rig;
  CHECK(r.spring_stiffness.value == 1895.0);  // thesis 3.2.2
  CHECK(r.hanging_mass.value == 0.5);         // thesis 3.2.2
  CHECK(r.pressure_rate.value == 128.0);      // thesis 3.3.3
  CHECK(r.low_pass_cutoff.value == 64.0);     // thesis 3.3.3
  CHECK(r.trials_per_case.value == 3.0);      // thesis 3.2.2
  CHECK(r.spring_stiffness.source.starts_with("thesis"));
  CHECK(r.impactor_mass.source.starts_with("assumption"));
  // 1895 N/m x 0.05 m / (pi 0.02^2 / 4 m^2) = 301,598.6 Pa (by hand)
  CHECK(relative_error(spring_modulus(r), 301598.6171591417) < 1e-12);
  // and the cylinder's axial stiffness E A / L gives K_s back
  CHECK(relative_error(spring_modulus(r) * spring_cylinder_area(r) / r.spring_length.value,
                       1895.0) < 1e-14);
}

TEST_CASE("rig cases: the printed table has every case and every parameter with its source",
          "[rig]") {
  const RigCaseTable table = read_case_table(kCaseFile);
  const std::string text = format_case_table(table);
  // heading, 20 rig rows, E_s; drive heading and its 9 rows; blank, header, 12 cases
  CHECK(std::count(text.begin(), text.end(), '\n') == 1 + 20 + 1 + 1 + 9 + 1 + 1 + 12);
  CHECK_THAT(text, Catch::Contains("string stiffness                   5000 N/m     assumption"));
  CHECK_THAT(text,
             Catch::Contains(" 1  RX025         0.25  rigid     fixed     clamped (rig table)"));
  CHECK_THAT(text,
             Catch::Contains("12  FF100         1.00  flexible  free      mu_s 0.4, mu_k 0.7"));
  CHECK_THAT(text, Catch::Contains("spring stiffness K_s               1895 N/m     thesis"));
  CHECK_THAT(text, Catch::Contains("spring cylinder E_s              301599 Pa      eq. 3.1"));
}

TEST_CASE("rig cases: bad input names file, line and key", "[rig]") {
  const std::string good = case_file_text();
  const int l_ks = line_of(good, "spring_stiffness =");
  CHECK(error_of(with(good, "unit = \"N/m\"", "unit = \"N/mm\"")) ==
        fmt::format("cases.toml:{}: rig.spring_stiffness.unit: must be 'N/m' (got 'N/mm')", l_ks));
  CHECK(error_of(with(good, "value = 1895.0", "value = -1895.0")) ==
        fmt::format("cases.toml:{}: rig.spring_stiffness.value: must be > 0 (got -1895)", l_ks));
  const int l_track = line_of(good, "track_friction =");
  CHECK(
      error_of(with(good, "track_friction = { value = 0.01", "track_friction = { value = -0.01")) ==
      fmt::format("cases.toml:{}: drive.track_friction.value: must be >= 0 (got -0.01)", l_track));
  CHECK(error_of(with(good, "spring_stiffness =", "spring_stifness =")) ==
        fmt::format("cases.toml:{}: rig.spring_stifness: unknown key 'spring_stifness' (did you "
                    "mean 'spring_stiffness'?)",
                    l_ks));
  CHECK(error_of(with(good, "value = 1895.0, ", "")) ==
        fmt::format("cases.toml:{}: rig.spring_stiffness.value: required key is missing", l_ks));
  CHECK(error_of(with(good, "value = 1895.0", "value = \"1895\"")) ==
        fmt::format("cases.toml:{}: rig.spring_stiffness.value: expected a number, got a string",
                    l_ks));
  CHECK(error_of(with(good, "value = 64.0", "value = 65.0")) ==
        fmt::format("cases.toml:{}: rig.low_pass_cutoff: 65 Hz is above the Nyquist frequency "
                    "of the 128 Hz pressure sensor",
                    line_of(good, "low_pass_cutoff =")));
}

TEST_CASE("rig cases: a case that disagrees with Table 3.2 or with its own code", "[rig]") {
  const std::string good = case_file_text();
  const int l_code = line_of(good, "code = \"RX050\"");
  CHECK(error_of(with(good, "code = \"RX050\"", "code = \"RX055\"")) ==
        fmt::format("cases.toml:{}: cases[1].code: 'RX055' is not a case code of thesis Table "
                    "3.2 (RX025 ... FF100)",
                    l_code));
  CHECK(error_of(with(good, "code = \"RX050\"", "code = \"FX050\"")) ==
        fmt::format("cases.toml:{}: cases[1].code: case 2 of Table 3.2 is 'RX050', not 'FX050'",
                    l_code));
  const std::string rx050 = good.substr(good.find("code = \"RX050\""));
  const int l_imp = l_code + line_of(rx050, "impactor = \"rigid\"") - 1;
  CHECK(error_of(with(good,
                      "code = \"RX050\"\ntarget_speed = { value = 0.50, unit = \"m/s\", "
                      "source = \"thesis Table 3.2\" }\nimpactor = \"rigid\"",
                      "code = \"RX050\"\ntarget_speed = { value = 0.50, unit = \"m/s\", "
                      "source = \"thesis Table 3.2\" }\nimpactor = \"flexible\"")) ==
        fmt::format("cases.toml:{}: cases[1].impactor: 'flexible' disagrees with the code "
                    "'RX050'",
                    l_imp));
  CHECK(error_of(with(good, "value = 0.50, unit = \"m/s\"", "value = 0.55, unit = \"m/s\"")) ==
        fmt::format("cases.toml:{}: cases[1].target_speed: 0.55 m/s disagrees with the code "
                    "'RX050'",
                    l_code + 1));
  CHECK(error_of(with(good, "impactor = \"rigid\"", "impactor = \"stiff\"")) ==
        fmt::format("cases.toml:{}: cases[0].impactor: 'stiff' is not one of: rigid, flexible",
                    line_of(good, "impactor = \"rigid\"")));
}

TEST_CASE("rig cases: duplicated, missing, friction where it does not belong", "[rig]") {
  const std::string good = case_file_text();
  // the last case removed: FF100 is missing
  const std::string eleven = good.substr(0, good.rfind("[[cases]]"));
  CHECK(error_of(eleven) ==
        fmt::format("cases.toml:{}: cases: case 12 (FF100) of Table 3.2 is missing",
                    line_of(good, "[[cases]]")));
  // the first case given twice, appended at the end
  const size_t first_at = good.find("[[cases]]");
  const std::string first = good.substr(first_at, good.find("[[cases]]", first_at + 1) - first_at);
  const std::string twice = good + first;
  CHECK(error_of(twice) == fmt::format("cases.toml:{}: cases[12].number: case 1 is given twice",
                                       line_at(twice, twice.rfind("number = 1\n"))));
  // a fixed artifact with pivot friction; a free one without
  CHECK(error_of(with(good, "artifact = \"fixed\"",
                      "artifact = \"fixed\"\npivot_friction = { mu_s = 1.0, mu_k = 0.5, "
                      "source = \"x\" }")) ==
        fmt::format("cases.toml:{}: cases[0].pivot_friction: a fixed artifact is held by the "
                    "pin's clamp ([rig] clamp_stiffness, clamp_damping); pivot friction is for "
                    "free artifacts",
                    line_of(good, "artifact = \"fixed\"") + 1));
  const int l_rf025 = line_of(good, "[[cases]]\nnumber = 7");
  CHECK(error_of(with(good,
                      "pivot_friction = { mu_s = 0.2, mu_k = 0.1, source = \"thesis "
                      "3.4.2 (RF025; its later text swaps the two)\" }\n",
                      "")) ==
        fmt::format("cases.toml:{}: cases[6].pivot_friction: required table is missing", l_rf025));
  CHECK(error_of("[rig\n") ==
        "cases.toml:1: Error while parsing table header: expected ']', "
        "saw '\\n'");
}
