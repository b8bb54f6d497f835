// The I-DEAS universal reader on files written by ElmerGrid's test suite and by Salome (through
// unv2ccx's examples): counts, volumes and group surfaces against closed forms and the files'
// own statements, then truncated and garbled copies.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "engine/mesh/readers/inp_reader.hpp"
#include "engine/mesh/readers/unv_reader.hpp"
#include "tests/engine/mesh/readers/mesh_test_files.hpp"

using namespace ccm;
using Catch::Contains;

TEST_CASE("unv: ElmerGrid's 200 x 200 x 200 box with the groups side and top", "[mesh][unv]") {
  const MeshFile m = read_unv_file(test::mesh_data("elmer_box.unv"));
  // Counts as the file states them: 554 nodes in dataset 2411; 2308 linear tets in 2412 (the
  // element count ElmerGrid's own test case.sif checks), 84 rods (FE descriptor 11) ignored.
  CHECK(m.mesh.n_nodes() == 554);
  CHECK(m.report.file_nodes == 554);
  CHECK(m.mesh.n_elements() == 2308);
  CHECK(m.report.inverted_tets == 0);
  CHECK(m.report.ignored.at("rod (11)") == 84);
  // The box [0, 200]^3: volume 8e6; a sum of 2308 positive terms, relative round-off ~1e-13.
  CHECK(mesh_volume(m.mesh) == Approx(8e6).epsilon(1e-12));
  // Groups of 94 triangles each: "side" is the face x = 200, "top" the face z = 200, each of area
  // 200^2 = 4e4, oriented out of the box (their area vectors point along +x and +z).
  REQUIRE(m.mesh.named_surfaces.size() == 2);
  const auto& side = m.mesh.named_surfaces.at("side");
  const auto& top = m.mesh.named_surfaces.at("top");
  CHECK(side.size() == 94);
  CHECK(top.size() == 94);
  const Vec3 a_side = test::area_vector(m.mesh, side), a_top = test::area_vector(m.mesh, top);
  CHECK(a_side.x() == Approx(4e4).epsilon(1e-12));
  CHECK(a_side.tail<2>().norm() < 1e-9 * 4e4);
  CHECK(a_top.z() == Approx(4e4).epsilon(1e-12));
  CHECK(a_top.head<2>().norm() < 1e-9 * 4e4);
  for (const Triangle& t : side)
    for (int n : t) CHECK(m.mesh.nodes[static_cast<size_t>(n)].x() == 200.0);
}

TEST_CASE("unv and inp: Salome's one-tet file and unv2ccx's conversion of it agree",
          "[mesh][unv][inp]") {
  const MeshFile unv = read_unv_file(test::mesh_data("unv2ccx_111.unv"));
  const MeshFile inp = read_inp_file(test::mesh_data("unv2ccx_111.inp"));
  for (const MeshFile* m : {&unv, &inp}) {
    REQUIRE(m->mesh.n_elements() == 1);
    REQUIRE(m->mesh.n_nodes() == 4);
    // Nodes (0,0,0), (1,0,0), (0.5,0.8,0), (0.5,0.3,0.8) as written (0.8 in single precision):
    // base 1 x 0.8 / 2, height 0.8, volume base * height / 3.
    const double y = 8.0000001192092896E-01;
    CHECK(mesh_volume(m->mesh) == Approx(0.5 * y * y / 3.0).epsilon(1e-14));
    // The file lists the tet as 1 3 2 4, a negative volume: read with two nodes swapped.
    CHECK(m->report.inverted_tets == 1);
    CHECK(m->report.inverted_labels == std::vector<long>{1});
    // Groups N1..N4 (UNV 2467) / NSETs N1..N4 hold node k alone.
    for (int k = 1; k <= 4; ++k)
      CHECK(m->mesh.named_node_sets.at(fmt::format("N{}", k)) == std::vector<int>{k - 1});
  }
  CHECK(unv.mesh.nodes == inp.mesh.nodes);
  CHECK(unv.mesh.tets == inp.mesh.tets);
}

