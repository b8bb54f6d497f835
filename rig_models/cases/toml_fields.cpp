#include "rig_models/cases/toml_fields.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::rig {
namespace {

int line_of_node(const toml::node& n) {
  return std::max(1, static_cast<int>(n.source().begin.line));
}

std::string_view type_name(const toml::node& n) {
  if (n.is_table()) return "a table";
  if (n.is_array()) return "an array";
  if (n.is_string()) return "a string";
  if (n.is_integer()) return "an integer";
  if (n.is_floating_point()) return "a float";
  if (n.is_boolean()) return "a boolean";
  return "a date or time";
}

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

TomlFields::TomlFields(const toml::table& table, std::string path,
                       const std::filesystem::path& file)
    : table_(&table), path_(std::move(path)), file_(&file) {}

std::string TomlFields::key_path(std::string_view key) const {
  if (path_.empty()) return std::string(key);
  if (key.empty()) return path_;
  return fmt::format("{}.{}", path_, key);
}

int TomlFields::line_of(std::string_view key) const {
  const toml::node* n = key.empty() ? nullptr : table_->get(key);
  return line_of_node(n ? *n : static_cast<const toml::node&>(*table_));
}

void TomlFields::fail(std::string_view key, std::string_view problem) const {
  throw rig_input_error(*file_, line_of(key), key_path(key), problem);
}

void TomlFields::allow_only(std::initializer_list<std::string_view> allowed) const {
  for (auto&& [k, v] : *table_) {
    const std::string_view key = k.str();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string_view best;
    size_t best_d = key.size();
    for (std::string_view a : allowed)
      if (const size_t d = edit_distance(key, a); d < best_d) {
        best_d = d;
        best = a;
      }
    if (best_d <= 2) fail(key, fmt::format("unknown key '{}' (did you mean '{}'?)", key, best));
    fail(key, fmt::format("unknown key '{}' (allowed: {})", key, fmt::join(allowed, ", ")));
  }
}

const toml::node& TomlFields::need_node(std::string_view key) const {
  const toml::node* n = table_->get(key);
  if (!n) fail(key, "required key is missing");
  return *n;
}

void TomlFields::wrong_type(std::string_view key, std::string_view expected) const {
  fail(key, fmt::format("expected {}, got {}", expected, type_name(need_node(key))));
}

double TomlFields::need_number(std::string_view key) const {
  const toml::node& n = need_node(key);
  double v = 0.0;
  if (const auto* f = n.as_floating_point())
    v = f->get();
  else if (const auto* i = n.as_integer())
    v = static_cast<double>(i->get());
  else
    wrong_type(key, "a number");
  if (!std::isfinite(v)) fail(key, fmt::format("must be finite (got {})", v));
  return v;
}

long TomlFields::need_integer(std::string_view key) const {
  const toml::node& n = need_node(key);
  if (!n.is_integer()) wrong_type(key, "an integer");
  return static_cast<long>(n.as_integer()->get());
}

std::string TomlFields::need_string(std::string_view key) const {
  const toml::node& n = need_node(key);
  if (!n.is_string()) wrong_type(key, "a string");
  std::string s = n.as_string()->get();
  if (s.empty()) fail(key, "must not be empty");
  return s;
}

TomlFields TomlFields::need_table(std::string_view key) const {
  const toml::node& n = need_node(key);
  if (!n.is_table()) wrong_type(key, "a table");
  return TomlFields(*n.as_table(), key_path(key), *file_);
}

std::vector<TomlFields> TomlFields::need_tables(std::string_view key) const {
  const toml::node& n = need_node(key);
  if (!n.is_array()) wrong_type(key, "an array of tables ([[" + std::string(key) + "]])");
  const toml::array& a = *n.as_array();
  if (a.empty()) fail(key, "must not be empty");
  std::vector<TomlFields> out;
  for (size_t i = 0; i < a.size(); ++i) {
    const std::string path = fmt::format("{}[{}]", key_path(key), i);
    if (!a[i].is_table())
      throw rig_input_error(*file_, line_of_node(a[i]), path,
                            fmt::format("expected a table, got {}", type_name(a[i])));
    out.emplace_back(*a[i].as_table(), path, *file_);
  }
  return out;
}

}  // namespace ccm::rig
