#pragma once
// A file the program writes as it runs (events, later the recorder's trajectories): every write,
// flush and the close are checked, so a full disk or a vanished directory ends the run with an
// error instead of an exit status of 0 and an empty file; it is flushed at least once a second of
// wall-clock time, so a run killed with SIGKILL leaves everything up to its last flush; and it
// refuses to open over a file the run reads (the scene, the input script). POSIX I/O under our
// own buffer: the data reaches the file only at a flush, in the order written.
#include <chrono>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace imasim::metrics {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How long written data may stay in the process's buffer (unit: s of wall-clock time).
inline constexpr std::chrono::milliseconds kFlushInterval{1000};

class OutputFile {
 public:
  // Creates (or truncates) `path`; `what` names the file in messages ("the events file").
  // Throws OutputError when it cannot be created or when it is one of `inputs` (the same file
  // by device and inode, whatever the spelling of the path).
  OutputFile(std::string path, std::string what, std::span<const std::string> inputs = {});
  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  // Closes without reporting: call close() to learn whether the data reached the file.
  ~OutputFile();

  // Each throws OutputError naming the file and the system's reason.
  void write(std::string_view text);
  void flush();
  // Flushes when kFlushInterval has passed since the last flush.
  void flush_if_due(std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());
  void close();

  bool is_open() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }

 private:
  [[noreturn]] void fail(const char* action, int error);

  std::string path_, what_;
  int fd_ = -1;
  // Written text waiting for the next flush; flushes write whole lines when callers write
  // whole lines, so a killed run never leaves half a line.
  std::string pending_;
  std::chrono::steady_clock::time_point last_flush_{};
};

}  // namespace imasim::metrics
