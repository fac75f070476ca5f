#include "math/printable.hpp"

namespace imasim {

void append_printable(std::string& out, std::string_view s, bool token) {
  static constexpr char kHex[] = "0123456789abcdef";
  for (const char c : s) {
    const auto b = static_cast<unsigned char>(c);
    const bool control = b < 0x20 || b == 0x7f;
    if (control || (token && b > 0x7f)) {
      out += "\\x";
      out += kHex[b >> 4];
      out += kHex[b & 0xf];
    } else if (token && c == '\\') {
      out += "\\\\";
    } else {
      out += c;
    }
  }
}

std::string printable(std::string_view s, std::size_t max_bytes) {
  std::string out;
  append_printable(out, s.substr(0, max_bytes), true);
  if (s.size() > max_bytes) out += "...";
  return out;
}

}  // namespace imasim
