#include "math/text_file.hpp"

#include <filesystem>
#include <fstream>

namespace imasim {

std::string size_text(std::uint64_t bytes) {
  constexpr std::uint64_t kKiB = 1024, kMiB = kKiB * 1024;
  if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  if (bytes >= kKiB && bytes % kKiB == 0) return std::to_string(bytes / kKiB) + " KiB";
  return std::to_string(bytes) + " bytes";
}

TextFile read_text_file(const std::string& path, std::uint64_t max_bytes, const std::string& what) {
  TextFile out;
  const std::string cannot_open = "cannot open the " + what + ": ";
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    out.error = cannot_open + "no such file";
    return out;
  }
  if (std::filesystem::is_directory(status)) {
    out.error = cannot_open + "is a directory, not a file";
    return out;
  }
  if (!std::filesystem::is_regular_file(status)) {
    out.error = cannot_open + "not a regular file (a device or a pipe is not read)";
    return out;
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) {
    out.error = cannot_open + ec.message();
    return out;
  }
  if (size > max_bytes) {
    out.error = "the " + what + " is " + std::to_string(size) + " bytes, above the limit of " +
                size_text(max_bytes);
    return out;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    out.error = cannot_open + "permission denied or unreadable";
    return out;
  }
  // Read at most one byte past the limit: a file that grew since the size check is refused.
  out.text.resize(static_cast<std::size_t>(size) + 1);
  in.read(out.text.data(), static_cast<std::streamsize>(out.text.size()));
  if (in.bad()) {
    out.text.clear();
    out.error = "cannot read the " + what;
    return out;
  }
  out.text.resize(static_cast<std::size_t>(in.gcount()));
  if (out.text.size() > max_bytes) {
    out.text.clear();
    out.error = "the " + what + " grew above the limit of " + size_text(max_bytes) + " while read";
  }
  return out;
}

}  // namespace imasim
