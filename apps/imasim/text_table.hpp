#pragma once
// A table for the terminal: columns as wide as their widest cell, two spaces apart, numbers
// right-aligned so that their digits line up.
#include <string>
#include <vector>

namespace imasim::cli {

struct TextTable {
  std::vector<std::string> header;
  std::vector<bool> right_aligned;  // per column; missing: left
  std::vector<std::vector<std::string>> rows;
};

// Every line starts with `indent` and ends with '\n'. Widths count UTF-8 characters.
std::string format_table(const TextTable& table, const std::string& indent = "  ");

}  // namespace imasim::cli
