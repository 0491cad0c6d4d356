#include "text_table.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace bench {
namespace {

// Characters, not bytes: cells may hold UTF-8 ("±", "³").
std::size_t display_width(const std::string& s) {
  return std::ranges::count_if(s, [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
}

std::string padded(const std::string& cell, std::size_t width, bool right) {
  const std::string fill(width - std::min(width, display_width(cell)), ' ');
  return right ? fill + cell : cell + fill;
}

// A '|' would end the Markdown cell.
std::string markdown_cell(const std::string& cell) {
  std::string out;
  for (const char c : cell) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::string TextTable::text() const {
  std::vector<std::size_t> widths(header.size(), 0);
  for (std::size_t c = 0; c < header.size(); ++c) widths[c] = display_width(header[c]);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c) widths[c] = std::max(widths[c], display_width(row[c]));
  const auto line = [&](const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t c = 0; c < widths.size(); ++c) {
      const std::string cell = c < cells.size() ? cells[c] : "";
      out += (c ? "  " : "") + padded(cell, widths[c], c < numeric.size() && numeric[c]);
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "\n";
  };
  std::string out = line(header);
  for (const auto& row : rows) out += line(row);
  return out;
}

std::string TextTable::markdown() const {
  std::string out = "|";
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on " " + string.
  const auto cell = [&out](const std::string& text) {
    out += ' ';
    out += markdown_cell(text);
    out += " |";
  };
  for (const auto& h : header) cell(h);
  out += "\n|";
  for (std::size_t c = 0; c < header.size(); ++c) out += c < numeric.size() && numeric[c] ? "---:|" : "---|";
  out += "\n";
  for (const auto& row : rows) {
    out += "|";
    for (std::size_t c = 0; c < header.size(); ++c) cell(c < row.size() ? row[c] : "");
    out += "\n";
  }
  return out;
}

std::string markdown_lines(const std::string& text) {
  std::string md;
  for (const char c : text) md += c == '\n' ? std::string("  \n") : std::string(1, c);
  return md;
}

std::string format(const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  const int length = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string text(length > 0 ? std::size_t(length) : 0, '\0');
  std::vsnprintf(text.data(), text.size() + 1, format, again);  // writes the '\0' into the string's own terminator
  va_end(again);
  return text;
}

}  // namespace bench
