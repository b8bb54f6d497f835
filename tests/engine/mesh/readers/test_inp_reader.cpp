// The Abaqus/CalculiX reader on files from AbaqusReader.jl's test suite (one of them a HyperMesh
// export) and CalculiX CAE's examples: counts, volumes, sets and face-based surfaces against
// closed forms, then the keyword forms the real files do not use (GENERATE, *INCLUDE, free-face
// and node surfaces), truncated copies and bad fields.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "engine/mesh/readers/inp_reader.hpp"
#include "tests/engine/mesh/readers/mesh_test_files.hpp"

using namespace ccm;
using Catch::Contains;

namespace {

// `text` with `from` (which must occur) replaced by `to`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// Every node of the set has coordinate `axis` equal to `value`.
bool all_at(const MeshFile& m, const std::string& set, int axis, double value) {
  for (int n : m.mesh.named_node_sets.at(set))
    if (m.mesh.nodes[static_cast<size_t>(n)][axis] != value) return false;
  return true;
}

}  // namespace

TEST_CASE("inp: the 10 m cube of 17 C3D4 with symmetry sets and a loaded face", "[mesh][inp]") {
  // The same deck twice: upper-case keywords, and keywords and names in mixed case (names keep
  // the spelling of the file).
  struct Deck {
    const char* file;
    std::string sym12, sym23, sym13, load;
  };
  for (const Deck& d :
       {Deck{"abaqusreader_cube_tet4.inp", "SYM12", "SYM23", "SYM13", "LOAD"},
        Deck{"abaqusreader_cube_tet4_mixed_case.inp", "Sym12", "Sym23", "Sym13", "Load"}}) {
    INFO(d.file);
    const MeshFile m = read_inp_file(test::mesh_data(d.file));
    CHECK(m.mesh.n_nodes() == 10);
    CHECK(m.mesh.n_elements() == 17);
    CHECK(m.report.inverted_tets == 0);
    // The cube [0, 10]^3: volume 1000 (17 terms, round-off ~1e-13 relative).
    CHECK(mesh_volume(m.mesh) == Approx(1000).epsilon(1e-12));
    // SYM12, SYM23, SYM13: the four corners of the faces z = 0, x = 0, y = 0.
    CHECK(m.mesh.named_node_sets.at(d.sym12).size() == 4);
    CHECK(all_at(m, d.sym12, 2, 0.0));
    CHECK(all_at(m, d.sym23, 0, 0.0));
    CHECK(all_at(m, d.sym13, 1, 0.0));
    // LOAD = faces S1 of elements 16 and 8: the top face z = 10, area 100, normal +z (outward).
    const Vec3 load = test::area_vector(m.mesh, m.mesh.named_surfaces.at(d.load));
    CHECK(load.z() == Approx(100).epsilon(1e-14));
    CHECK(load.head<2>().norm() < 1e-12);
  }
}

TEST_CASE("inp: HyperMesh's two-part unit cube with contact surfaces", "[mesh][inp]") {
  const MeshFile m = read_inp_file(test::mesh_data("hypermesh_tet4.inp"));
  CHECK(m.mesh.n_nodes() == 116);          // "**NSET COUNT = 116" in the file's header
  CHECK(m.mesh.n_elements() == 172 + 92);  // "**ELSET COUNT" of UPPER and LOWER
  CHECK(mesh_volume(m.mesh) == Approx(1.0).epsilon(1e-12));  // the unit cube
  // Two parts (ELSET= on each *ELEMENT) that meet at z = 0.5 without sharing a node (their
  // corners coincide): two regions, so the coincident corners are parts that meet, not a cut.
  CHECK(m.mesh.region_names == std::vector<std::string>{"UPPER", "LOWER"});
  // The parts share no node: 71 + 45 = 116.
  const auto& upper = m.mesh.named_node_sets.at("UPPER");
  const auto& lower = m.mesh.named_node_sets.at("LOWER");
  CHECK(upper.size() + lower.size() == 116);
  // The interface: LOWER_TO_UPPER on the lower part faces +z, UPPER_TO_LOWER on the upper part
  // faces -z; both are the whole cross-section (area 1) at one height z0, and the lower part's
  // tets fill [0, 1]^2 x [0, z0] (volume z0).
  const auto& lower_to_upper = m.mesh.named_surfaces.at("LOWER_TO_UPPER");
  const auto& upper_to_lower = m.mesh.named_surfaces.at("UPPER_TO_LOWER");
  const double z0 = m.mesh.nodes[static_cast<size_t>(lower_to_upper[0][0])].z();
  for (const auto* surface : {&lower_to_upper, &upper_to_lower})
    for (const Triangle& t : *surface)
      for (int n : t) CHECK(m.mesh.nodes[static_cast<size_t>(n)].z() == Approx(z0).margin(1e-12));
  CHECK(test::area_vector(m.mesh, lower_to_upper).z() == Approx(1.0).epsilon(1e-12));
  CHECK(test::area_vector(m.mesh, upper_to_lower).z() == Approx(-1.0).epsilon(1e-12));
  double lower_volume = 0;
  const std::set<int> in_lower(lower.begin(), lower.end());
  for (const Tet& t : m.mesh.tets)
    if (in_lower.count(t[0])) {
      TetMesh one{m.mesh.nodes, {t}, {}, {}, {}, {}};
      lower_volume += mesh_volume(one);
    }
  CHECK(lower_volume == Approx(z0).epsilon(1e-12));
  CHECK(test::area_vector(m.mesh, m.mesh.named_surfaces.at("LOWER_BOTTOM")).z() ==
        Approx(-1.0).epsilon(1e-12));
  CHECK(test::area_vector(m.mesh, m.mesh.named_surfaces.at("UPPER_TOP")).z() ==
        Approx(1.0).epsilon(1e-12));
}

