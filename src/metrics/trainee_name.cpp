#include "trainee_name.hpp"

#include <cstdint>

namespace imasim::metrics {

namespace {

// The code point starting at `at` and its length in bytes; length 0 for invalid UTF-8
// (a stray continuation byte, a cut sequence, an overlong form, a surrogate, above U+10FFFF).
std::pair<std::uint32_t, std::size_t> decode(std::string_view s, std::size_t at) {
  const auto byte = [&s](std::size_t i) { return static_cast<std::uint8_t>(s[i]); };
  const std::uint8_t lead = byte(at);
  if (lead < 0x80) return {lead, 1};
  std::size_t n = 0;
  std::uint32_t cp = 0, min = 0;
  if ((lead & 0xE0) == 0xC0) {
    n = 2, cp = lead & 0x1Fu, min = 0x80;
  } else if ((lead & 0xF0) == 0xE0) {
    n = 3, cp = lead & 0x0Fu, min = 0x800;
  } else if ((lead & 0xF8) == 0xF0) {
    n = 4, cp = lead & 0x07u, min = 0x10000;
  } else {
    return {0, 0};
  }
  if (at + n > s.size()) return {0, 0};
  for (std::size_t i = 1; i < n; ++i) {
    if ((byte(at + i) & 0xC0) != 0x80) return {0, 0};
    cp = (cp << 6) | (byte(at + i) & 0x3Fu);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return {0, 0};
  return {cp, n};
}

bool is_control(std::uint32_t cp) {
  return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F);
}

}  // namespace

std::string trainee_name_problem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.front() == ' ' || name.back() == ' ') return "begins or ends with a space";
  std::size_t characters = 0;
  for (std::size_t at = 0; at < name.size(); ++characters) {
    const auto [cp, length] = decode(name, at);
    if (length == 0) return "is not valid UTF-8 (at byte " + std::to_string(at + 1) + ")";
    if (is_control(cp))
      return "has a control character at byte " + std::to_string(at + 1) +
             " (only printable "
             "text is kept)";
    at += length;
  }
  if (characters > kMaxTraineeNameCharacters)
    return "has " + std::to_string(characters) + " characters, above the limit of " +
           std::to_string(kMaxTraineeNameCharacters);
  return {};
}

}  // namespace imasim::metrics
