#include "metrics/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace imasim::metrics {
namespace {

bool same_file(const struct stat& a, const std::string& other) {
  struct stat b {};
  return ::stat(other.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

}  // namespace

OutputFile::OutputFile(std::string path, std::string what, std::span<const std::string> inputs)
    : path_(std::move(path)), what_(std::move(what)) {
  if (path_.empty()) throw OutputError("the path of " + what_ + " is empty");
  struct stat existing {};
  if (::stat(path_.c_str(), &existing) == 0) {
    if (S_ISDIR(existing.st_mode)) {
      throw OutputError(what_ + " " + path_ + " is a directory; give a file name");
    }
    for (const std::string& input : inputs) {
      if (!input.empty() && same_file(existing, input)) {
        throw OutputError(what_ + " " + path_ + " is the input file " + input +
                          "; refusing to overwrite it");
      }
    }
  }
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail("create", errno);
  last_flush_ = std::chrono::steady_clock::now();
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : path_(std::move(other.path_)),
      what_(std::move(other.what_)),
      fd_(std::exchange(other.fd_, -1)),
      pending_(std::move(other.pending_)),
      last_flush_(other.last_flush_) {}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    path_ = std::move(other.path_);
    what_ = std::move(other.what_);
    fd_ = std::exchange(other.fd_, -1);
    pending_ = std::move(other.pending_);
    last_flush_ = other.last_flush_;
  }
  return *this;
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
}

void OutputFile::fail(const char* action, int error) {
  throw OutputError(std::string("cannot ") + action + " " + what_ + " " + path_ + ": " +
                    std::strerror(error));
}

void OutputFile::write(std::string_view text) {
  if (fd_ < 0) throw OutputError(what_ + " " + path_ + " is closed");
  pending_.append(text);
}

void OutputFile::flush() {
  if (fd_ < 0) return;
  std::size_t done = 0;
  while (done < pending_.size()) {
    const ssize_t n = ::write(fd_, pending_.data() + done, pending_.size() - done);
    if (n < 0 && errno == EINTR) continue;  // a signal (Ctrl-C) arrived: the run ends cleanly
    if (n <= 0) {
      pending_.erase(0, done);
      fail("write", n < 0 ? errno : ENOSPC);
    }
    done += std::size_t(n);
  }
  pending_.clear();
  last_flush_ = std::chrono::steady_clock::now();
}

void OutputFile::flush_if_due(std::chrono::steady_clock::time_point now) {
  if (fd_ >= 0 && now - last_flush_ >= kFlushInterval) flush();
}

void OutputFile::close() {
  if (fd_ < 0) return;
  try {
    flush();
  } catch (const OutputError&) {
    ::close(std::exchange(fd_, -1));
    throw;
  }
  if (::close(std::exchange(fd_, -1)) != 0) fail("close", errno);
}

}  // namespace imasim::metrics