TEST_CASE("unv: a mesh with wedges and bricks is refused at the first of them", "[mesh][unv]") {
  const auto file = test::mesh_data("unv2ccx_mixed.unv");
  CHECK(test::mesh_error_of([&] { read_unv_file(file); }) ==
        file.string() +
            ":303: dataset 2412 (elements): element 6 is a solid linear wedge (112) with 6 "
            "nodes; ccm reads linear tetrahedra (111, 4 nodes) only, and leaving the others out "
            "would lose their mass (the file holds 6 solid linear brick (115), 24 solid linear "
            "wedge (112), 1 solid parabolic brick (116), 8 solid parabolic tetrahedron (118), 12 "
            "solid parabolic wedge (113))");
  // The same counts as CalculiX CAE's deck of this model states (cae_mixed.inp: 24 C3D6, 6 C3D8,
  // 8 C3D10, 12 C3D15, 1 C3D20; test_inp_reader.cpp).
}

TEST_CASE("unv: truncated copies never crash and name the file", "[mesh][unv]") {
  test::TempDir dir;
  const std::string small = test::file_text(test::mesh_data("unv2ccx_111.unv"));
  // The small file cut after every line and inside lines (every 5th byte).
  std::vector<size_t> cuts_small = test::cut_points(small, 1, 0);
  for (size_t i = 0; i < small.size(); i += 5) cuts_small.push_back(i);
  CHECK(test::read_truncated(dir, "t.unv", small, cuts_small,
                             [](const auto& f) { read_unv_file(f); }) > 0);
  // Every 250th line of the 370 kB box and 20 cuts in the middle of lines.
  const std::string box = test::file_text(test::mesh_data("elmer_box.unv"));
  const auto cuts = test::cut_points(box, 250, 20);
  CHECK(test::read_truncated(dir, "t.unv", box, cuts, [](const auto& f) { read_unv_file(f); }) ==
        static_cast<int>(cuts.size()));
}

TEST_CASE("unv: garbled fields name the line and the dataset", "[mesh][unv]") {
  test::TempDir dir;
  const std::string text = test::file_text(test::mesh_data("unv2ccx_111.unv"));
  const auto error_with = [&](const std::string& from, const std::string& to) {
    std::string edited = text;
    const size_t at = edited.find(from);
    REQUIRE(at != std::string::npos);
    edited.replace(at, from.size(), to);
    const auto file = dir.write("g.unv", edited);
    return test::mesh_error_of([&] { read_unv_file(file); });
  };
  const std::string f = (dir.path / "g.unv").string();
  CHECK(error_with("   1.0000000000000000E+00   0.0000000000000000E+00",
                   "   1.0000000000000000E+0x   0.0000000000000000E+00") ==
        f + ":23: dataset 2411 (nodes): coordinates of node 2: '1.0000000000000000E+0x' is not "
            "a finite number");
  CHECK(error_with("   1.0000000000000000E+00   0.0000000000000000E+00",
                   "   1.0000000000000000E+999   0.0000000000000000E+00") ==
        f + ":23: dataset 2411 (nodes): coordinates of node 2: '1.0000000000000000E+999' is not "
            "a finite number");
  CHECK_THAT(error_with("         1       111         2         1         7         4",
                        "         1       111         2         1         7        -4"),
             Contains(f + ":31: dataset 2412 (elements): element 1: node count -4 is out of "
                          "range"));
  CHECK(error_with("         1         3         2         4\n",
                   "         1         3         2         9\n") ==
        f + ":31: dataset 2412 (elements): element 1 uses node 9, which is not defined");
  CHECK(error_with("         1         3         2         4\n",
                   "         1         3         2         2\n") ==
        f + ":31: dataset 2412 (elements): element 1 has zero volume (its nodes are repeated or "
            "coplanar)");
  CHECK(error_with("         7         4         0         0",
                   "         7        44         0         0") ==
        f + ":46: dataset 2467 (groups): set 'N4' names node 44, which is not defined");
  CHECK(error_with("  2412\n", "  2412b\n") ==
        f + ":30: dataset 2412 (elements): binary datasets are not supported (export the "
            "universal file as ASCII)");
}
