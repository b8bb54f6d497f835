#include "config/strict_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "config/config_error.hpp"
#include "config/did_you_mean.hpp"

namespace ccm {
namespace {

int line_of(const toml::node& n) { return std::max(1, static_cast<int>(n.source().begin.line)); }

std::string_view type_name(const toml::node& n) {
  if (n.is_table()) return "a table";
  if (n.is_array()) return "an array";
  if (n.is_string()) return "a string";
  if (n.is_integer()) return "an integer";
  if (n.is_floating_point()) return "a float";
  if (n.is_boolean()) return "a boolean";
  return "a date or time";
}

}  // namespace

std::string StrictTable::key_path(std::string_view key) const {
  if (key.empty()) return path_;
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

int StrictTable::line_of_key(std::string_view key) const {
  const toml::node* n = key.empty() ? nullptr : t_->get(key);
  return n ? line_of(*n) : line_of(*t_);
}

void StrictTable::fail(std::string_view key, std::string_view problem) const {
  throw config_error(*file_, line_of_key(key), key_path(key), problem);
}

void StrictTable::allow_only(std::initializer_list<std::string_view> allowed) const {
  allow_only(std::vector<std::string_view>(allowed));
}

void StrictTable::allow_only(const std::vector<std::string_view>& allowed) const {
  for (auto&& [k, v] : *t_) {
    if (std::find(allowed.begin(), allowed.end(), k.str()) != allowed.end()) continue;
    const std::string_view best = closest_name(k.str(), allowed);
    if (!best.empty())
      fail(k.str(), fmt::format("unknown key '{}' (did you mean '{}'?)", k.str(), best));
    fail(k.str(), fmt::format("unknown key '{}' (allowed: {})", k.str(), fmt::join(allowed, ", ")));
  }
}

void StrictTable::wrong_type(const toml::node& n, std::string_view path,
                             std::string_view expected) const {
  throw config_error(*file_, line_of(n), path,
                     fmt::format("expected {}, got {}", expected, type_name(n)));
}

double StrictTable::to_number(const toml::node& n, std::string_view path) const {
  double v = 0.0;
  if (const auto* f = n.as_floating_point())
    v = f->get();
  else if (const auto* i = n.as_integer())
    v = static_cast<double>(i->get());
  else
    wrong_type(n, path, "a number");
  if (!std::isfinite(v))
    throw config_error(*file_, line_of(n), path, fmt::format("must be finite (got {})", v));
  return v;
}

std::optional<double> StrictTable::number(std::string_view key) const {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  return to_number(*n, key_path(key));
}

double StrictTable::need_number(std::string_view key) const {
  if (auto v = number(key)) return *v;
  fail(key, "required key is missing");
}

double StrictTable::number_or(std::string_view key, double fallback) const {
  return number(key).value_or(fallback);
}

std::optional<long> StrictTable::integer(std::string_view key) const {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  if (!n->is_integer()) wrong_type(*n, key_path(key), "an integer");
  return static_cast<long>(n->as_integer()->get());
}

long StrictTable::need_integer(std::string_view key) const {
  if (auto v = integer(key)) return *v;
  fail(key, "required key is missing");
}

std::optional<std::string> StrictTable::string(std::string_view key) const {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  if (!n->is_string()) wrong_type(*n, key_path(key), "a string");
  return n->as_string()->get();
}

std::string StrictTable::need_string(std::string_view key) const {
  auto v = string(key);
  if (!v) fail(key, "required key is missing");
  if (v->empty()) fail(key, "must not be empty");
  return *v;
}

std::vector<double> StrictTable::number_array(std::string_view key) const {
  const toml::node* n = t_->get(key);
  if (!n) fail(key, "required key is missing");
  const toml::array* a = n->as_array();
  if (!a) wrong_type(*n, key_path(key), "an array of numbers");
  if (a->empty()) fail(key, "must not be empty");
  std::vector<double> out;
  for (size_t i = 0; i < a->size(); ++i)
    out.push_back(to_number((*a)[i], fmt::format("{}[{}]", key_path(key), i)));
  return out;
}

std::optional<StrictTable> StrictTable::table(std::string_view key) const {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  if (!n->is_table()) wrong_type(*n, key_path(key), "a table");
  return StrictTable(*n->as_table(), key_path(key), *file_);
}

StrictTable StrictTable::need_table(std::string_view key) const {
  if (auto t = table(key)) return *t;
  fail(key, "required table is missing");
}

std::vector<StrictTable> StrictTable::tables(std::string_view key) const {
  std::vector<StrictTable> out;
  const toml::node* n = t_->get(key);
  if (!n) return out;
  if (!n->is_array()) wrong_type(*n, key_path(key), "an array of tables");
  const toml::array& a = *n->as_array();
  for (size_t i = 0; i < a.size(); ++i) {
    const std::string path = fmt::format("{}[{}]", key_path(key), i);
    if (!a[i].is_table()) wrong_type(a[i], path, "a table");
    out.emplace_back(*a[i].as_table(), path, *file_);
  }
  return out;
}

std::vector<StrictTable> StrictTable::need_tables(std::string_view key) const {
  if (!has(key)) fail(key, "required key is missing");
  std::vector<StrictTable> out = tables(key);
  if (out.empty()) fail(key, "must not be empty");
  return out;
}

}  // namespace ccm
