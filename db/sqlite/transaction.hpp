// RAII transaction: rolled back unless commit() is called. The outermost one is
// BEGIN IMMEDIATE (takes the write lock at once, so a concurrent writer waits on the busy
// timeout instead of failing on a lock upgrade); nested ones are savepoints.
#pragma once

#include <string>

#include "db/sqlite/connection.hpp"

namespace ccm::db {

class Transaction {
 public:
  explicit Transaction(Connection& connection);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;

  void commit();

 private:
  Connection& connection_;
  bool outermost_ = true;
  bool done_ = false;
  std::string savepoint_;
};

}  // namespace ccm::db
