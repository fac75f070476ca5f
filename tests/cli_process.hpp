#pragma once
// Running `imasim` as a user does, for the command-line suites: a shell command whose stdout is
// captured and whose stderr goes to a file, kept apart.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace imasim::test {

struct Finished {
  int exit_code = -1;  // -1 when ended by a signal
  int signal = 0;
  std::string out, err;
};

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Width and height from a PNG's header (IHDR), or {0, 0} when the file is no PNG.
inline std::pair<unsigned, unsigned> png_size(const std::string& path) {
  const std::string b = read_file(path);
  if (b.size() < 24 || b.compare(1, 3, "PNG") != 0 || b.compare(12, 4, "IHDR") != 0) return {0, 0};
  auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t k = 0; k < 4; ++k)
      v = (v << 8) | static_cast<unsigned char>(b[at + k]);
    return v;
  };
  return {be32(16), be32(20)};
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);)
    lines.push_back(line);
  return lines;
}

// Runs `command` (which sends its stderr to `err_path`), keeping stdout and stderr apart.
// A file for the running test's stderr, `stem` and the test's own name: ctest runs two tests of
// a suite at a time, and a file shared by the suite let one read the other's messages.
inline std::string test_err_file(const std::string& directory, const std::string& stem) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  return directory + stem + "_" + (test ? test->name() : "none") + ".stderr";
}

inline Finished run_shell(const std::string& command, const std::string& err_path) {
  FILE* pipe = popen(command.c_str(), "r");
  Finished f;
  if (pipe == nullptr) return f;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr)
    f.out += buffer.data();
  const int status = pclose(pipe);
  if (WIFEXITED(status)) f.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) f.signal = WTERMSIG(status);
  f.err = read_file(err_path);
  return f;
}

// A loopback port free now (the kernel's pick for a socket bound to port 0), for a run and a
// device emulator started apart that must meet on it.
inline std::uint16_t free_loopback_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  ::inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
  ::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a);
  socklen_t length = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &length);
  ::close(fd);
  return ntohs(a.sin_port);
}

#ifdef IMASIM_EXE
// `imasim ARGS` (after `prefix`, an `env ...` say), its standard error kept in `err_path`.
inline Finished run_imasim(const std::string& args, const std::string& err_path,
                           const std::string& prefix = "") {
  return run_shell(prefix + " " + std::string(IMASIM_EXE) + " " + args + " 2>" + err_path,
                   err_path);
}
#endif

}  // namespace imasim::test
