#include "scene/toml_nesting.hpp"

namespace imasim::scene {

namespace {

enum class Mode : std::uint8_t { code, comment, basic, literal, multi_basic, multi_literal };

bool starts(std::string_view text, std::size_t i, std::string_view with) {
  return text.substr(i, with.size()) == with;
}

}  // namespace

TomlNestingProblem find_deep_toml_nesting(std::string_view text) {
  std::uint32_t line = 1;
  std::uint32_t dots = 0;   // dots of the key being read (a float has one, then a separator)
  std::uint32_t depth = 0;  // open [ and { (table headers count too and close on their line)
  Mode mode = Mode::code;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    switch (mode) {
      case Mode::comment:
        if (c == '\n') mode = Mode::code;
        continue;
      case Mode::basic:
        if (c == '\\') {
          ++i;  // an escaped quote does not end the string (an escaped newline is invalid)
          if (i < text.size() && text[i] == '\n') ++line;
        } else if (c == '"' || c == '\n') {
          mode = Mode::code;
        }
        continue;
      case Mode::literal:
        if (c == '\'' || c == '\n') mode = Mode::code;
        continue;
      case Mode::multi_basic:
        if (c == '\\') {
          ++i;
          if (i < text.size() && text[i] == '\n') ++line;
        } else if (starts(text, i, "\"\"\"")) {
          mode = Mode::code;
          i += 2;
        }
        continue;
      case Mode::multi_literal:
        if (starts(text, i, "'''")) {
          mode = Mode::code;
          i += 2;
        }
        continue;
      case Mode::code:
        break;
    }
    switch (c) {
      case '#':
        mode = Mode::comment;
        break;
      case '"':
        mode = starts(text, i, "\"\"\"") ? Mode::multi_basic : Mode::basic;
        if (mode == Mode::multi_basic) i += 2;
        break;
      case '\'':
        mode = starts(text, i, "'''") ? Mode::multi_literal : Mode::literal;
        if (mode == Mode::multi_literal) i += 2;
        break;
      case '.':
        if (++dots > kMaxTomlNesting)
          return {line, "a dotted key deeper than " + std::to_string(kMaxTomlNesting) +
                            " levels (a scene key has 2: table.key)"};
        break;
      case '[':
      case '{':
        dots = 0;
        if (++depth > kMaxTomlNesting)
          return {line, "tables or arrays nested deeper than " + std::to_string(kMaxTomlNesting) +
                            " levels (a scene file needs 2)"};
        break;
      case ']':
      case '}':
        dots = 0;
        if (depth > 0) --depth;
        break;
      case '=':
      case ',':
      case '\n':
        dots = 0;
        break;
      default:
        break;
    }
  }
  return {};
}

}  // namespace imasim::scene
