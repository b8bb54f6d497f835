#include "engine/mesh/readers/inp_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdlib>
#include <deque>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "engine/mesh/readers/fields.hpp"
#include "engine/mesh/readers/labelled_mesh.hpp"
#include "engine/mesh/readers/text_file.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxIncludeDepth = 10;
constexpr long kMaxGenerated = 100'000'000;
constexpr std::size_t kMaxSetLabels = 20'000'000;  // in all the deck's sets together

// Faces of a C3D4 (Abaqus element library, "solid element faces"): S1 = 1-2-3, S2 = 1-4-2,
// S3 = 2-4-3, S4 = 3-4-1.
constexpr int kC3D4Faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};

bool is_tet_type(const std::string& t) { return t == "C3D4" || t == "C3D4H"; }
bool is_triangle_type(const std::string& t) {
  static const std::set<std::string> types = {"S3",    "S3R", "CPS3", "CPE3",  "M3D3",
                                              "STRI3", "DS3", "R3D3", "SFM3D3"};
  return types.count(t) > 0;
}
bool is_solid_type(const std::string& t) {
  return t.rfind("C3D", 0) == 0 || t.rfind("DC3D", 0) == 0 || t.rfind("AC3D", 0) == 0;
}

struct Keyword {
  std::string name;                           // upper case, without '*'
  std::map<std::string, std::string> params;  // upper-case key -> value as written
  int line = 0;                               // index of the keyword line
};

struct LabelSet {
  std::string name;  // spelling of the first definition
  std::vector<long> labels;
  Place at;
};

struct Element {
  std::vector<long> nodes;
  std::string type;
  Place at;
};

struct SurfaceEntry {
  std::string surface;  // display name
  std::vector<long> elements;
  int face;  // 0..3, or -1: all free faces of `elements`
  Place at;
};

enum class Block {
  none,
  node,
  tet,
  other_solid,  // volume elements ccm does not simulate: counted, then refused
  triangle,
  other_element,
  nset,
  elset,
  surface,
  node_surface,
  instance
};

class InpParser {
 public:
  MeshFile read(const fs::path& path) {
    m_.report.format = "Abaqus/CalculiX input";
    m_.node_section = "*NODE";
    m_.tet_section = "*ELEMENT";
    m_.set_section = "*NSET";
    m_.surface_section = "*SURFACE";
    parse_file(path, 0);
    refuse_other_solids();
    resolve();
    return assemble(std::move(m_));
  }

 private:
  // ------------------------------------------------------------------------------------------
  // Lines and keywords

  void parse_file(const fs::path& path, int depth) {
    files_.push_back(std::make_unique<TextFile>(path));
    const TextFile& f = *files_.back();
    const int file_index = static_cast<int>(m_.files.size());
    m_.files.push_back(f.name());
    block_ = Block::none;
    for (int i = 0; i < f.n_lines(); ++i) {
      const std::string_view line = trim(f.line(i));
      if (line.empty() || line.rfind("**", 0) == 0) continue;
      file_ = &f;
      file_index_ = file_index;
      if (line.front() == '*') {
        const Keyword k = keyword(f, i);
        if (k.name == "INCLUDE") {
          check_no_pending();
          include(k, path, depth);
          file_ = &f;
          file_index_ = file_index;
        } else {
          start(k);
        }
      } else {
        data(i, line);
      }
    }
    check_no_pending();
  }

  // An element whose node list was not finished before the next keyword or the end of the file.
  void check_no_pending() const {
    if (!pending_.empty())
      fail(pending_line_,
           fmt::format("element data ends after {} of the 5 fields of a C3D4", pending_.size()));
  }

  // The keyword line i and its continuation lines (a keyword line ending in a comma continues);
  // i is left on the last of them.
  Keyword keyword(const TextFile& f, int& i) {
    std::string text(trim(f.line(i)));
    Keyword k;
    k.line = i;
    while (!text.empty() && text.back() == ',' && i + 1 < f.n_lines()) {
      ++i;
      text += std::string(trim(f.line(i)));
    }
    const auto fields = split_commas(std::string_view(text).substr(1));
    k.name = upper(trim(fields[0]));
    for (size_t p = 1; p < fields.size(); ++p) {
      const auto eq = fields[p].find('=');
      std::string key = upper(trim(fields[p].substr(0, eq)));
      std::string value;
      if (eq != std::string_view::npos) value = std::string(trim(fields[p].substr(eq + 1)));
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
      if (!key.empty()) k.params[key] = value;
    }
    return k;
  }

