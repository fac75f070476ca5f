#pragma once
// Starting this very program (/proc/self/exe) as a child: the device emulator beside a live run,
// the trials of a study.
#include <sys/types.h>

#include <string>
#include <vector>

namespace imasim::cli {

// `args` follow the program's name. Its stdout and stderr go to the files named (created or
// truncated; "/dev/null" to drop them), or stay ours where a name is empty. Returns the child's
// pid, or -1 with the reason in `error` (errno's, from posix_spawn).
pid_t spawn_self(const std::vector<std::string>& args, const std::string& stdout_path,
                 const std::string& stderr_path, int& error);

}  // namespace imasim::cli
