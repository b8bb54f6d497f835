// Meshes that cannot be simulated are refused by element in every format (issue: bad meshes
// refused by element; docs/meshes.md "What is refused"). A generator writes one small valid mesh
// (the unit cube cut into six tets) as .inp, .unv and .msh, then the same mesh with one defect at
// a time: an inverted tet, a tet of zero volume, a node on no tet, two nodes at one position, a
// brick among the tets. Each defect must be refused with the file, the element or node label and
// the defect named; the clean mesh, and the mesh whose tets are all numbered the other way, read.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <functional>
#include <string>
#include <vector>

#include "engine/mesh/readers/mesh_file.hpp"
#include "tests/engine/mesh/readers/mesh_test_files.hpp"

using namespace ccm;
using Catch::Contains;

namespace {

struct LabelledNode {
  long label;
  Vec3 x;
};
struct LabelledTet {
  long label;
  std::array<long, 4> nodes;
};

// The generated case: labels start at 101 (nodes) and 11 (tets), so that a message that printed
// an index instead of a label would be caught.
struct CubeMesh {
  std::vector<LabelledNode> nodes;
  std::vector<LabelledTet> tets;
  std::vector<std::array<long, 8>> bricks;  // volume elements ccm does not simulate
};

double six_volume_of(const CubeMesh& m, const LabelledTet& t) {
  const auto x = [&](long label) { return m.nodes[static_cast<size_t>(label - 101)].x; };
  return (x(t.nodes[1]) - x(t.nodes[0]))
      .cross(x(t.nodes[2]) - x(t.nodes[0]))
      .dot(x(t.nodes[3]) - x(t.nodes[0]));
}

// The unit cube in six positive tets around its diagonal from corner 0 to corner 7 (Kuhn): one per
// order in which the path from 0 to 7 steps along x, y and z. Corner c is (c & 1, c >> 1 & 1,
// c >> 2 & 1) with node label 101 + c.
CubeMesh unit_cube() {
  CubeMesh m;
  for (int c = 0; c < 8; ++c) m.nodes.push_back({101 + c, Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1)});
  const int orders[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
  long label = 11;
  for (const auto& o : orders) {
    LabelledTet t{label++, {101, 101 + o[0], 101 + o[0] + o[1], 108}};
    if (six_volume_of(m, t) < 0) std::swap(t.nodes[2], t.nodes[3]);
    m.tets.push_back(t);
  }
  return m;
}

std::string inp_text(const CubeMesh& m) {
  std::string s = "*NODE\n";
  for (const auto& n : m.nodes)
    s += fmt::format("{}, {}, {}, {}\n", n.label, n.x.x(), n.x.y(), n.x.z());
  s += "*ELEMENT, TYPE=C3D4, ELSET=CUBE\n";
  for (const auto& t : m.tets)
    s += fmt::format("{}, {}, {}, {}, {}\n", t.label, t.nodes[0], t.nodes[1], t.nodes[2],
                     t.nodes[3]);
  if (!m.bricks.empty()) s += "*ELEMENT, TYPE=C3D8\n";
  for (const auto& b : m.bricks) s += fmt::format("90, {}\n", fmt::join(b, ", "));
  return s;
}

std::string unv_text(const CubeMesh& m) {
  std::string s = "    -1\n  2411\n";
  for (const auto& n : m.nodes)
    s += fmt::format("{:10d}{:10d}{:10d}{:10d}\n{:25.16E}{:25.16E}{:25.16E}\n", n.label, 1, 1, 11,
                     n.x.x(), n.x.y(), n.x.z());
  s += "    -1\n    -1\n  2412\n";
  for (const auto& t : m.tets)
    s += fmt::format("{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}\n{:10d}{:10d}{:10d}{:10d}\n", t.label,
                     111, 2, 1, 7, 4, t.nodes[0], t.nodes[1], t.nodes[2], t.nodes[3]);
  for (const auto& b : m.bricks) {
    s += fmt::format("{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}\n", 90, 115, 2, 1, 7, 8);
    for (long n : b) s += fmt::format("{:10d}", n);
    s += "\n";
  }
  return s + "    -1\n";
}

std::string msh_text(const CubeMesh& m) {
  std::string s = fmt::format("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n{}\n", m.nodes.size());
  for (const auto& n : m.nodes)
    s += fmt::format("{} {} {} {}\n", n.label, n.x.x(), n.x.y(), n.x.z());
  s += fmt::format("$EndNodes\n$Elements\n{}\n", m.tets.size() + m.bricks.size());
  for (const auto& t : m.tets)
    s += fmt::format("{} 4 2 1 1 {} {} {} {}\n", t.label, t.nodes[0], t.nodes[1], t.nodes[2],
                     t.nodes[3]);
  for (const auto& b : m.bricks) s += fmt::format("90 5 2 1 1 {}\n", fmt::join(b, " "));
  return s + "$EndElements\n";
}

struct Format {
  const char* extension;
  std::function<std::string(const CubeMesh&)> text;
};
const std::vector<Format> kFormats = {{".inp", inp_text}, {".unv", unv_text}, {".msh", msh_text}};

// One defect applied to the clean cube, and what its refusal must name.
struct Defect {
  const char* name;
  std::function<void(CubeMesh&)> apply;
  std::vector<std::string> named;  // every one must be in the message
};

std::vector<Defect> defects() {
  return {
      {"an inverted tet",
       [](CubeMesh& m) { std::swap(m.tets[2].nodes[0], m.tets[2].nodes[1]); },
       {"13 is inverted"}},
      {"two of six inverted",
       [](CubeMesh& m) {
         for (int k : {1, 4})
           std::swap(m.tets[static_cast<size_t>(k)].nodes[0],
                     m.tets[static_cast<size_t>(k)].nodes[1]);
       },
       {"12 is inverted", "2 inverted: 12, 15"}},
      {"a tet of zero volume",
       [](CubeMesh& m) { m.tets[3].nodes[3] = m.tets[3].nodes[0]; },
       {"14 has zero volume"}},
      {"a node on no tet",
       [](CubeMesh& m) {
         m.nodes.push_back({109, Vec3(2, 2, 2)});
       },
       {"node 109 belongs to no tetrahedron"}},
      {"two nodes at one position",
       [](CubeMesh& m) {
         m.nodes.push_back({109, m.nodes[7].x});  // a copy of corner 7 (label 108)
         for (long& n : m.tets[5].nodes)
           if (n == 108) n = 109;
       },
       {"nodes 108 and 109 share the position (1, 1, 1)"}},
      {"a brick among the tets",
       [](CubeMesh& m) {
         m.bricks.push_back({101, 102, 104, 103, 105, 106, 108, 107});
       },
       {"linear tetrahedra", "lose their mass"}},
  };
}

}  // namespace

