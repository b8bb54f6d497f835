// Strict, typed reads of one table of a configuration file (toml++): grid files and the rig's
// case and geometry files read through it. Every problem is reported as
// "<file>:<line>: <key path>: <problem>" (ccm::ConfigError), with a did-you-mean suggestion for
// a mistyped key (config/did_you_mean.hpp).
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ccm {

class StrictTable {
 public:
  StrictTable(const toml::table& t, std::string path, const std::filesystem::path& file)
      : t_(&t), path_(std::move(path)), file_(&file) {}

  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  int line_of_key(std::string_view key) const;  // the table's line when the key is absent
  bool has(std::string_view key) const { return t_->contains(key); }

  [[noreturn]] void fail(std::string_view key, std::string_view problem) const;
  void allow_only(std::initializer_list<std::string_view> allowed) const;
  void allow_only(const std::vector<std::string_view>& allowed) const;

  std::optional<double> number(std::string_view key) const;  // integer or float, finite
  double need_number(std::string_view key) const;
  double number_or(std::string_view key, double fallback) const;
  std::optional<long> integer(std::string_view key) const;
  long need_integer(std::string_view key) const;
  std::optional<std::string> string(std::string_view key) const;
  std::string need_string(std::string_view key) const;           // required, non-empty
  std::vector<double> number_array(std::string_view key) const;  // required, non-empty

  std::optional<StrictTable> table(std::string_view key) const;
  StrictTable need_table(std::string_view key) const;
  std::vector<StrictTable> tables(std::string_view key) const;  // array of tables; empty if absent
  std::vector<StrictTable> need_tables(std::string_view key) const;  // required, non-empty

 private:
  [[noreturn]] void wrong_type(const toml::node& n, std::string_view path,
                               std::string_view expected) const;
  double to_number(const toml::node& n, std::string_view path) const;

  const toml::table* t_;
  std::string path_;
  const std::filesystem::path* file_;
};

}  // namespace ccm
