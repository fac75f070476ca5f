#include "sqlite_database.hpp"

#include <sqlite3.h>

#include <limits>

namespace imasim::metrics {

namespace {

const char* kind_name(int type) {
  switch (type) {
    case SQLITE_INTEGER:
      return "an integer";
    case SQLITE_FLOAT:
      return "a real number";
    case SQLITE_TEXT:
      return "text";
    case SQLITE_BLOB:
      return "a blob";
    default:
      return "NULL";
  }
}

[[noreturn]] void throw_failure(const std::string& path, std::string_view what, int code,
                                const std::string& reason) {
  if ((code & 0xff) == SQLITE_NOTADB)
    throw RecordsError(path + ": is not an SQLite database (" + std::string(what) + ": " + reason +
                       ")");
  const std::string message =
      path + ": " + std::string(what) + ": " + reason + " (code " + std::to_string(code) + ")";
  if ((code & 0xff) == SQLITE_BUSY || (code & 0xff) == SQLITE_LOCKED) throw RecordsBusy(message);
  throw RecordsError(message);
}

}  // namespace

SqliteDatabase::SqliteDatabase(std::string path, int flags, int busy_timeout_ms)
    : path_(std::move(path)) {
  const int rc = sqlite3_open_v2(path_.c_str(), &db_, flags, nullptr);
  if (rc != SQLITE_OK) {
    // Even a failed open may return a handle (for its message); it must be closed.
    const std::string reason = db_ != nullptr ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw RecordsError(path_ + ": cannot open the trainee records: " + reason);
  }
  sqlite3_extended_result_codes(db_, 1);
  if (const int busy = sqlite3_busy_timeout(db_, busy_timeout_ms); busy != SQLITE_OK) {
    const std::string reason = sqlite3_errmsg(db_);
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw RecordsError(path_ + ": cannot set the busy timeout: " + reason);
  }
}

SqliteDatabase::~SqliteDatabase() {
  // Statements are finalized before their connection (they are owned by callers' scopes);
  // close_v2 defers the close should one remain, so nothing leaks either way.
  sqlite3_close_v2(db_);
}

void SqliteDatabase::fail(std::string_view what, int code) const {
  throw_failure(path_, what, code, db_ != nullptr ? sqlite3_errmsg(db_) : sqlite3_errstr(code));
}

void SqliteDatabase::execute(const char* sql, std::string_view what) {
  if (!execute_unless_busy(sql, what)) fail(what, sqlite3_extended_errcode(db_));
}

bool SqliteDatabase::execute_unless_busy(const char* sql, std::string_view what) {
  char* message = nullptr;
  const int rc = sqlite3_exec(db_, sql, nullptr, nullptr, &message);
  if (rc == SQLITE_OK) return true;
  if ((rc & 0xff) == SQLITE_BUSY || (rc & 0xff) == SQLITE_LOCKED) {
    sqlite3_free(message);
    return false;
  }
  const std::string reason = message != nullptr ? message : sqlite3_errstr(rc);
  sqlite3_free(message);
  throw_failure(path_, what, rc, reason);
}

SqliteStatement SqliteDatabase::prepare(const char* sql, std::string_view what) {
  return SqliteStatement(*this, sql, what, db_);
}

std::int64_t SqliteDatabase::last_insert_rowid() const {
  return sqlite3_last_insert_rowid(db_);
}

void SqliteDatabase::set_busy_timeout(int ms) {
  if (const int rc = sqlite3_busy_timeout(db_, ms); rc != SQLITE_OK)
    fail("setting the busy timeout", rc);
}

bool SqliteDatabase::read_only() const {
  return sqlite3_db_readonly(db_, "main") == 1;
}

SqliteStatement::SqliteStatement(const SqliteDatabase& db, const char* sql, std::string_view what,
                                 sqlite3* raw)
    : db_(&db), what_(what) {
  if (const int rc = sqlite3_prepare_v2(raw, sql, -1, &stmt_, nullptr); rc != SQLITE_OK)
    db_->fail(what_, rc);
}

SqliteStatement::SqliteStatement(SqliteStatement&& other) noexcept
    : db_(other.db_), what_(std::move(other.what_)), stmt_(other.stmt_) {
  other.stmt_ = nullptr;
}

SqliteStatement::~SqliteStatement() {
  sqlite3_finalize(stmt_);
}

void SqliteStatement::bind(int index, double value) {
  if (const int rc = sqlite3_bind_double(stmt_, index, value); rc != SQLITE_OK)
    db_->fail(what_, rc);
}

void SqliteStatement::bind(int index, std::int64_t value) {
  if (const int rc = sqlite3_bind_int64(stmt_, index, value); rc != SQLITE_OK) db_->fail(what_, rc);
}

void SqliteStatement::bind(int index, std::string_view text) {
  if (text.size() > std::size_t(std::numeric_limits<int>::max())) db_->fail(what_, SQLITE_TOOBIG);
  // SQLITE_TRANSIENT: SQLite copies the text, so the view may end before the step.
  if (const int rc =
          sqlite3_bind_text(stmt_, index, text.data(), int(text.size()), SQLITE_TRANSIENT);
      rc != SQLITE_OK)
    db_->fail(what_, rc);
}

bool SqliteStatement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  db_->fail(what_, rc);
}

void SqliteStatement::reset() {
  if (const int rc = sqlite3_reset(stmt_); rc != SQLITE_OK) db_->fail(what_, rc);
  if (const int rc = sqlite3_clear_bindings(stmt_); rc != SQLITE_OK) db_->fail(what_, rc);
}

void SqliteStatement::check_type(int index, int expected) const {
  const int type = sqlite3_column_type(stmt_, index);
  if (type == expected) return;
  throw RecordsError(db_->path() + ": " + what_ + ": column '" + sqlite3_column_name(stmt_, index) +
                     "' holds " + kind_name(type) + ", expected " + kind_name(expected));
}

double SqliteStatement::real_column(int index) const {
  check_type(index, SQLITE_FLOAT);
  return sqlite3_column_double(stmt_, index);
}

std::int64_t SqliteStatement::integer_column(int index) const {
  check_type(index, SQLITE_INTEGER);
  return sqlite3_column_int64(stmt_, index);
}

std::string SqliteStatement::text_column(int index) const {
  check_type(index, SQLITE_TEXT);
  const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, index));
  const int bytes = sqlite3_column_bytes(stmt_, index);
  if (text == nullptr) db_->fail(what_, SQLITE_NOMEM);
  return std::string(text, std::size_t(bytes));
}

}  // namespace imasim::metrics
