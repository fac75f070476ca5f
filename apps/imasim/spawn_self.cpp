#include "spawn_self.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cstdlib>
#include <string_view>

extern char** environ;

namespace imasim::cli {

pid_t spawn_self(const std::vector<std::string>& args, const std::string& stdout_path,
                 const std::string& stderr_path, int& error) {
  std::vector<std::string> words = {"imasim"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words)
    argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  constexpr int kFlags = O_WRONLY | O_CREAT | O_TRUNC;
  if (!stdout_path.empty())
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, stdout_path.c_str(), kFlags, 0644);
  if (!stderr_path.empty())
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_path.c_str(), kFlags, 0644);
  // The child learns who its parent is, to die with it (die_with_parent).
  std::vector<std::string> env_words;
  for (char** e = environ; *e != nullptr; ++e)
    if (!std::string_view(*e).starts_with(std::string(kParentPidVariable) + "="))
      env_words.emplace_back(*e);
  env_words.push_back(std::string(kParentPidVariable) + "=" + std::to_string(::getpid()));
  std::vector<char*> envp;
  for (std::string& w : env_words)
    envp.push_back(w.data());
  envp.push_back(nullptr);
  pid_t pid = -1;
  error = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  return error == 0 ? pid : -1;
}

void die_with_parent() {
  const char* given = std::getenv(kParentPidVariable);
  if (given == nullptr) return;
  char* end = nullptr;
  const long parent = std::strtol(given, &end, 10);
  ::unsetenv(kParentPidVariable);
  if (end == given || *end != '\0' || parent <= 1) return;
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  // The parent may have died before the line above: then this process is already an orphan.
  if (::getppid() != pid_t(parent)) ::_exit(137);
}

}  // namespace imasim::cli
