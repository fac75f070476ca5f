#pragma once
// A thin RAII layer over the sqlite3 C API for the trainee records: a connection and its
// prepared statements, every return code checked. A failure throws RecordsError naming the
// database file, what was being done and SQLite's own reason.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace imasim::metrics {

class RecordsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Another connection held a lock past the busy timeout: the same failure, worth another try.
class RecordsBusy : public RecordsError {
 public:
  using RecordsError::RecordsError;
};

class SqliteStatement;

class SqliteDatabase {
 public:
  // Opens `path` with sqlite3_open_v2 `flags` (SQLITE_OPEN_*) and waits up to `busy_timeout_ms`
  // for another process's lock before a statement reports it busy.
  SqliteDatabase(std::string path, int flags, int busy_timeout_ms);
  SqliteDatabase(const SqliteDatabase&) = delete;
  SqliteDatabase& operator=(const SqliteDatabase&) = delete;
  ~SqliteDatabase();

  // Runs statements that return no rows we need ("BEGIN IMMEDIATE", "CREATE TABLE ...").
  void execute(const char* sql, std::string_view what);
  // As execute, but false instead of an error when another connection holds a lock.
  bool execute_unless_busy(const char* sql, std::string_view what);
  SqliteStatement prepare(const char* sql, std::string_view what);
  std::int64_t last_insert_rowid() const;
  // How long a statement waits for another connection's lock before it is busy (unit: ms).
  void set_busy_timeout(int ms);
  // Whether the file can only be read (write-protected, a read-only file system).
  bool read_only() const;

  const std::string& path() const { return path_; }
  // "PATH: WHAT: SQLite's message (code N)"; RecordsBusy for a lock held past the timeout.
  [[noreturn]] void fail(std::string_view what, int code) const;

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
};

class SqliteStatement {
 public:
  SqliteStatement(const SqliteDatabase& db, const char* sql, std::string_view what, sqlite3* raw);
  SqliteStatement(SqliteStatement&& other) noexcept;
  SqliteStatement& operator=(SqliteStatement&&) = delete;
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;
  ~SqliteStatement();

  // Parameters count from 1, as in SQL's ?1.
  void bind(int index, double value);
  void bind(int index, std::int64_t value);
  void bind(int index, std::string_view text);
  // True when a row is ready to read, false when the statement has finished.
  bool step();
  // Makes the statement ready to run again with new parameters.
  void reset();

  // Columns count from 0. A NULL or a value of another type is refused (the schema has none).
  double real_column(int index) const;
  std::int64_t integer_column(int index) const;
  std::string text_column(int index) const;

 private:
  void check_type(int index, int expected) const;

  const SqliteDatabase* db_;
  std::string what_;
  sqlite3_stmt* stmt_ = nullptr;
};

}  // namespace imasim::metrics
