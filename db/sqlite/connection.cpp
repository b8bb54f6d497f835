#include "db/sqlite/connection.hpp"

#include <sqlite3.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "db/sqlite/disk_space.hpp"

namespace ccm::db {
namespace {

// "file:<path>?mode=ro[&immutable=1]" with the path percent-encoded (RFC 3986 unreserved
// characters and '/' are kept), for sqlite3_open_v2 with SQLITE_OPEN_URI.
std::string read_only_uri(const std::filesystem::path& file, bool immutable) {
  std::string uri = "file:";
  for (const unsigned char c : file.string()) {
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                       c == '/' || c == '-' || c == '.' || c == '_' || c == '~';
    if (plain) {
      uri += static_cast<char>(c);
    } else {
      constexpr const char* kHex = "0123456789ABCDEF";
      uri += '%';
      uri += kHex[c >> 4];
      uri += kHex[c & 0xF];
    }
  }
  return uri + (immutable ? "?mode=ro&immutable=1" : "?mode=ro");
}

// A WAL database's "-wal" file exists while a connection has it open (and after a writer was
// killed); without one, the main file holds every committed transaction.
bool has_wal_file(const std::filesystem::path& file) {
  std::error_code ignored;
  return std::filesystem::exists(file.string() + "-wal", ignored);
}

// A writer in SQLite's rollback-journal mode (a store being created or migrated, before it
// switches to WAL) writes the main file only while its "-journal" file exists. A reader that
// reads without locks (immutable=1, below) waits for it to go, up to the busy timeout: otherwise
// it may read pages half written ("database disk image is malformed").
void wait_for_rollback_writer(const std::filesystem::path& file, int timeout_ms) {
  const std::filesystem::path journal = file.string() + "-journal";
  std::error_code ignored;
  for (int waited = 0; waited < timeout_ms && std::filesystem::exists(journal, ignored);
       waited += 5)
    ::usleep(5000);
}

// A store a command will write must be writable, and so must its folder (SQLite keeps its -wal
// and -shm files, or a rollback journal, beside it): said before SQLite's "attempt to write a
// readonly database" surfaces from the first statement that writes.
void require_writable(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && ::access(file.c_str(), W_OK) != 0)
    throw StoreError(file.string() + ": the store is read-only (" + std::strerror(errno) +
                     "): a command that writes to it cannot use it; `ccm study status`, "
                     "`ccm recommend` and `ccm report` read it as it is");
  const std::filesystem::path folder =
      file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  if (std::filesystem::is_directory(folder, ec) && ::access(folder.c_str(), W_OK) != 0)
    throw StoreError(file.string() + ": its folder " + folder.string() + " is not writable (" +
                     std::strerror(errno) +
                     "): SQLite keeps the store's journal beside it; a command that writes "
                     "to the store cannot use it there");
}

}  // namespace

Connection::Connection(const std::filesystem::path& file, Access access, int busy_timeout_ms)
    : file_(file) {
  std::string name = file.string();
  int flags = SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX;
  if (access == Access::read_only) {
    const bool immutable = !has_wal_file(file);
    if (immutable) wait_for_rollback_writer(file, busy_timeout_ms);
    name = read_only_uri(file, immutable);
    flags = SQLITE_OPEN_READONLY | SQLITE_OPEN_URI | SQLITE_OPEN_FULLMUTEX;
  } else if (file != ":memory:") {
    require_writable(file);
  }
  if (sqlite3_open_v2(name.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError(file.string() + ": cannot open the study store: " + message);
  }
  sqlite3_extended_result_codes(db_, 1);
  sqlite3_busy_timeout(db_, busy_timeout_ms);
}

Connection::~Connection() { sqlite3_close(db_); }

void Connection::copy_into_memory() {
  sqlite3* memory = nullptr;
  if (sqlite3_open_v2(":memory:", &memory, SQLITE_OPEN_READWRITE | SQLITE_OPEN_FULLMUTEX,
                      nullptr) != SQLITE_OK) {
    sqlite3_close(memory);
    throw StoreError(file_.string() + ": cannot open an in-memory copy of the store");
  }
  sqlite3_backup* backup = sqlite3_backup_init(memory, "main", db_, "main");
  const bool copied = backup && sqlite3_backup_step(backup, -1) == SQLITE_DONE;
  sqlite3_backup_finish(backup);
  if (!copied) {
    const std::string message = sqlite3_errmsg(memory);
    sqlite3_close(memory);
    throw StoreError(file_.string() + ": cannot copy the store into memory: " + message);
  }
  sqlite3_extended_result_codes(memory, 1);
  sqlite3_close(db_);
  db_ = memory;
}

void Connection::exec(std::string_view sql, std::string_view what) {
  const std::string text(sql);
  if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK)
    fail(what.empty() ? std::string_view(text) : what);
}

long long Connection::last_insert_rowid() const { return sqlite3_last_insert_rowid(db_); }

int Connection::changes() const { return sqlite3_changes(db_); }

bool Connection::in_transaction() const { return sqlite3_get_autocommit(db_) == 0; }

void Connection::fail(std::string_view what) const {
  const int code = sqlite3_errcode(db_);
  const bool write_failed = code == SQLITE_FULL || code == SQLITE_IOERR;
  throw StoreError(file_.string() + ": " + std::string(what) + ": " + sqlite3_errmsg(db_) +
                   (write_failed ? disk_full_note(file_) : ""));
}

}  // namespace ccm::db
