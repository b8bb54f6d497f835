// RAII prepared statement with typed binds (1-based, as in SQLite) and typed column reads.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "db/sqlite/connection.hpp"

struct sqlite3_stmt;

namespace ccm::db {

class Statement {
 public:
  Statement(Connection& connection, std::string_view sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, double value);
  Statement& bind(int index, long long value);
  Statement& bind(int index, int value) { return bind(index, static_cast<long long>(value)); }
  Statement& bind(int index, long value) { return bind(index, static_cast<long long>(value)); }
  Statement& bind(int index, std::string_view value);
  Statement& bind(int index, const char* value) { return bind(index, std::string_view(value)); }
  Statement& bind(int index, const std::string& value) {
    return bind(index, std::string_view(value));
  }
  Statement& bind_null(int index);
  Statement& bind(int index, std::optional<double> value) {
    return value ? bind(index, *value) : bind_null(index);
  }

  // Advances to the next row: true while a row is available, false when done.
  bool step();
  // Steps a statement that returns no rows.
  void run() { step(); }
  void reset();

  bool is_null(int column) const;
  double column_double(int column) const;
  long long column_int(int column) const;
  std::string column_text(int column) const;
  std::optional<double> column_optional_double(int column) const;

 private:
  Connection& connection_;
  sqlite3_stmt* stmt_ = nullptr;
  std::string sql_;
};

}  // namespace ccm::db
