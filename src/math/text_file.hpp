#pragma once
// Reading a user's file whole, bounded: only a regular file (a directory reads as empty, and
// /dev/zero or a pipe never ends) of at most a stated size, checked before anything is read.
#include <cstdint>
#include <string>

namespace imasim {

struct TextFile {
  std::string text;
  // Empty when read; else why not, naming the file as `what`: "cannot open the scene file: is a
  // directory", "the input script is 9 bytes, above the limit of 8 bytes".
  std::string error;
};

// The file at `path`, or an error when it is missing, not a regular file, larger than
// `max_bytes` (said with the limit) or unreadable. `what` names the kind of file.
TextFile read_text_file(const std::string& path, std::uint64_t max_bytes, const std::string& what);

// "64 MiB", "512 KiB" or "300 bytes": a size limit as messages state it.
std::string size_text(std::uint64_t bytes);

}  // namespace imasim
