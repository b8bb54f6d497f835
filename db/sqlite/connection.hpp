// RAII handle of one SQLite connection, with errors that name the database file.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

struct sqlite3;

namespace ccm::db {

// Every failure of the store: the message names the file and what was being done.
class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How a file is opened. read_only never creates or changes a file: the database must exist;
// a WAL database without a -wal file (no writer has it open) is read as immutable, so that
// SQLite creates no -wal or -shm file beside it; with a -wal file (a writer at work, or one
// that was killed) the writer's -wal and -shm are read.
enum class Access { read_write, read_only };

class Connection {
 public:
  // Opens the database file (read_write: creating it if absent) with a busy timeout so that
  // concurrent writers wait for each other instead of failing at once.
  explicit Connection(const std::filesystem::path& file, Access access = Access::read_write,
                      int busy_timeout_ms = 30000);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // Runs one or more statements that return no rows; throws StoreError naming `what`.
  void exec(std::string_view sql, std::string_view what = {});
  long long last_insert_rowid() const;
  int changes() const;  // rows changed by the last statement
  bool in_transaction() const;

  // Replaces the connection by one to an in-memory copy of the database (SQLite's backup API),
  // still named after the file: what a read-only command migrates instead of the file.
  void copy_into_memory();

  sqlite3* handle() const { return db_; }
  const std::filesystem::path& file() const { return file_; }

  // "<file>: <what>: <sqlite message>" for an error code returned by the library.
  [[noreturn]] void fail(std::string_view what) const;

 private:
  sqlite3* db_ = nullptr;
  std::filesystem::path file_;
};

}  // namespace ccm::db