TEST_CASE("inp: a mesh with C3D6 and other solids is refused at their *ELEMENT", "[mesh][inp]") {
  const auto file = test::mesh_data("cae_mixed.inp");
  CHECK(test::mesh_error_of([&] { read_inp_file(file); }) ==
        file.string() +
            ":186: *ELEMENT: element type C3D6 is not supported: ccm reads linear tetrahedra "
            "(C3D4) only, and leaving the others out would lose their mass (the deck holds 8 "
            "C3D10, 12 C3D15, 1 C3D20, 24 C3D6, 6 C3D8)");
}

TEST_CASE("inp: *INCLUDE, GENERATE, free-face and node-based surfaces", "[mesh][inp]") {
  test::TempDir dir;
  const std::string cube = test::file_text(test::mesh_data("abaqusreader_cube_tet4.inp"));
  // The nodes move to an included file; a set by GENERATE, and the free faces of all elements.
  const size_t nodes_end = cube.find("*ELEMENT");
  dir.write("nodes.inp", "** the nodes\n" + cube.substr(0, nodes_end));
  const std::string main = "*Heading\n a cube\n*include,\n  input=nodes.inp\n" +
                           cube.substr(nodes_end) +
                           "*elset, elset=all, generate\n 1, 17, 1\n"
                           "*Surface, name=skin\nALL\n"
                           "*SURFACE, NAME=top_nodes, TYPE=NODE\n 7, 1.0\n 8\n 9\n 10\n";
  const MeshFile m = read_inp_file(dir.write("main.inp", main));
  CHECK(m.mesh.n_elements() == 17);
  // The free faces of the 17 tets are the cube's boundary: 6 faces of area 100 whose area
  // vectors cancel, enclosing (divergence theorem, no tet used) the volume 1000.
  const auto& skin = m.mesh.named_surfaces.at("skin");
  CHECK(skin.size() == 12);  // Each square face split in two
  CHECK(test::area_vector(m.mesh, skin).norm() < 1e-10);
  CHECK(test::enclosed_volume(m.mesh, skin) == Approx(1000).epsilon(1e-12));
  CHECK(m.mesh.named_node_sets.at("all").size() == 10);
  CHECK(m.mesh.named_node_sets.at("top_nodes").size() == 4);
  CHECK(all_at(m, "top_nodes", 2, 10.0));
}

TEST_CASE("inp: truncated copies never crash and name the file", "[mesh][inp]") {
  test::TempDir dir;
  const std::string text = test::file_text(test::mesh_data("hypermesh_tet4.inp"));
  const auto cuts = test::cut_points(text, 3, 40);
  const int refused =
      test::read_truncated(dir, "t.inp", text, cuts, [](const auto& f) { read_inp_file(f); });
  // A cut before the first element or inside a *SURFACE that names a later line is refused; a
  // cut after the last surface reads (the material data is not needed).
  CHECK(refused > 0);
  CHECK(refused < static_cast<int>(cuts.size()));
}

