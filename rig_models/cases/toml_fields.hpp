// Typed reads from one TOML table of a rig file, every failure a RigInputError reading
// "<file>:<line>: <key path>: <problem>".
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "rig_models/core/rig_error.hpp"

namespace ccm::rig {

class TomlFields {
 public:
  TomlFields(const toml::table& table, std::string path, const std::filesystem::path& file);

  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  int line_of(std::string_view key) const;  // the key's line, else the table's

  [[noreturn]] void fail(std::string_view key, std::string_view problem) const;

  // Rejects a key not in `allowed`, suggesting the nearest allowed one.
  void allow_only(std::initializer_list<std::string_view> allowed) const;

  double need_number(std::string_view key) const;  // integer or float, finite
  long need_integer(std::string_view key) const;
  std::string need_string(std::string_view key) const;  // non-empty
  bool has(std::string_view key) const { return table_->contains(key); }
  TomlFields need_table(std::string_view key) const;
  std::vector<TomlFields> need_tables(std::string_view key) const;  // [[key]], not empty

 private:
  const toml::node& need_node(std::string_view key) const;
  [[noreturn]] void wrong_type(std::string_view key, std::string_view expected) const;

  const toml::table* table_;
  std::string path_;
  const std::filesystem::path* file_;
};

}  // namespace ccm::rig
