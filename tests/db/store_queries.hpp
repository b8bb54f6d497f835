// Raw SQL probes the store tests use to look at what is really in the file.
#pragma once

#include <string>

#include "db/sqlite/connection.hpp"
#include "db/sqlite/statement.hpp"

namespace ccm::test {

inline long long count_rows(db::Connection& c, const std::string& sql) {
  db::Statement q(c, sql);
  q.step();
  return q.column_int(0);
}

inline std::string integrity_check(db::Connection& c) {
  db::Statement q(c, "PRAGMA integrity_check");
  q.step();
  return q.column_text(0);
}

}  // namespace ccm::test
