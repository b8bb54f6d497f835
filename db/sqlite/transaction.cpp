#include "db/sqlite/transaction.hpp"

#include <sqlite3.h>

#include <atomic>

namespace ccm::db {

namespace {
std::string next_savepoint_name() {
  static std::atomic<long> counter{0};
  return "ccm_sp_" + std::to_string(counter++);
}
}  // namespace

Transaction::Transaction(Connection& connection)
    : connection_(connection), outermost_(!connection.in_transaction()) {
  if (outermost_) {
    connection_.exec("BEGIN IMMEDIATE", "cannot start a write transaction");
  } else {
    savepoint_ = next_savepoint_name();
    connection_.exec("SAVEPOINT " + savepoint_, "cannot open a savepoint");
  }
}

Transaction::~Transaction() {
  if (done_) return;
  // Errors are ignored here: a failed rollback leaves SQLite to roll back on close.
  const std::string sql =
      outermost_ ? "ROLLBACK" : "ROLLBACK TO " + savepoint_ + "; RELEASE " + savepoint_;
  sqlite3_exec(connection_.handle(), sql.c_str(), nullptr, nullptr, nullptr);
}

void Transaction::commit() {
  connection_.exec(outermost_ ? "COMMIT" : "RELEASE " + savepoint_, "cannot commit");
  done_ = true;
}

}  // namespace ccm::db