  [[noreturn]] void fail(int i, std::string_view problem) const {
    file_->fail(i, "*" + keyword_.name, problem);
  }
  Place place(int i) const { return {file_index_, i + 1}; }

  std::string required(const Keyword& k, const std::string& key) const {
    const auto it = k.params.find(key);
    if (it == k.params.end() || it->second.empty())
      file_->fail(k.line, "*" + k.name, fmt::format("the parameter {}= is required", key));
    return it->second;
  }
  std::string optional(const Keyword& k, const std::string& key) const {
    const auto it = k.params.find(key);
    return it == k.params.end() ? std::string() : it->second;
  }

  void include(const Keyword& k, const fs::path& from, int depth) {
    keyword_ = k;
    const fs::path input = required(k, "INPUT");
    if (depth + 1 > kMaxIncludeDepth)
      fail(k.line,
           fmt::format("includes are nested deeper than {} (an include cycle?)", kMaxIncludeDepth));
    const fs::path target = input.is_relative() ? from.parent_path() / input : input;
    std::error_code ec;
    if (!fs::exists(target, ec))
      fail(k.line, fmt::format("the included file {} does not exist", target.string()));
    parse_file(target, depth + 1);
    block_ = Block::none;
  }

  // ------------------------------------------------------------------------------------------
  // Keywords

  void start(const Keyword& k) {
    check_no_pending();
    keyword_ = k;
    block_ = Block::none;
    if (in_step_) {
      if (k.name == "END STEP") in_step_ = false;
      return;
    }
    if (k.name == "STEP") {
      in_step_ = true;
    } else if (k.name == "NODE") {
      start_node(k);
    } else if (k.name == "ELEMENT") {
      start_element(k);
    } else if (k.name == "NSET" || k.name == "ELSET") {
      start_set(k);
    } else if (k.name == "SURFACE") {
      start_surface(k);
    } else if (k.name == "PART") {
      if (++parts_ > 1)
        fail(k.line, "a second *PART: ccm reads a flat input file (one part, no instances)");
    } else if (k.name == "INSTANCE") {
      block_ = Block::instance;
    }
  }

  void start_node(const Keyword& k) {
    if (k.params.count("INPUT")) fail(k.line, "INPUT= (nodes in another file) is not supported");
    const std::string system = upper(optional(k, "SYSTEM"));
    if (!system.empty() && system != "R")
      fail(k.line,
           fmt::format("SYSTEM={}: only rectangular coordinates (R) are supported", system));
    set_ = k.params.count("NSET") ? &set_named(nsets_, k.params.at("NSET"), k.line) : nullptr;
    block_ = Block::node;
  }

  void start_element(const Keyword& k) {
    if (k.params.count("INPUT")) fail(k.line, "INPUT= (elements in another file) is not supported");
    element_type_ = upper(required(k, "TYPE"));
    set_ = k.params.count("ELSET") ? &set_named(elsets_, k.params.at("ELSET"), k.line) : nullptr;
    region_ = -1;
    other_solid_fields_ = 0;
    if (is_tet_type(element_type_)) {
      block_ = Block::tet;
      if (k.params.count("ELSET")) region_ = region_named(k.params.at("ELSET"));
    } else if (is_solid_type(element_type_)) {
      block_ = Block::other_solid;
      other_solids_.try_emplace(element_type_, OtherSolids{0, file_index_, k.line});
    } else {
      block_ = is_triangle_type(element_type_) ? Block::triangle : Block::other_element;
    }
  }

  void start_set(const Keyword& k) {
    const bool nodes = k.name == "NSET";
    auto& sets = nodes ? nsets_ : elsets_;
    set_ = &set_named(sets, required(k, nodes ? "NSET" : "ELSET"), k.line);
    generate_ = k.params.count("GENERATE") > 0;
    block_ = nodes ? Block::nset : Block::elset;
    if (nodes && k.params.count("ELSET")) {  // the nodes of the elements of a set
      const LabelSet& from = existing(elsets_, k.params.at("ELSET"), k.line);
      for (long e : from.labels) {
        const auto it = elements_.find(e);
        if (it != elements_.end())
          set_->labels.insert(set_->labels.end(), it->second.nodes.begin(), it->second.nodes.end());
      }
    }
  }

