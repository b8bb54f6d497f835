// The one strict, typed reader of a table of a configuration file (toml++): scene files
// (run/scene/scene_file.cpp, which adds vectors and source references), grid files and the rig's
// case and geometry files read through it. Every problem is reported as
// "<file>:<line>: <key path>: <problem>" (ccm::ConfigError), with a did-you-mean suggestion for
// a mistyped key (config/did_you_mean.hpp).
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ccm {

// The document of a configuration file's text; a syntax error is a ConfigError naming the file
// and the line: "<file>:<line>: TOML syntax error: <what>".
toml::table parse_toml(std::string_view text, const std::filesystem::path& source);

// "unknown key 'x' (did you mean 'y'?)", or with the allowed keys listed when none is close.
std::string unknown_key_problem(std::string_view key, std::span<const std::string_view> allowed);

class StrictTable {
 public:
  StrictTable(const toml::table& t, std::string path, const std::filesystem::path& file)
      : t_(&t), path_(std::move(path)), file_(&file) {}

  const std::filesystem::path& file() const { return *file_; }
  const std::string& path() const { return path_; }
  int line() const;  // the table's own line, >= 1
  std::string key_path(std::string_view key) const;
  int line_of_key(std::string_view key) const;  // the table's line when the key is absent
  // "<file>:<line>: <key path>" of a key (the table itself when key is empty).
  std::string where(std::string_view key) const;
  // The line of every key the table sets.
  std::map<std::string, int, std::less<>> key_lines() const;
  bool has(std::string_view key) const { return t_->contains(key); }
  const toml::node* node(std::string_view key) const { return t_->get(key); }

  [[noreturn]] void fail(std::string_view key, std::string_view problem) const;
  [[noreturn]] void fail_at(const toml::node& n, std::string_view key_path,
                            std::string_view problem) const;
  [[noreturn]] void wrong_type(const toml::node& n, std::string_view key_path,
                               std::string_view expected) const;
  void allow_only(std::span<const std::string_view> allowed) const;
  void allow_only(std::initializer_list<std::string_view> allowed) const;
  void allow_only(const std::vector<std::string_view>& allowed) const;

  // Typed reads, T one of double (integer or float, finite), long, bool, std::string.
  template <typename T>
  std::optional<T> get(std::string_view key) const {
    const toml::node* n = t_->get(key);
    if (!n) return std::nullopt;
    return convert<T>(*n, key_path(key));
  }
  template <typename T>
  T need(std::string_view key) const {
    if (auto v = get<T>(key)) return *v;
    fail(key, "required key is missing");
  }
  template <typename T>
  T get_or(std::string_view key, T fallback) const {
    return get<T>(key).value_or(fallback);
  }
  // A node's value as a finite number; the path names it in messages.
  double number(const toml::node& n, std::string_view key_path) const;

  std::optional<double> number(std::string_view key) const { return get<double>(key); }
  double need_number(std::string_view key) const { return need<double>(key); }
  double number_or(std::string_view key, double fallback) const {
    return get_or<double>(key, fallback);
  }
  std::optional<long> integer(std::string_view key) const { return get<long>(key); }
  long need_integer(std::string_view key) const { return need<long>(key); }
  std::optional<std::string> string(std::string_view key) const { return get<std::string>(key); }
  std::string need_string(std::string_view key) const;           // required, non-empty
  std::vector<double> number_array(std::string_view key) const;  // required, non-empty

  std::optional<StrictTable> table(std::string_view key) const;
  StrictTable need_table(std::string_view key) const;
  std::vector<StrictTable> tables(std::string_view key) const;  // array of tables; empty if absent
  std::vector<StrictTable> need_tables(std::string_view key) const;  // required, non-empty

 private:
  template <typename T>
  T convert(const toml::node& n, std::string_view key_path) const;

  const toml::table* t_;
  std::string path_;
  const std::filesystem::path* file_;
};

template <>
double StrictTable::convert<double>(const toml::node& n, std::string_view key_path) const;
template <>
long StrictTable::convert<long>(const toml::node& n, std::string_view key_path) const;
template <>
bool StrictTable::convert<bool>(const toml::node& n, std::string_view key_path) const;
template <>
std::string StrictTable::convert<std::string>(const toml::node& n, std::string_view key_path) const;

}  // namespace ccm
