#include "engine/mesh/readers/unv_reader.hpp"

#include <fmt/format.h>

#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "engine/mesh/readers/fields.hpp"
#include "engine/mesh/readers/labelled_mesh.hpp"
#include "engine/mesh/readers/text_file.hpp"

namespace ccm {
namespace {

// I-DEAS FE descriptor ids (Universal File Datasets Summary, dataset 2412).
constexpr long kLinearTet = 111;
bool is_beam(long fe) { return fe == 11 || fe == 21 || fe == 22 || fe == 23 || fe == 24; }
bool is_linear_triangle(long fe) {
  return fe == 41 || fe == 51 || fe == 61 || fe == 74 || fe == 81 || fe == 91;
}
bool is_other_solid(long fe) { return fe >= 112 && fe <= 118; }

std::string fe_name(long fe) {
  static const std::map<long, const char*> names = {{11, "rod"},
                                                    {21, "linear beam"},
                                                    {22, "tapered beam"},
                                                    {24, "parabolic beam"},
                                                    {41, "plane stress linear triangle"},
                                                    {42, "plane stress parabolic triangle"},
                                                    {44, "plane stress linear quadrilateral"},
                                                    {45, "plane stress parabolic quadrilateral"},
                                                    {91, "thin shell linear triangle"},
                                                    {92, "thin shell parabolic triangle"},
                                                    {94, "thin shell linear quadrilateral"},
                                                    {95, "thin shell parabolic quadrilateral"},
                                                    {111, "solid linear tetrahedron"},
                                                    {112, "solid linear wedge"},
                                                    {113, "solid parabolic wedge"},
                                                    {114, "solid cubic wedge"},
                                                    {115, "solid linear brick"},
                                                    {116, "solid parabolic brick"},
                                                    {117, "solid cubic brick"},
                                                    {118, "solid parabolic tetrahedron"},
                                                    {161, "lumped mass"}};
  const auto it = names.find(fe);
  return it == names.end() ? fmt::format("FE descriptor {}", fe)
                           : fmt::format("{} ({})", it->second, fe);
}

std::string section_name(long dataset) {
  switch (dataset) {
    case 164:
      return "dataset 164 (units)";
    case 2411:
      return "dataset 2411 (nodes)";
    case 2412:
      return "dataset 2412 (elements)";
    default:
      return fmt::format("dataset {} (groups)", dataset);
  }
}

bool is_group_dataset(long n) { return n == 2467 || n == 2477 || n == 2435; }

struct Group {
  std::vector<long> nodes, elements;
  Place at;
};

// The lines [begin, end) of one dataset and the state the datasets build up.
class UnvParser {
 public:
  explicit UnvParser(const TextFile& file) : f_(file) {
    m_.files = {f_.name()};
    m_.report.format = "I-DEAS universal";
    m_.node_section = section_name(2411);
    m_.tet_section = section_name(2412);
    m_.set_section = "dataset 2467 (groups)";
    m_.surface_section = m_.set_section;
  }

  MeshFile read() {
    int i = 0;
    std::set<long> skipped;
    while (i < f_.n_lines()) {
      const std::string_view line = trim(f_.line(i));
      if (line.empty()) {
        ++i;
        continue;
      }
      if (line != "-1")
        f_.fail(i, "file", fmt::format("expected -1 (the start of a dataset), found '{}'", line));
      const long dataset = dataset_number(i + 1);
      const int end = dataset_end(i + 2, dataset);
      section_ = section_name(dataset);
      if (dataset == 164)
        read_units(i + 2, end);
      else if (dataset == 2411)
        read_nodes(i + 2, end);
      else if (dataset == 2412)
        read_elements(i + 2, end);
      else if (is_group_dataset(dataset))
        read_groups(i + 2, end);
      else
        skipped.insert(dataset);
      i = end + 1;
    }
    if (!skipped.empty())
      m_.report.notes.push_back(
          fmt::format("datasets skipped (not mesh data): {}", fmt::join(skipped, ", ")));
    refuse_other_solids();
    resolve_groups();
    return assemble(std::move(m_));
  }

 private:
  long dataset_number(int i) const {
    if (i >= f_.n_lines()) f_.fail(i - 1, "file", "ends after -1 without a dataset number");
    const auto fields = split_whitespace(f_.line(i));
    if (!fields.empty() && fields[0].size() > 1 &&
        (fields[0].back() == 'b' || fields[0].back() == 'B'))
      if (const auto binary = parse_integer(fields[0].substr(0, fields[0].size() - 1)))
        f_.fail(i, section_name(*binary),
                "binary datasets are not supported (export the universal file as ASCII)");
    const auto n = fields.empty() ? std::nullopt : parse_integer(fields[0]);
    if (!n || *n <= 0)
      f_.fail(i, "file", fmt::format("expected a dataset number, found '{}'", trim(f_.line(i))));
    if (fields.size() > 1)
      f_.fail(i, section_name(*n),
              "binary datasets are not supported (export the universal file as ASCII)");
    return *n;
  }

