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
// The child is told its parent's pid (kParentPidVariable) and dies with it (die_with_parent):
// a study killed with SIGKILL left its running trials as orphans, which went on writing records.
pid_t spawn_self(const std::vector<std::string>& args, const std::string& stdout_path,
                 const std::string& stderr_path, int& error);

inline constexpr const char* kParentPidVariable = "IMASIM_PARENT_PID";

// In main(), first: a process started by spawn_self is killed (SIGKILL) when its parent dies,
// and exits at once if the parent is already gone. Nothing for any other process.
void die_with_parent();

}  // namespace imasim::cli
