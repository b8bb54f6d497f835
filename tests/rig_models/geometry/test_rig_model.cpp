// The rig as an engine model (rig_models/geometry/): the parts meshed conformingly, the
// densities tuned so that the impactor and the artifact have the case file's masses and the
// artifact its moment of inertia about the pin, and every named set where the geometry file
// puts it: the pin's bore, the track guide, the drive surface, the sensor patch with its area,
// the contact surfaces and the tracked nodes. And the geometry file's bad input named by file,
// line and key.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "engine/mesh/boundary_surface.hpp"
#include "rig_models/cases/case_file.hpp"
#include "rig_models/core/rig_error.hpp"
#include "rig_models/geometry/geometry_file.hpp"
#include "rig_models/geometry/rig_model.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;
using namespace ccm::rig;
using test::relative_error;

namespace {

const std::filesystem::path kRig = std::filesystem::path(CCM_SOURCE_DIR) / "rig_models";

const RigCaseTable& cases() {
  static const RigCaseTable t = read_case_table(kRig / "cases.toml");
  return t;
}

const RigGeometry& geometry() {
  static const RigGeometry g = read_geometry(kRig / "geometry.toml");
  return g;
}

RigModel model_of(ImpactorKind impactor, ArtifactKind artifact) {
  RigModelRequest req;
  req.impactor = impactor;
  req.artifact = artifact;
  req.gap = 0.005;
  return build_rig_model(geometry(), cases().rig, req);
}

std::string geometry_text() {
  std::ifstream in(kRig / "geometry.toml");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string error_of(const std::string& text) {
  try {
    parse_geometry(text, "geometry.toml");
  } catch (const RigInputError& e) {
    return e.what();
  }
  return "no error";
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

int line_of(const std::string& text, const std::string& what) {
  const size_t at = text.find(what);
  REQUIRE(at != std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

}  // namespace

TEST_CASE("rig model: tuned masses and inertia, parts joined, named sets in place",
          "[rig][rig-model]") {
  const RigParameters& rig = cases().rig;
  const ArtifactGeometry& a = geometry().artifact;
  for (const ImpactorKind kind : {ImpactorKind::rigid, ImpactorKind::flexible}) {
    const RigModel r = model_of(kind, ArtifactKind::fixed);
    const ModelMesh& mesh = r.model.mesh;
    const auto& X = mesh.X;
    INFO(name_of(kind) << ": " << mesh.n_elements() << " elements, J " << r.artifact_inertia
                       << ", sensor " << r.sensor_mesh_area << " m^2");
    // The densities are solved on the very lumped masses the integrator uses: round-off only.
    CHECK(relative_error(r.impactor_mass, rig.impactor_mass.value) < 1e-9);
    CHECK(relative_error(r.artifact_mass, rig.artifact_mass.value) < 1e-9);
    CHECK(relative_error(r.artifact_inertia, rig.artifact_inertia_pivot.value) < 1e-9);
    CHECK(r.artifact_cm_depth > 0.0);  // it hangs from the pin
    CHECK(mesh.bodies.size() == (kind == ImpactorKind::flexible ? 6u : 5u));
    // Parts are joined: the rod shares nodes with what holds it (carriage or spring).
    const auto& rod = mesh.node_sets.at("rod");
    const auto& holder = mesh.node_sets.at(kind == ImpactorKind::flexible ? "spring" : "carriage");
    std::vector<int> shared;
    std::set_intersection(rod.begin(), rod.end(), holder.begin(), holder.end(),
                          std::back_inserter(shared));
    CHECK(shared.size() >= 4);
    // The pin's bore: every node at the pin's radius about the x axis, on the core.
    REQUIRE(r.pin_nodes.size() >= 8);
    for (int n : r.pin_nodes)
      CHECK(std::hypot(X[n].y(), X[n].z()) == Approx(a.pin_diameter.value / 2).epsilon(1e-6));
    CHECK(r.model.bcs.fixed_nodes == r.pin_nodes);  // Fixed: all DOF of the pin nodes
    // The sensor: on the struck face of the envelope around the contact point, its meshed area
    // that of the patch to within the triangles cut by its edge (10 %; the pressure uses A_p).
    REQUIRE(!r.sensor_nodes.empty());
    for (int n : r.sensor_nodes) {
      CHECK(X[n].y() < 0.0);
      CHECK(std::abs(X[n].z() + rig.pivot_to_sensor.value) < a.sensor_height.value);
    }
    CHECK(relative_error(r.sensor_mesh_area, rig.sensor_area.value) < 0.10);
    // Tracked nodes: the pearls on the carriage's top, the angle node on the core's axis.
    CHECK(X[r.pearl_front].y() > X[r.pearl_back].y());
    CHECK(X[r.pearl_front].z() == Approx(X[r.pearl_back].z()));
    CHECK(X[r.angle_node].z() == Approx(-a.angle_node_depth.value).margin(0.015));
    // The drive surface (the bracket) faces the track on the carriage's front.
    double area = 0.0;
    for (const Triangle& t : r.drive_surface) {
      area += triangle_area(t, X);
      CHECK(triangle_normal(t, X).y() == Approx(1.0).margin(1e-9));
    }
    CHECK(area > 0.5 * geometry().impactor.carriage_width.value *
                     geometry().impactor.carriage_height.value);
    CHECK(r.contact_surfaces == std::vector<std::string>{"rod/tip", "envelope/contact_zone"});
    CHECK(r.rod_tip_y == Approx(-a.envelope_outer_diameter.value / 2 - 0.005));
    if (kind == ImpactorKind::flexible) {
      // eq. 3.1 on the meshed cross-section: E_s A / L = K_s
      CHECK(relative_error(r.spring_modulus * r.spring_area / rig.spring_length.value,
                           rig.spring_stiffness.value) < 1e-12);
    }
  }
}

TEST_CASE("rig model: a free artifact is not fixed, bad gap refused", "[rig][rig-model]") {
  const RigModel r = model_of(ImpactorKind::rigid, ArtifactKind::free);
  CHECK(r.model.bcs.fixed_nodes.empty());
  CHECK(!r.pin_nodes.empty());
  RigModelRequest req;
  req.gap = 0.0;
  CHECK_THROWS_WITH(build_rig_model(geometry(), cases().rig, req),
                    "rig model: the gap must be > 0 (got 0 m)");
}

TEST_CASE("rig geometry file: bad input names file, line and key", "[rig][rig-model]") {
  const std::string good = geometry_text();
  CHECK(error_of(good) == "no error");
  const int l_wall = line_of(good, "envelope_wall =");
  CHECK(
      error_of(with(good, "unit = \"m\", source = \"assumption: Schedule 40 wall",
                    "unit = \"mm\", source = \"assumption: Schedule 40 wall")) ==
      fmt::format("geometry.toml:{}: artifact.envelope_wall.unit: must be 'm' (got 'mm')", l_wall));
  CHECK(
      error_of(with(good, "envelope_wall = { value = 0.0039", "envelope_wall = { value = 0.04")) ==
      fmt::format("geometry.toml:{}: artifact.envelope_wall: must be less than half the "
                  "envelope's outer diameter",
                  l_wall));
  const int l_core = line_of(good, "core_width =");
  CHECK(error_of(with(good, "core_width = { value = 0.0254", "core_width = { value = 0.05")) ==
        fmt::format("geometry.toml:{}: artifact.core_width: the core's corners must lie inside "
                    "the envelope's bore (half-diagonal 0.03536 m, bore radius 0.02625 m)",
                    l_core));
  const int l_rod = line_of(good, "rod = {");
  CHECK(error_of(with(good, "rod = { value = 0.008", "rod = { value = 0.02")) ==
        fmt::format("geometry.toml:{}: mesh.rod: must not exceed the rod's radius", l_rod));
  CHECK(error_of(with(good, "[contact]", "[contacts]")) ==
        fmt::format("geometry.toml:{}: contacts: unknown key 'contacts' (did you mean "
                    "'contact'?)",
                    line_of(good, "[contact]")));
  // Against the case file: the sensor patch must have cases.toml's sensor_area.
  RigGeometry g = parse_geometry(good, "geometry.toml");
  g.artifact.sensor_width.value = 0.05;
  CHECK_THROWS_WITH(check_against_cases(g, cases().rig),
                    "geometry.toml: artifact.sensor_width: the sensor patch is 0.002 m^2, "
                    "cases.toml sensor_area is 0.0016 m^2");
}
