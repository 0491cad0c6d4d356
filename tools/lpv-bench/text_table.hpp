// A table for people: aligned plain text for the terminal, or Markdown for job summaries.
#pragma once

#include <string>
#include <vector>

namespace bench {

struct TextTable {
  std::vector<std::string> header;
  std::vector<bool> numeric;  // per column: right-aligned
  std::vector<std::vector<std::string>> rows;

  std::string text() const;      // columns padded to their widest cell, two spaces apart
  std::string markdown() const;  // a GitHub-flavoured Markdown table
};

// Lines of plain text as Markdown lines: each ends in a line break (two spaces), not a space.
std::string markdown_lines(const std::string& text);

// printf-style formatting into a std::string, for table cells.
std::string format(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace bench