TEST_CASE("inp: bad fields name the file, the line and the keyword", "[mesh][inp]") {
  test::TempDir dir;
  const std::string cube = test::file_text(test::mesh_data("abaqusreader_cube_tet4.inp"));
  const std::string f = (dir.path / "b.inp").string();
  const auto error_with = [&](const std::string& from, const std::string& to) {
    const auto file = dir.write("b.inp", edited(cube, from, to));
    return test::mesh_error_of([&] { read_inp_file(file); });
  };
  CHECK(error_with("3,1.0e1,10.00000,0.00000", "3,1.0e1,1O.00000,0.00000") ==
        f + ":4: *NODE: node 3: coordinate '1O.00000' is not a finite number");
  CHECK(error_with("        16,         8,         9,        10,         2",
                   "        16,         8,         9,        10,        12") ==
        f + ":28: *ELEMENT: element 16 uses node 12, which is not defined");
  CHECK(error_with("        16,         8,         9,        10,         2",
                   "        16,         8,         9,        10") ==
        f + ":28: *ELEMENT: a C3D4 needs a label and 4 nodes, found 9 fields");
  CHECK(error_with("        16, S1", "        16, S5") ==
        f + ":41: *SURFACE: face 'S5' is not a face of a C3D4 (S1, S2, S3 or S4)");
  CHECK(error_with("        16, S1", "        18, S1") ==
        f + ":41: *SURFACE: element 18 is not defined");
  CHECK(error_with("TYPE=C3D4", "TYPE=C3D10") ==
        f + ":12: *ELEMENT: element type C3D10 is not supported: ccm reads linear tetrahedra "
            "(C3D4) only, and leaving the others out would lose their mass (the deck holds 5 "
            "C3D10)");
  CHECK(error_with("*NSET, NSET=SYM12\n", "*NSET, NSET=SYM12\nNOPE,\n") ==
        f + ":35: *NSET: no set named 'NOPE' is defined before");
  CHECK(error_with("*NSET, NSET=SYM12\n", "*NSET\n") ==
        f + ":34: *NSET: the parameter NSET= is required");
}

TEST_CASE("inp: nodes at one position in one part are refused (the mesh is cut there)",
          "[mesh][inp]") {
  test::TempDir dir;
  // Two tets on one face, the second given its own copies of the face's three nodes.
  const auto file = dir.write("cut.inp",
                              "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n"
                              "5, 1, 1, 1\n6, 1, 0, 0\n7, 0, 1, 0\n8, 0, 0, 1\n"
                              "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n2, 6, 7, 8, 5\n");
  CHECK(test::mesh_error_of([&] { read_inp_file(file); }) ==
        file.string() +
            ":9: *NODE: nodes 4 and 8 share the position (0, 0, 1) (3 node(s) share their "
            "position with another): the tetrahedra on either side are not connected there, a cut "
            "the body would open along; merge the duplicates, or make each part a body (or a "
            "region) of its own");
  // The same two tets as two parts (ELSET= on *ELEMENT): parts that meet, read as two regions.
  const auto parts = dir.write("parts.inp",
                               "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n"
                               "5, 1, 1, 1\n6, 1, 0, 0\n7, 0, 1, 0\n8, 0, 0, 1\n"
                               "*ELEMENT, TYPE=C3D4, ELSET=a\n1, 1, 2, 3, 4\n"
                               "*ELEMENT, TYPE=C3D4, ELSET=b\n2, 6, 7, 8, 5\n");
  const MeshFile m = read_inp_file(parts);
  CHECK(m.mesh.region_names == std::vector<std::string>{"a", "b"});
  CHECK(m.mesh.tet_region == std::vector<int>{0, 1});
  // Joined (the second tet on nodes 2, 3, 4), nothing to report.
  const auto joined = dir.write("joined.inp",
                                "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n"
                                "5, 1, 1, 1\n*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n2, 2, 3, 4, 5\n");
  CHECK(read_inp_file(joined).report.notes.empty());
}

TEST_CASE("inp: a set that names itself adds nothing (it once doubled at every line)",
          "[mesh][inp]") {
  // Found by fuzzing (tests/data/fuzz/README.md): 40 lines of "A, A" made set A hold 2^40 labels.
  test::TempDir dir;
  std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n"
      "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n*NSET, NSET=A\n1, 2, 3\n*NSET, NSET=A\n";
  for (int k = 0; k < 40; ++k) deck += "A, A\n";
  const MeshFile m = read_inp_file(dir.write("self.inp", deck));
  CHECK(m.mesh.named_node_sets.at("A") == std::vector<int>{0, 1, 2});
}
