// The mesh file dispatcher (by extension), a Gmsh tutorial script meshed with its own sizes, and
// the quality figures of `ccm mesh info` against closed forms.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "engine/element/mesh_quality.hpp"
#include "engine/element/tet4.hpp"
#include "engine/mesh/readers/mesh_file.hpp"
#include "tests/engine/mesh/readers/mesh_test_files.hpp"

using namespace ccm;

TEST_CASE("mesh files: chosen by extension, any case, unknown ones named", "[mesh]") {
  test::TempDir dir;
  const auto upper = dir.write("BOX.UNV", test::file_text(test::mesh_data("elmer_box.unv")));
  const MeshFile m = read_mesh_file_with_report(upper);
  CHECK(m.report.format == "I-DEAS universal");
  CHECK(m.mesh.n_elements() == 2308);
  CHECK(read_mesh_file(test::mesh_data("abaqusreader_cube_tet4.inp")).n_elements() == 17);
  const auto stl = dir.write("part.stl", "solid x\nendsolid x\n");
  CHECK(test::mesh_error_of([&] { read_mesh_file(stl); }) ==
        stl.string() + ": unknown mesh file type '.stl' (known: .msh, .unv, .inp, .geo)");
  CHECK(test::mesh_error_of([&] { read_mesh_file(dir.path / "gone.inp"); }) ==
        (dir.path / "gone.inp").string() + ": no such file");
}

TEST_CASE("mesh files: Gmsh tutorial t16.geo is meshed with its own mesh sizes", "[mesh][gmsh]") {
  // Gmsh 4.8.4's tutorial/t16.geo: the unit cube minus the cube [0, 0.5]^3 (volume 7/8), five
  // balls inside as separate volumes, mesh size 0.1 at the corners, 0.055 on the balls and 5e-4
  // at the point (0.5, 0.5, 0.5).
  const MeshFile m = read_mesh_file_with_report(test::mesh_data("gmsh_t16.geo"));
  CHECK(m.report.format == "Gmsh script, meshed by Gmsh");
  // The faces of the cubes are planes, the balls' facets are shared by the volumes on both sides:
  // the total is 7/8 up to round-off.
  CHECK(mesh_volume(m.mesh) == Approx(0.875).epsilon(1e-10));
  const MeshQuality q = mesh_quality(m.mesh);
  CHECK(q.box_min.isApprox(Vec3::Zero()));
  CHECK(q.box_max.isApprox(Vec3::Ones()));
  // The script's size of 5e-4 at (0.5, 0.5, 0.5) is honoured: tets there are far below the
  // size 0.055 of a mesh that ignored it (h_e is a fraction of the edge length).
  CHECK(q.min_h < 5e-4);
  const Tet& finest = m.mesh.tets[static_cast<size_t>(q.min_h_tet)];
  CHECK((m.mesh.nodes[static_cast<size_t>(finest[0])] - Vec3::Constant(0.5)).norm() < 0.01);
}

TEST_CASE("mesh quality: dihedral angles and h_e of two tets with known values", "[mesh]") {
  // The corner tet (0, e1, e2, e3): right dihedral angles at the three edges through the origin,
  // acos(1/sqrt(3)) = 54.7356 deg at the three edges of the slanted face; h_e = 1/sqrt(6)
  // (|grad N_a|^2 = 1, 1, 1, 3; tet4.hpp).
  const TetMesh corner{
      {Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()}, {{0, 1, 2, 3}}, {}, {}, {}, {}};
  const MeshQuality c = mesh_quality(corner);
  CHECK(c.min_dihedral_deg == Approx(std::acos(1 / std::sqrt(3.0)) * 180 / std::numbers::pi));
  CHECK(c.max_dihedral_deg == Approx(90.0));
  CHECK(c.min_h == Approx(1 / std::sqrt(6.0)));
  CHECK(c.volume == Approx(1.0 / 6.0));
  // The regular tet: every dihedral angle is acos(1/3) = 70.5288 deg.
  const TetMesh regular{{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)},
                        {{0, 1, 2, 3}},
                        {},
                        {},
                        {},
                        {}};
  const MeshQuality r = mesh_quality(regular);
  const double expected = std::acos(1.0 / 3.0) * 180 / std::numbers::pi;
  CHECK(r.min_dihedral_deg == Approx(expected).epsilon(1e-12));
  CHECK(r.max_dihedral_deg == Approx(expected).epsilon(1e-12));
}