  void start_surface(const Keyword& k) {
    surface_name_ = required(k, "NAME");
    const std::string type = upper(optional(k, "TYPE"));
    if (type.empty() || type == "ELEMENT") {
      block_ = Block::surface;
      if (!surface_names_.emplace(upper(surface_name_), surface_name_).second)
        surface_name_ = surface_names_.at(upper(surface_name_));
    } else if (type == "NODE") {
      set_ = &set_named(nsets_, surface_name_, k.line);
      block_ = Block::node_surface;
    } else {
      fail(k.line,
           fmt::format("TYPE={}: only element-based and node-based surfaces are read", type));
    }
  }

  // The region of the tets of an *ELEMENT, ELSET=name keyword (names case-insensitive, the first
  // spelling kept).
  int region_named(const std::string& name) {
    auto& names = m_.region_names;
    for (size_t r = 0; r < names.size(); ++r)
      if (upper(names[r]) == upper(name)) return static_cast<int>(r);
    names.push_back(name);
    return static_cast<int>(names.size()) - 1;
  }

  LabelSet& set_named(std::map<std::string, LabelSet>& sets, const std::string& name, int line) {
    LabelSet& s = sets[upper(name)];
    if (s.name.empty()) s = {name, {}, place(line)};
    return s;
  }
  const LabelSet& existing(const std::map<std::string, LabelSet>& sets, std::string_view name,
                           int line) const {
    const auto it = sets.find(upper(name));
    if (it == sets.end()) fail(line, fmt::format("no set named '{}' is defined before", name));
    return it->second;
  }

  // ------------------------------------------------------------------------------------------
  // Data lines

  void data(int i, std::string_view line) {
    switch (block_) {
      case Block::node:
        return node_line(i, line);
      case Block::tet:
      case Block::triangle:
      case Block::other_element:
        return element_line(i, line);
      case Block::other_solid:
        return other_solid_line(line);
      case Block::nset:
        return set_line(i, line, nsets_);
      case Block::elset:
        return set_line(i, line, elsets_);
      case Block::surface:
        return surface_line(i, line);
      case Block::node_surface:
        return set_line(i, line, nsets_, true);
      case Block::instance:
        fail(i, "an instance with a placement: ccm reads a flat input file (no instances)");
      case Block::none:
        if (keyword_.name.empty()) file_->fail(i, "file", "a data line before the first keyword");
        return;
    }
  }

  long label(int i, std::string_view field, std::string_view what) const {
    const auto v = parse_integer(field);
    if (!v || *v <= 0) fail(i, fmt::format("{} '{}' is not a positive integer", what, field));
    return *v;
  }

  void node_line(int i, std::string_view line) {
    const auto fields = split_commas(line);
    if (fields.size() < 2 || fields.size() > 7)
      fail(i, fmt::format("expected 'label, x, y, z', found '{}'", line));
    const long n = label(i, fields[0], "node label");
    Vec3 x = Vec3::Zero();
    for (size_t k = 1; k < std::min<size_t>(fields.size(), 4); ++k) {
      const auto v = fields[k].empty() ? std::optional<double>(0.0) : parse_real(fields[k]);
      if (!v) fail(i, fmt::format("node {}: coordinate '{}' is not a finite number", n, fields[k]));
      x[static_cast<Eigen::Index>(k - 1)] = *v;
    }
    m_.nodes.push_back({n, x, place(i)});
    if (set_) set_->labels.push_back(n);
  }

  // Element data: label and node labels; a tet may continue on the next line.
  void element_line(int i, std::string_view line) {
    const auto fields = split_commas(line);
    if (pending_.empty()) pending_line_ = i;
    pending_.insert(pending_.end(), fields.begin(), fields.end());
    if (block_ == Block::tet && pending_.size() < 5) return;
    std::vector<std::string_view> item;
    item.swap(pending_);
    const int at = pending_line_;
    if (block_ == Block::tet && item.size() != 5)
      fail(at, fmt::format("a C3D4 needs a label and 4 nodes, found {} fields", item.size()));
    const long e = label(at, item[0], "element label");
    Element el{{}, element_type_, place(at)};
    for (size_t k = 1; k < item.size(); ++k)
      el.nodes.push_back(label(at, item[k], fmt::format("node of element {}", e)));
    if (elements_.count(e))
      fail(at, fmt::format("element {} is defined twice (first at line {})", e,
                           elements_.at(e).at.line));
    if (block_ == Block::tet)
      m_.tets.push_back(
          {e, {el.nodes[0], el.nodes[1], el.nodes[2], el.nodes[3]}, place(at), region_});
    else if (block_ == Block::triangle && el.nodes.size() == 3)
      triangles_.insert(e);
    else
      ++m_.report.ignored[element_type_];
    elements_.emplace(e, std::move(el));
    if (set_) set_->labels.push_back(e);
  }

