#include "text_table.hpp"

#include <algorithm>

namespace imasim::cli {

namespace {

// Characters, not bytes: a continuation byte of UTF-8 (10xxxxxx) starts none.
std::size_t display_width(const std::string& s) {
  return std::size_t(std::count_if(
      s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

}  // namespace

std::string format_table(const TextTable& table, const std::string& indent) {
  std::vector<std::size_t> width(table.header.size(), 0);
  const auto widen = [&width](const std::vector<std::string>& row) {
    if (row.size() > width.size()) width.resize(row.size(), 0);
    for (std::size_t c = 0; c < row.size(); ++c)
      width[c] = std::max(width[c], display_width(row[c]));
  };
  widen(table.header);
  for (const auto& row : table.rows)
    widen(row);
  std::string out;
  const auto add = [&](const std::vector<std::string>& row) {
    std::string line = indent;
    for (std::size_t c = 0; c < row.size(); ++c) {
      const std::string pad(width[c] - display_width(row[c]), ' ');
      const bool right = c < table.right_aligned.size() && table.right_aligned[c];
      line += right ? pad + row[c] : row[c] + (c + 1 < row.size() ? pad : "");
      if (c + 1 < row.size()) line += "  ";
    }
    out += line + '\n';
  };
  add(table.header);
  for (const auto& row : table.rows)
    add(row);
  return out;
}

}  // namespace imasim::cli
