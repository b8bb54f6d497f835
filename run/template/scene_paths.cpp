#include "run/template/scene_paths.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "config/did_you_mean.hpp"

namespace ccm {
namespace {

struct PathStep {
  std::string key;
  std::vector<std::size_t> indices;  // "[i]" after the key, in order
};

// "a.b[1][2].c" -> {a}, {b, 1, 2}, {c}; nullopt when it is not of that form.
std::optional<std::vector<PathStep>> parse_path(std::string_view path) {
  std::vector<PathStep> steps;
  std::size_t pos = 0;
  while (pos <= path.size()) {
    const std::size_t end = std::min(path.find('.', pos), path.size());
    const std::string_view segment = path.substr(pos, end - pos);
    const std::size_t bracket = std::min(segment.find('['), segment.size());
    PathStep step{std::string(segment.substr(0, bracket)), {}};
    if (step.key.empty()) return std::nullopt;
    for (std::size_t b = bracket; b < segment.size();) {
      const std::size_t close = segment.find(']', b);
      if (segment[b] != '[' || close == std::string_view::npos || close == b + 1)
        return std::nullopt;
      std::size_t index = 0;
      for (std::size_t d = b + 1; d < close; ++d) {
        if (segment[d] < '0' || segment[d] > '9') return std::nullopt;
        index = index * 10 + static_cast<std::size_t>(segment[d] - '0');
      }
      step.indices.push_back(index);
      b = close + 1;
    }
    steps.push_back(std::move(step));
    pos = end + 1;
  }
  return steps;
}

// The entry of an array of tables whose `name` is `name`, or nullptr.
const toml::node* named_entry(const toml::array& tables, std::string_view name) {
  for (const toml::node& entry : tables) {
    const toml::table* t = entry.as_table();
    const std::optional<std::string_view> entry_name =
        t ? (*t)["name"].value<std::string_view>() : std::nullopt;
    if (entry_name == name) return &entry;
  }
  return nullptr;
}

const toml::node* resolve(const toml::table& doc, const std::vector<PathStep>& steps) {
  const toml::node* n = &doc;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const toml::table* t = n->as_table();
    if (!t || !(n = t->get(steps[i].key))) return nullptr;
    for (std::size_t index : steps[i].indices) {
      const toml::array* a = n->as_array();
      if (!a || !(n = a->get(index))) return nullptr;
    }
    if (steps[i].indices.empty() && n->is_array_of_tables() && i + 1 < steps.size()) {
      ++i;  // the next step names an entry
      if (!steps[i].indices.empty()) return nullptr;
      if (!(n = named_entry(*n->as_array(), steps[i].key))) return nullptr;
    }
  }
  return n;
}

bool is_number(const toml::node& n) { return n.is_integer() || n.is_floating_point(); }

// An array of numbers (a vector such as a velocity or a size): a path to it sets its magnitude.
bool is_vector(const toml::node& n) {
  const toml::array* a = n.as_array();
  return a && !a->empty() &&
         std::all_of(a->begin(), a->end(), [](const toml::node& x) { return is_number(x); });
}

double magnitude(const toml::array& a) {
  double sum = 0.0;
  for (const toml::node& x : a) {
    const double v = x.value<double>().value_or(0.0);
    sum += v * v;
  }
  return std::sqrt(sum);
}

// Scales the vector to `value` (its direction kept; a negative value reverses it). Its entries
// become floats.
void set_magnitude(toml::array& a, std::string_view path, double value) {
  const double norm = magnitude(a);
  if (!(norm > 0.0))
    throw std::invalid_argument(
        fmt::format("\"{}\" is a zero vector in the scene: it has no direction to scale; sweep its "
                    "components (\"{}[0]\", ...)",
                    path, path));
  std::vector<double> scaled;
  for (const toml::node& x : a) scaled.push_back(x.value<double>().value_or(0.0) * value / norm);
  for (std::size_t i = 0; i < scaled.size(); ++i)
    a.replace(a.cbegin() + static_cast<std::ptrdiff_t>(i), scaled[i]);
}

// An array of tables whose every entry has a string `name`: its entries go by name.
bool entries_named(const toml::array& a) {
  if (!a.is_array_of_tables()) return false;
  for (const toml::node& entry : a)
    if (!entry.as_table()->get_as<std::string>("name")) return false;
  return true;
}

void collect_paths(const toml::node& n, const std::string& path, std::vector<std::string>& out) {
  if (is_number(n)) {
    out.push_back(path);
  } else if (const toml::table* t = n.as_table()) {
    for (auto&& [key, value] : *t)
      collect_paths(
          value, path.empty() ? std::string(key.str()) : path + "." + std::string(key.str()), out);
  } else if (const toml::array* a = n.as_array()) {
    if (is_vector(*a)) out.push_back(path);  // its magnitude; its components follow
    const bool named = entries_named(*a);
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::node& entry = *a->get(i);
      const auto name = toml::node_view<const toml::node>(entry)["name"].value<std::string>();
      collect_paths(entry, named && name ? path + "." + *name : fmt::format("{}[{}]", path, i),
                    out);
    }
  }
}

}  // namespace

