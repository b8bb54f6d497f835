#include "config/strict_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "config/config_error.hpp"
#include "config/did_you_mean.hpp"

namespace ccm {
namespace {

int line_of(const toml::node& n) { return std::max(1, static_cast<int>(n.source().begin.line)); }

std::string_view type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

}  // namespace

std::string unknown_key_problem(std::string_view key, std::span<const std::string_view> allowed) {
  const std::string_view best = closest_name(key, allowed);
  if (!best.empty()) return fmt::format("unknown key '{}' (did you mean '{}'?)", key, best);
  return fmt::format("unknown key '{}' (allowed: {})", key, fmt::join(allowed, ", "));
}

toml::table parse_toml(std::string_view text, const std::filesystem::path& source) {
  try {
    return toml::parse(text, source.string());
  } catch (const toml::parse_error& e) {
    throw config_error(source, static_cast<int>(e.source().begin.line), "",
                       fmt::format("TOML syntax error: {}", e.description()));
  }
}

int StrictTable::line() const { return line_of(*t_); }

std::string StrictTable::key_path(std::string_view key) const {
  if (key.empty()) return path_;
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

int StrictTable::line_of_key(std::string_view key) const {
  const toml::node* n = key.empty() ? nullptr : t_->get(key);
  return n ? line_of(*n) : line();
}

std::string StrictTable::where(std::string_view key) const {
  return fmt::format("{}:{}: {}", file_->string(), line_of_key(key), key_path(key));
}

std::map<std::string, int, std::less<>> StrictTable::key_lines() const {
  std::map<std::string, int, std::less<>> lines;
  for (auto&& [k, v] : *t_) lines.emplace(std::string(k.str()), line_of(v));
  return lines;
}

void StrictTable::fail(std::string_view key, std::string_view problem) const {
  throw config_error(*file_, line_of_key(key), key_path(key), problem);
}

void StrictTable::fail_at(const toml::node& n, std::string_view key_path,
                          std::string_view problem) const {
  throw config_error(*file_, line_of(n), key_path, problem);
}

void StrictTable::wrong_type(const toml::node& n, std::string_view key_path,
                             std::string_view expected) const {
  fail_at(n, key_path, fmt::format("expected {}, got {}", expected, type_name(n.type())));
}

void StrictTable::allow_only(std::span<const std::string_view> allowed) const {
  for (auto&& [k, v] : *t_)
    if (std::find(allowed.begin(), allowed.end(), k.str()) == allowed.end())
      fail(k.str(), unknown_key_problem(k.str(), allowed));
}

void StrictTable::allow_only(std::initializer_list<std::string_view> allowed) const {
  allow_only(std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

void StrictTable::allow_only(const std::vector<std::string_view>& allowed) const {
  allow_only(std::span<const std::string_view>(allowed));
}

double StrictTable::number(const toml::node& n, std::string_view key_path) const {
  double v = 0.0;
  if (const auto* f = n.as_floating_point())
    v = f->get();
  else if (const auto* i = n.as_integer())
    v = static_cast<double>(i->get());
  else
    wrong_type(n, key_path, "a number");
  if (!std::isfinite(v)) fail_at(n, key_path, fmt::format("must be finite (got {})", v));
  return v;
}

template <>
double StrictTable::convert<double>(const toml::node& n, std::string_view key_path) const {
  return number(n, key_path);
}

template <>
long StrictTable::convert<long>(const toml::node& n, std::string_view key_path) const {
  if (!n.is_integer()) wrong_type(n, key_path, "an integer");
  return static_cast<long>(n.as_integer()->get());
}

template <>
bool StrictTable::convert<bool>(const toml::node& n, std::string_view key_path) const {
  if (!n.is_boolean()) wrong_type(n, key_path, "a boolean (true or false)");
  return n.as_boolean()->get();
}

template <>
std::string StrictTable::convert<std::string>(const toml::node& n,
                                              std::string_view key_path) const {
  if (!n.is_string()) wrong_type(n, key_path, "a string");
  return n.as_string()->get();
}

std::string StrictTable::need_string(std::string_view key) const {
  std::string v = need<std::string>(key);
  if (v.empty()) fail(key, "must not be empty");
  return v;
}

std::vector<double> StrictTable::number_array(std::string_view key) const {
  const toml::node* n = t_->get(key);
  if (!n) fail(key, "required key is missing");
  const toml::array* a = n->as_array();
  if (!a) wrong_type(*n, key_path(key), "an array of numbers");
  if (a->empty()) fail(key, "must not be empty");
  std::vector<double> out;
  for (size_t i = 0; i < a->size(); ++i)
    out.push_back(number((*a)[i], fmt::format("{}[{}]", key_path(key), i)));
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