  // An element of a volume type ccm does not simulate, counted (its nodes run over continuation
  // lines: C3D<n> has n nodes).
  void other_solid_line(std::string_view line) {
    other_solid_fields_ += split_commas(line).size();
    const std::string digits = element_type_.substr(element_type_.find("3D") + 2);
    const size_t n_nodes = std::strtoul(digits.c_str(), nullptr, 10);
    if (other_solid_fields_ < 1 + n_nodes) return;
    ++other_solids_.at(element_type_).count;
    other_solid_fields_ = 0;
  }

  // Volume elements other than C3D4 are refused at the first such *ELEMENT keyword, with how many
  // of each type the deck holds: leaving them out would lose their mass.
  void refuse_other_solids() const {
    if (other_solids_.empty()) return;
    std::vector<std::string> counts;
    const OtherSolids* first = nullptr;
    for (const auto& [type, o] : other_solids_) {
      counts.push_back(fmt::format("{} {}", o.count, type));
      if (!first || std::pair(o.file, o.line) < std::pair(first->file, first->line)) first = &o;
    }
    for (const auto& [type, o] : other_solids_)
      if (&o == first)
        files_[static_cast<size_t>(o.file)]->fail(
            o.line, "*ELEMENT",
            fmt::format("element type {} is not supported: ccm reads linear tetrahedra (C3D4) "
                        "only, and leaving the others out would lose their mass (the deck holds "
                        "{})",
                        type, fmt::join(counts, ", ")));
  }

  // Labels, set names, or with GENERATE "first, last[, increment]". A node-based surface line is
  // "node or set[, weight]".
  void set_line(int i, std::string_view line, const std::map<std::string, LabelSet>& sets,
                bool node_surface = false) {
    auto fields = split_commas(line);
    if (node_surface) fields.resize(1);
    if (generate_ && !node_surface) return generate(i, fields);
    for (const auto field : fields) {
      if (field.empty()) continue;
      if (parse_integer(field)) {
        book_set_labels(i, 1);
        set_->labels.push_back(label(i, field, "label"));
      } else {
        const LabelSet& other = existing(sets, field, i);
        if (&other == set_) continue;  // a set naming itself adds nothing
        book_set_labels(i, other.labels.size());
        set_->labels.insert(set_->labels.end(), other.labels.begin(), other.labels.end());
      }
    }
  }

  // Sets that name sets can grow geometrically (B = A, A, A; C = B, B, B ...): refused past a
  // bound on the labels of all sets together, before the memory runs out (found by fuzzing).
  void book_set_labels(int i, std::size_t count) {
    set_labels_ += count;
    if (set_labels_ > kMaxSetLabels)
      fail(i, fmt::format("the sets hold more than {} labels in all (sets that name sets many "
                          "times over); ccm refuses the deck",
                          kMaxSetLabels));
  }

  void generate(int i, const std::vector<std::string_view>& fields) {
    if (fields.size() < 2 || fields.size() > 3)
      fail(i, "GENERATE expects 'first, last[, increment]'");
    const long first = label(i, fields[0], "first label");
    const long last = label(i, fields[1], "last label");
    const long step = fields.size() == 3 ? label(i, fields[2], "increment") : 1;
    if (last < first) fail(i, fmt::format("GENERATE: last label {} < first {}", last, first));
    if ((last - first) / step > kMaxGenerated)
      fail(i, fmt::format("GENERATE: more than {} labels", kMaxGenerated));
    book_set_labels(i, static_cast<std::size_t>((last - first) / step + 1));
    for (long l = first; l <= last; l += step) set_->labels.push_back(l);
  }

  void surface_line(int i, std::string_view line) {
    const auto fields = split_commas(line);
    if (fields.empty() || fields.size() > 2 || fields[0].empty())
      fail(i, fmt::format("expected 'element or element set, face', found '{}'", line));
    SurfaceEntry entry{surface_name_, {}, -1, place(i)};
    if (parse_integer(fields[0]))
      entry.elements.push_back(label(i, fields[0], "element label"));
    else
      entry.elements = existing(elsets_, fields[0], i).labels;
    if (fields.size() == 2 && !fields[1].empty()) {
      const std::string face = upper(fields[1]);
      if (face.size() != 2 || face[0] != 'S' || face[1] < '1' || face[1] > '4') {
        refuse_other_solids();  // the cause, when the face is one of a brick or wedge
        fail(i, fmt::format("face '{}' is not a face of a C3D4 (S1, S2, S3 or S4)", fields[1]));
      }
      entry.face = face[1] - '1';
    }
    surface_entries_.push_back(std::move(entry));
  }

