#pragma once
// Where the trainee records live unless --db says otherwise: the user's data directory of the
// XDG Base Directory specification, $XDG_DATA_HOME/imasim/trainees.sqlite, else
// $HOME/.local/share/imasim/trainees.sqlite.
#include <string>

namespace imasim::metrics {

// From the two variables' values (null when unset). XDG_DATA_HOME counts only when it is an
// absolute path, as the specification says. RecordsError when neither gives a directory.
std::string records_path_from(const char* xdg_data_home, const char* home);

// From this process's environment.
std::string default_records_path();

// Creates the directories above `database_path` that are missing; RecordsError naming the
// directory and the system's reason when that fails.
void create_records_directory(const std::string& database_path);

}  // namespace imasim::metrics
