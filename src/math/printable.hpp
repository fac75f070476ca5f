#pragma once
// Text from a user's file shown in a message: control bytes as \xHH, so a message stays on one
// line and cannot drive a terminal (escape sequences in a key name), and cut short, so a
// megabyte-long key or token is not echoed in full.
#include <cstddef>
#include <string>
#include <string_view>

namespace imasim {

// Appends `s` with control bytes escaped; `token` also escapes bytes outside printable ASCII and
// the backslash itself, so what is shown reads back unambiguously.
void append_printable(std::string& out, std::string_view s, bool token);

// `s` escaped as a token and cut after `max_bytes` bytes of the input, with "..." when cut.
std::string printable(std::string_view s, std::size_t max_bytes);

}  // namespace imasim