  // Index of the -1 that closes the dataset whose data starts at line `begin`.
  int dataset_end(int begin, long dataset) const {
    for (int j = begin; j < f_.n_lines(); ++j)
      if (trim(f_.line(j)) == "-1") return j;
    f_.fail(f_.n_lines() - 1, section_name(dataset),
            fmt::format("the file ends inside the dataset (started at line {}, no closing -1)",
                        begin - 1));
  }

  Place place(int i) const { return {0, i + 1}; }

  // `count` integers from line i; the line must hold exactly that many (at least `count` when
  // `at_least`).
  std::vector<long> integers(int i, int end, size_t count, std::string_view what,
                             bool at_least = false) const {
    if (i >= end) f_.fail(i - 1, section_, fmt::format("the dataset ends before {}", what));
    const auto fields = split_whitespace(f_.line(i));
    if (fields.size() < count || (!at_least && fields.size() != count))
      f_.fail(i, section_,
              fmt::format("{}: expected {} integers, found '{}'", what, count, trim(f_.line(i))));
    std::vector<long> out;
    for (size_t k = 0; k < count; ++k) {
      const auto v = parse_integer(fields[k]);
      if (!v) f_.fail(i, section_, fmt::format("{}: '{}' is not an integer", what, fields[k]));
      out.push_back(*v);
    }
    return out;
  }

  std::vector<double> reals(int i, int end, size_t count, std::string_view what) const {
    if (i >= end) f_.fail(i - 1, section_, fmt::format("the dataset ends before {}", what));
    const auto fields = split_whitespace(f_.line(i));
    if (fields.size() != count)
      f_.fail(i, section_,
              fmt::format("{}: expected {} numbers, found '{}'", what, count, trim(f_.line(i))));
    std::vector<double> out;
    for (const auto field : fields) {
      const auto v = parse_real(field);
      if (!v) f_.fail(i, section_, fmt::format("{}: '{}' is not a finite number", what, field));
      out.push_back(*v);
    }
    return out;
  }

  // Record 2 of dataset 164: factors that convert file units to SI by division.
  void read_units(int begin, int end) {
    const auto factors = reals(begin + 1, end, 3, "unit factors (length, force, temperature)");
    if (!(factors[0] > 0))
      f_.fail(begin + 1, section_,
              fmt::format("the length unit factor must be positive, got {}", factors[0]));
    m_.length_scale = 1.0 / factors[0];
    if (factors[0] != 1.0)
      m_.report.notes.push_back(fmt::format(
          "dataset 164: coordinates divided by the length unit factor {} (to metres)", factors[0]));
  }

  void read_nodes(int begin, int end) {
    for (int i = begin; i < end; i += 2) {
      const long label =
          integers(i, end, 4, "node record 1 (label, 3 coordinate systems, colour)", true)[0];
      if (label == -1) break;
      if (label <= 0) f_.fail(i, section_, fmt::format("node label {} is not positive", label));
      const auto x = reals(i + 1, end, 3, fmt::format("coordinates of node {}", label));
      m_.nodes.push_back({label, Vec3(x[0], x[1], x[2]), place(i)});
    }
  }

  void read_elements(int begin, int end) {
    int i = begin;
    while (i < end) {
      const auto r = integers(i, end, 6,
                              "element record 1 (label, FE descriptor, properties, "
                              "colour, node count)");
      const long label = r[0], fe = r[1], n_nodes = r[5];
      const int at = i;
      if (label == -1) break;
      if (label <= 0) f_.fail(i, section_, fmt::format("element label {} is not positive", label));
      if (n_nodes < 1 || n_nodes > 64)
        f_.fail(i, section_,
                fmt::format("element {}: node count {} is out of range", label, n_nodes));
      ++i;
      if (is_beam(fe)) integers(i++, end, 3, fmt::format("beam record of element {}", label));
      std::vector<long> nodes;
      while (nodes.size() < static_cast<size_t>(n_nodes)) {
        const size_t on_line = std::min<size_t>(8, static_cast<size_t>(n_nodes) - nodes.size());
        const auto more = integers(i++, end, on_line, fmt::format("nodes of element {}", label));
        nodes.insert(nodes.end(), more.begin(), more.end());
      }
      add_element(label, fe, nodes, at);
    }
  }

