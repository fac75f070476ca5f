#include "records_path.hpp"

#include <cstdlib>
#include <filesystem>

#include "metrics/sqlite_database.hpp"

namespace imasim::metrics {

std::string records_path_from(const char* xdg_data_home, const char* home) {
  namespace fs = std::filesystem;
  if (xdg_data_home != nullptr && fs::path(xdg_data_home).is_absolute())
    return (fs::path(xdg_data_home) / "imasim" / "trainees.sqlite").string();
  if (home != nullptr && fs::path(home).is_absolute())
    return (fs::path(home) / ".local" / "share" / "imasim" / "trainees.sqlite").string();
  throw RecordsError(
      "cannot place the trainee records: neither XDG_DATA_HOME nor HOME is an absolute path "
      "(name the database with --db PATH)");
}

std::string default_records_path() {
  return records_path_from(std::getenv("XDG_DATA_HOME"), std::getenv("HOME"));
}

void create_records_directory(const std::string& database_path) {
  namespace fs = std::filesystem;
  const fs::path directory = fs::path(database_path).parent_path();
  if (directory.empty()) return;
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec)
    throw RecordsError("cannot create the directory " + directory.string() +
                       " for the trainee records: " + ec.message());
}

}  // namespace imasim::metrics
