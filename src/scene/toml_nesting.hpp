#pragma once
// A pre-scan of scene-file text before toml++ sees it: toml++ parses dotted keys, table headers,
// arrays and inline tables recursively, and thousands of levels (`a.a.a...`, `[a.a.a...]`,
// `x = [[[...`) overflow the stack (SIGSEGV). A scene key has two levels (table.key), so the
// scan refuses far deeper nesting with a message instead.
#include <cstdint>
#include <string>
#include <string_view>

namespace imasim::scene {

// Deepest nesting accepted, for dotted key parts and for open brackets and braces each: 16 times
// what a scene needs, so a wrong file still gets toml++'s and the keys' messages, and thousands
// of times below what overflows the stack.
constexpr std::uint32_t kMaxTomlNesting = 32;

struct TomlNestingProblem {
  std::uint32_t line = 0;  // 1-based; 0: no problem
  std::string what;
};

// The first place the text nests deeper than kMaxTomlNesting, skipping strings and comments.
TomlNestingProblem find_deep_toml_nesting(std::string_view text);

}  // namespace imasim::scene