  // ------------------------------------------------------------------------------------------
  // Sets and surfaces to named node sets and surfaces

  void resolve() {
    for (auto& [key, set] : nsets_) m_.node_sets[set.name] = {set.labels, set.at};
    for (auto& [key, set] : elsets_) resolve_elset(set);
    for (const SurfaceEntry& entry : surface_entries_) resolve_surface(entry);
  }

  const Element& element(long e, Place at, std::string_view section) const {
    const auto it = elements_.find(e);
    if (it == elements_.end())
      fail_at(m_.files[static_cast<size_t>(at.file)], at.line, section,
              fmt::format("element {} is not defined", e));
    return it->second;
  }

  // An element set: the nodes of its tets become a node set, its triangles a surface.
  void resolve_elset(const LabelSet& set) {
    std::vector<long> nodes;
    std::vector<LabelledMesh::Face> faces;
    for (long e : set.labels) {
      const Element& el = element(e, set.at, "*ELSET");
      if (is_tet_type(el.type)) nodes.insert(nodes.end(), el.nodes.begin(), el.nodes.end());
      if (triangles_.count(e))
        faces.push_back({{el.nodes[0], el.nodes[1], el.nodes[2]}, 0, set.at});
    }
    if (!nodes.empty()) {
      auto& target = m_.node_sets[set.name];
      if (target.at.line == 0) target.at = set.at;
      target.labels.insert(target.labels.end(), nodes.begin(), nodes.end());
    }
    if (!faces.empty()) {
      auto& target = m_.surfaces[set.name];
      target.insert(target.end(), faces.begin(), faces.end());
    }
  }

  void resolve_surface(const SurfaceEntry& entry) {
    auto& faces = m_.surfaces[entry.surface];
    std::map<std::array<long, 3>, std::pair<int, LabelledMesh::Face>> free;  // sorted -> count
    for (long e : entry.elements) {
      const Element& el = element(e, entry.at, "*SURFACE");
      if (!is_tet_type(el.type))
        fail_at(m_.files[static_cast<size_t>(entry.at.file)], entry.at.line, "*SURFACE",
                fmt::format("element {} is a {}, not a C3D4", e, el.type));
      for (int f = 0; f < 4; ++f) {
        if (entry.face >= 0 && f != entry.face) continue;
        const LabelledMesh::Face face{{el.nodes[static_cast<size_t>(kC3D4Faces[f][0])],
                                       el.nodes[static_cast<size_t>(kC3D4Faces[f][1])],
                                       el.nodes[static_cast<size_t>(kC3D4Faces[f][2])]},
                                      e,
                                      entry.at};
        if (entry.face >= 0) {
          faces.push_back(face);
          continue;
        }
        auto key = face.nodes;
        std::sort(key.begin(), key.end());
        auto& slot = free[key];
        if (slot.first++ == 0) slot.second = face;
      }
    }
    for (const auto& [key, slot] : free)
      if (slot.first == 1) faces.push_back(slot.second);
  }

  LabelledMesh m_;
  std::deque<std::unique_ptr<TextFile>> files_;
  const TextFile* file_ = nullptr;
  int file_index_ = 0;
  Keyword keyword_;
  Block block_ = Block::none;
  bool in_step_ = false;
  bool generate_ = false;
  int parts_ = 0;
  std::string element_type_;
  int region_ = -1;  // of the tets of the current *ELEMENT keyword
  struct OtherSolids {
    int count = 0;
    int file = 0, line = 0;  // of the first *ELEMENT keyword of the type
  };
  std::map<std::string, OtherSolids> other_solids_;  // by element type
  size_t other_solid_fields_ = 0;
  std::size_t set_labels_ = 0;  // in all sets, for kMaxSetLabels
  std::string surface_name_;
  LabelSet* set_ = nullptr;
  std::vector<std::string_view> pending_;
  int pending_line_ = 0;
  std::map<std::string, LabelSet> nsets_, elsets_;    // by upper-case name
  std::map<std::string, std::string> surface_names_;  // upper -> first spelling
  std::unordered_map<long, Element> elements_;
  std::set<long> triangles_;
  std::vector<SurfaceEntry> surface_entries_;
};

}  // namespace

MeshFile read_inp_file(const std::filesystem::path& path) { return InpParser().read(path); }

}  // namespace ccm
