// import_triangle_corners in a child process (mesh_import.hpp). The child writes one message on
// a pipe: a status byte (0: corners follow, 1: an error text follows), the payload's length as
// 8 bytes, then the payload; the parent reads it under a deadline, then reaps the child.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "scene/mesh_import.hpp"

namespace imasim::scene {

namespace {

// A file of a few megabytes imports in well under a second; the largest accepted (256 MiB)
// in about a minute.
double import_deadline_s(const std::string& path) {
  std::error_code ec;
  const double bytes = double(std::filesystem::file_size(path, ec));
  return 10.0 + (ec ? 0.0 : bytes / double(4 << 20));
}

bool write_all(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

[[noreturn]] void child_main(const std::string& path, int fd) {
  // A crash ends the child as a signal the parent reports, not in a handler inherited from the
  // parent (a sanitizer's or a fuzzer's, which would report it as the parent's own).
  for (const int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGTRAP})
    ::signal(sig, SIG_DFL);
  // Assimp's own complaints (its assertion handler prints before it aborts) are summed up by the
  // parent's message; the user's terminal gets that one line.
  if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, STDERR_FILENO);
  std::uint8_t status = 0;
  std::vector<float> corners;
  std::string error;
  try {
    corners = import_triangle_corners(path);
  } catch (const std::exception& e) {
    status = 1;
    error = e.what();
  }
  const void* payload = status == 0 ? static_cast<const void*>(corners.data()) : error.data();
  const std::uint64_t bytes = status == 0 ? corners.size() * sizeof(float) : error.size();
  const bool ok = write_all(fd, &status, 1) && write_all(fd, &bytes, sizeof bytes) &&
                  write_all(fd, payload, bytes);
  ::_exit(ok ? 0 : 1);  // no destructors or exit handlers of the parent's copy
}

// Everything the child writes until it closes the pipe, or false at the deadline.
bool read_until_closed(int fd, double deadline_s, std::string& out) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(deadline_s);
  char buffer[1 << 16];
  while (true) {
    const double left =
        std::chrono::duration<double>(end - std::chrono::steady_clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left * 1000) + 1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;  // the deadline is checked above
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    out.append(buffer, static_cast<std::size_t>(n));
  }
}

}  // namespace

std::vector<float> import_triangle_corners_isolated(const std::string& path) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw MeshImportError(std::string("cannot read the mesh: pipe: ") + std::strerror(errno));
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw MeshImportError(std::string("cannot read the mesh: fork: ") + std::strerror(errno));
  }
  if (child == 0) {
    ::close(fds[0]);
    child_main(path, fds[1]);
  }
  ::close(fds[1]);
  const double deadline_s = import_deadline_s(path);
  std::string message;
  const bool finished = read_until_closed(fds[0], deadline_s, message);
  ::close(fds[0]);
  if (!finished) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!finished) {
    throw MeshImportError("cannot read the mesh: the importer did not finish within " +
                          std::to_string(static_cast<int>(deadline_s)) +
                          " s (a malformed file; it was stopped)");
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    throw MeshImportError("cannot read the mesh: the importer failed on it (signal " +
                          std::to_string(sig) + ", " + ::strsignal(sig) + "): a malformed file");
  }
  constexpr std::size_t kHead = 1 + sizeof(std::uint64_t);
  std::uint64_t bytes = 0;
  if (message.size() >= kHead) std::memcpy(&bytes, message.data() + 1, sizeof bytes);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || message.size() < kHead ||
      message.size() - kHead != bytes) {
    throw MeshImportError("cannot read the mesh: the importer ended without a result");
  }
  if (message[0] != 0) throw MeshImportError(message.substr(kHead));
  if (bytes % (9 * sizeof(float)) != 0)
    throw MeshImportError("cannot read the mesh: the importer's result is cut short");
  std::vector<float> corners(bytes / sizeof(float));
  if (bytes > 0) std::memcpy(corners.data(), message.data() + kHead, bytes);
  return corners;
}

}  // namespace imasim::scene