  void add_element(long label, long fe, const std::vector<long>& nodes, int at) {
    if (!element_lines_.emplace(label, at + 1).second)
      f_.fail(at, section_,
              fmt::format("element {} is defined twice (first at line {})", label,
                          element_lines_.at(label)));
    if (fe == kLinearTet && nodes.size() == 4) {
      m_.tets.push_back({label, {nodes[0], nodes[1], nodes[2], nodes[3]}, place(at)});
      tet_nodes_.emplace(label, nodes);
    } else if (is_linear_triangle(fe) && nodes.size() == 3) {
      triangles_.emplace(label, std::array<long, 3>{nodes[0], nodes[1], nodes[2]});
    } else if (fe == kLinearTet) {
      f_.fail(at, section_,
              fmt::format("element {} is a {} with {} nodes; ccm reads linear tetrahedra (111, "
                          "4 nodes) only",
                          label, fe_name(fe), nodes.size()));
    } else if (is_other_solid(fe)) {
      if (other_solids_.empty()) {
        first_other_solid_ =
            fmt::format("element {} is a {} with {} nodes", label, fe_name(fe), nodes.size());
        first_other_solid_at_ = at;
      }
      ++other_solids_[fe_name(fe)];
    } else {
      ++m_.report.ignored[fe_name(fe)];
    }
  }

  // Volume elements other than linear tets are refused at the first of them, with how many of
  // each kind the file holds: leaving them out would lose their mass.
  void refuse_other_solids() const {
    if (other_solids_.empty()) return;
    std::vector<std::string> counts;
    for (const auto& [kind, n] : other_solids_) counts.push_back(fmt::format("{} {}", n, kind));
    f_.fail(first_other_solid_at_, section_name(2412),
            fmt::format("{}; ccm reads linear tetrahedra (111, 4 nodes) only, and leaving the "
                        "others out would lose their mass (the file holds {})",
                        first_other_solid_, fmt::join(counts, ", ")));
  }

  void read_groups(int begin, int end) {
    int i = begin;
    while (i < end) {
      const auto r = integers(i, end, 8, "group record 1 (number, 6 active sets, entity count)");
      const long count = r[7];
      if (count < 0) f_.fail(i, section_, fmt::format("group entity count {} is negative", count));
      if (i + 1 >= end) f_.fail(i, section_, "the dataset ends before the group name");
      std::string name(trim(f_.line(i + 1)));
      if (name.empty()) name = fmt::format("group{}", r[0]);
      Group& g = groups_[name];
      if (g.at.line == 0) g.at = place(i + 1);
      i += 2;
      for (long read = 0; read < count;) {
        const size_t on_line = count - read >= 2 ? 2 : 1;
        const auto e = integers(i, end, 4 * on_line, fmt::format("members of group '{}'", name));
        for (size_t k = 0; k < on_line; ++k) add_member(g, e[4 * k], e[4 * k + 1], name);
        read += static_cast<long>(on_line);
        ++i;
      }
    }
  }

  // Entity type codes of dataset 2467: 7 node, 8 finite element; the rest are not mesh items.
  void add_member(Group& g, long type, long tag, const std::string& name) {
    if (type == 7)
      g.nodes.push_back(tag);
    else if (type == 8)
      g.elements.push_back(tag);
    else
      ++m_.report.ignored[fmt::format("group '{}' members of entity type {}", name, type)];
  }

  // Groups to named surfaces (their triangles) and node sets (their nodes and tets' nodes).
  void resolve_groups() {
    for (auto& [name, g] : groups_) {
      std::vector<LabelledMesh::Face> faces;
      std::vector<long> nodes = g.nodes;
      for (long e : g.elements) {
        if (const auto t = triangles_.find(e); t != triangles_.end())
          faces.push_back({t->second, 0, g.at});
        else if (const auto tet = tet_nodes_.find(e); tet != tet_nodes_.end())
          nodes.insert(nodes.end(), tet->second.begin(), tet->second.end());
        else if (!element_lines_.count(e))
          fail_at(f_.name(), g.at.line, "dataset 2467 (groups)",
                  fmt::format("group '{}' names element {}, which is not defined", name, e));
      }
      const bool has_faces = !faces.empty();
      if (has_faces) m_.surfaces[name] = std::move(faces);
      if (!nodes.empty() || !has_faces) m_.node_sets[name] = {std::move(nodes), g.at};
    }
  }

  const TextFile& f_;
  LabelledMesh m_;
  std::string section_;
  std::unordered_map<long, int> element_lines_;  // label -> line of record 1
  std::unordered_map<long, std::array<long, 3>> triangles_;
  std::unordered_map<long, std::vector<long>> tet_nodes_;
  std::map<std::string, Group> groups_;
  std::map<std::string, int> other_solids_;  // volume elements that are not linear tets, by kind
  std::string first_other_solid_;            // "element 6 is a ..."
  int first_other_solid_at_ = 0;
};

}  // namespace

MeshFile read_unv_file(const std::filesystem::path& path) {
  const TextFile file(path);
  return UnvParser(file).read();
}

}  // namespace ccm
