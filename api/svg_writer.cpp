#include "api/svg_writer.hpp"

#include <cstdio>

namespace api {

std::string xml_escape(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&apos;"; break;
      default: escaped += c;
    }
  }
  return escaped;
}

std::string svg_number(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.2f", x);
  std::string text = buffer;
  // "12.50" -> "12.5", "3.00" -> "3"; a rounded "-0.00" becomes "0".
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text == "-0" ? "0" : text;
}

SvgWriter::SvgWriter(double width, double height, const Attributes& attributes) {
  Attributes root = {{"xmlns", "http://www.w3.org/2000/svg"},
                     {"width", svg_number(width)},
                     {"height", svg_number(height)},
                     {"viewBox", "0 0 " + svg_number(width) + " " + svg_number(height)}};
  root.insert(root.end(), attributes.begin(), attributes.end());
  open("svg", root);
}

void SvgWriter::open(std::string_view tag, const Attributes& attributes) {
  start_tag(tag, attributes);
  out_ += ">\n";
  open_.emplace_back(tag);
}

void SvgWriter::close() {
  if (open_.empty()) return;
  const std::string tag = std::move(open_.back());
  open_.pop_back();
  indent();
  out_ += "</" + tag + ">\n";
}

void SvgWriter::element(std::string_view tag, const Attributes& attributes, std::string_view text) {
  start_tag(tag, attributes);
  if (text.empty()) {
    out_ += "/>\n";
    return;
  }
  out_ += '>';
  out_ += xml_escape(text);
  out_ += "</";
  out_ += tag;
  out_ += ">\n";
}

std::string SvgWriter::finish() {
  while (!open_.empty()) close();
  return std::move(out_);
}

void SvgWriter::start_tag(std::string_view tag, const Attributes& attributes) {
  indent();
  out_ += '<';
  out_ += tag;
  for (const auto& [name, value] : attributes) out_ += ' ' + name + "=\"" + xml_escape(value) + '"';
}

void SvgWriter::indent() { out_.append(2 * open_.size(), ' '); }

}  // namespace api
