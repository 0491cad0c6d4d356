// A minimal writer of SVG documents: every element it opens is closed, every text and
// attribute value is escaped, so whatever the caller passes the output stays well-formed.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace api {

// &, <, >, " and ' as entities: safe in text and in attribute values.
std::string xml_escape(std::string_view text);

// A coordinate or length: two decimals at most, no trailing zeros ("12.5", "3", "-0.25").
std::string svg_number(double x);

class SvgWriter {
 public:
  using Attributes = std::vector<std::pair<std::string, std::string>>;

  // Opens the <svg> root of that size in user units; `attributes` are added to it. No XML
  // declaration (UTF-8 needs none), so the document can be inlined in HTML as it is.
  SvgWriter(double width, double height, const Attributes& attributes = {});

  // An element with children to come; close() ends it.
  void open(std::string_view tag, const Attributes& attributes = {});
  // Ends the innermost open element.
  void close();
  // A whole element: empty (<tag .../>) when text is empty, else with the text inside.
  void element(std::string_view tag, const Attributes& attributes, std::string_view text = {});

  // Closes what is still open (the root included) and gives the document.
  std::string finish();

 private:
  void start_tag(std::string_view tag, const Attributes& attributes);
  void indent();

  std::string out_;
  std::vector<std::string> open_;  // the tags open, innermost last
};

}  // namespace api