TEST_CASE("mesh defects: the generated clean cube reads in every format", "[mesh]") {
  const test::TempDir dir;
  for (const Format& f : kFormats) {
    INFO(f.extension);
    const MeshFile m = read_mesh_file_with_report(
        dir.write(std::string("cube") + f.extension, f.text(unit_cube())));
    CHECK(m.mesh.n_elements() == 6);
    CHECK(m.mesh.n_nodes() == 8);
    CHECK(mesh_volume(m.mesh) == Approx(1.0).epsilon(1e-14));
  }
}

TEST_CASE("mesh defects: tets all numbered the other way are one convention, read", "[mesh]") {
  const test::TempDir dir;
  CubeMesh reversed = unit_cube();
  for (auto& t : reversed.tets) std::swap(t.nodes[2], t.nodes[3]);
  for (const Format& f : kFormats) {
    INFO(f.extension);
    const MeshFile m =
        read_mesh_file_with_report(dir.write(std::string("rev") + f.extension, f.text(reversed)));
    CHECK(mesh_volume(m.mesh) == Approx(1.0).epsilon(1e-14));  // every tet made positive
    for (const Tet& t : m.mesh.tets) CHECK(six_volume(t, m.mesh.nodes) > 0);
    if (m.report.inverted_tets) CHECK(*m.report.inverted_tets == 6);
  }
}

TEST_CASE("mesh defects: each is refused naming the file, the label and the defect", "[mesh]") {
  const test::TempDir dir;
  for (const Defect& d : defects())
    for (const Format& f : kFormats) {
      CubeMesh m = unit_cube();
      d.apply(m);
      const auto file = dir.write(std::string("bad") + f.extension, f.text(m));
      const std::string message = test::mesh_error_of([&] { read_mesh_file_with_report(file); });
      INFO(d.name << " in " << f.extension << ": " << message);
      CHECK(message.rfind(file.string() + ":", 0) == 0);
      for (const std::string& s : d.named) CHECK_THAT(message, Contains(s));
    }
}