std::optional<double> number_at_path(const toml::table& doc, std::string_view path) {
  const auto steps = parse_path(path);
  if (!steps) return std::nullopt;
  const toml::node* n = resolve(doc, *steps);
  if (n && is_vector(*n)) return magnitude(*n->as_array());
  if (!n || !is_number(*n)) return std::nullopt;
  return n->value<double>();
}

std::vector<std::string> number_paths(const toml::table& doc) {
  std::vector<std::string> out;
  collect_paths(doc, "", out);
  return out;
}

void set_number_at_path(toml::table& doc, std::string_view path, double value) {
  const auto steps = parse_path(path);
  // resolve() only reads; the node it finds belongs to `doc`, which is not const here.
  toml::node* n = steps ? const_cast<toml::node*>(resolve(doc, *steps)) : nullptr;
  if (n && is_vector(*n)) return set_magnitude(*n->as_array(), path, value);
  if (!n || !is_number(*n))
    throw std::invalid_argument(fmt::format("no number at path \"{}\"", path));
  if (toml::value<double>* f = n->as_floating_point()) {
    *f = value;
    return;
  }
  if (value != std::trunc(value) || std::abs(value) > 9.0e15)
    throw std::invalid_argument(
        fmt::format("\"{}\" is an integer in the scene; {} is not", path, value));
  *n->as_integer() = static_cast<std::int64_t>(value);
}

std::string path_problem(const toml::table& doc, std::string_view path) {
  const std::vector<std::string> paths = number_paths(doc);
  const std::vector<std::string_view> views(paths.begin(), paths.end());
  const std::string_view nearest = closest_name(path, views);
  if (!nearest.empty())
    return fmt::format("no number at this path of the scene (did you mean \"{}\"?)", nearest);
  // The longest beginning of the path that some number path shares, and those paths.
  std::string prefix(path);
  while (!prefix.empty()) {
    std::vector<std::string_view> under;
    for (std::string_view p : views)
      if (p.starts_with(prefix) && p.size() > prefix.size() &&
          (p[prefix.size()] == '.' || p[prefix.size()] == '['))
        under.push_back(p);
    if (!under.empty()) {
      if (under.size() > 8) under.resize(8);
      return fmt::format("no number at this path of the scene; paths under \"{}\": {}", prefix,
                         fmt::join(under, ", "));
    }
    const std::size_t cut = prefix.find_last_of(".[");
    prefix = cut == std::string::npos ? "" : prefix.substr(0, cut);
  }
  if (views.size() > 8)
    return fmt::format("no number at this path of the scene; its paths begin {}, ...",
                       fmt::join(views.begin(), views.begin() + 8, ", "));
  return fmt::format("no number at this path of the scene; its paths: {}", fmt::join(views, ", "));
}

std::string document_text(const toml::table& doc) {
  std::ostringstream out;
  out << toml::toml_formatter(doc, toml::format_flags::none);
  out << '\n';
  return out.str();
}

}  // namespace ccm
