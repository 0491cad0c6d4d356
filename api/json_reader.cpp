#include "api/json_reader.hpp"

#include "api/counted.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

namespace api::reader {
namespace {

using nlohmann::json;

constexpr std::size_t max_json_depth = 16;  // the schemas need 5

bool is_plain_key(std::string_view key) {
  constexpr std::size_t max_plain = 64;
  return !key.empty() && key.size() <= max_plain && std::ranges::all_of(key, [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

}  // namespace

// The shortest text that reads back as the same float ("0.1", "1e+12", "179.9").
std::string number_text(float x) {
  std::array<char, 32> buf{};
  const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), x);
  return std::string(buf.data(), res.ptr);
}

// A JSON string literal of (at most the start of) `s`, in ASCII, safe to embed in a
// message: every message is ASCII, whatever bytes the client sent.
std::string quote(std::string_view s) {
  constexpr std::size_t max_length = 40;
  std::string q = json(std::string(s.substr(0, max_length))).dump(-1, ' ', true, json::error_handler_t::replace);
  if (s.size() > max_length) q.insert(q.size() - 1, "...");
  return q;
}

// What a value is, for the "got ..." part of a message. Never dumps a container,
// which could be large or deeply nested.
std::string describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::number_integer: return std::to_string(v.get<std::int64_t>());
    case json::value_t::number_unsigned: return std::to_string(v.get<std::uint64_t>());
    case json::value_t::number_float: {
      const double d = v.get<double>();
      if (std::isnan(d)) return "NaN";
      if (std::isinf(d)) return d > 0 ? "Infinity" : "-Infinity";
      return v.dump();
    }
    case json::value_t::string: return "string " + quote(v.get_ref<const std::string&>());
    case json::value_t::array: return "an array of " + counted(v.size(), "element");
    case json::value_t::object: return "an object";
    default: return "an unsupported value";
  }
}

// "output" + "width" -> "output.width". Keys that are not identifiers (they can only
// be unknown ones, straight from the client) are quoted: output["wi dth"].
std::string member_path(const std::string& parent, std::string_view key) {
  if (!is_plain_key(key)) return parent + "[" + quote(key) + "]";
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

std::string element_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

// Any JSON number, integer or not, that is finite and in [lo, hi] once stored as a float.
// The bounds are compared as floats, so a limit like 179.9 accepts the JSON text "179.9".
float as_float(const Field& f, float lo, float hi) {
  const std::string expectation = hi == no_upper_limit
                                      ? "a number >= " + number_text(lo)
                                      : "a number in [" + number_text(lo) + ", " + number_text(hi) + "]";
  if (!f.value->is_number()) f.reject(expectation);
  const double d = f.value->get<double>();
  if (!std::isfinite(d) || std::abs(d) > static_cast<double>(std::numeric_limits<float>::max()))
    f.reject(expectation + " that fits a 32-bit float");
  const float x = static_cast<float>(d);
  if (x < lo || x > hi) f.reject(expectation);
  return x;
}

double as_double(const Field& f, double lo, double hi) {
  const auto text = [](double x) { return json(x).dump(); };
  const std::string expectation = "a number in [" + text(lo) + ", " + text(hi) + "]";
  if (!f.value->is_number()) f.reject(expectation);
  const double d = f.value->get<double>();
  if (!std::isfinite(d) || d < lo || d > hi) f.reject(expectation);
  return d;
}

std::string as_string(const Field& f, std::size_t max_bytes) {
  if (!f.value->is_string() || f.value->get_ref<const std::string&>().size() > max_bytes)
    f.reject("a string of at most " + std::to_string(max_bytes) + " bytes");
  return f.value->get<std::string>();
}

std::string as_name(const Field& f, std::size_t max_bytes) {
  const std::string expectation =
      "a string of 1 to " + std::to_string(max_bytes) + " characters from [A-Za-z0-9._-], not starting with '.'";
  if (!f.value->is_string()) f.reject(expectation);
  const std::string& name = f.value->get_ref<const std::string&>();
  const bool valid_chars = std::ranges::all_of(name, [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
           c == '-';
  });
  if (name.empty() || name.size() > max_bytes || name.front() == '.' || !valid_chars)
    f.reject(expectation);
  return name;
}

bool as_bool(const Field& f) {
  if (!f.value->is_boolean()) f.reject("true or false");
  return f.value->get<bool>();
}

// The elements of an array of at most `max_size` elements.
std::vector<Field> as_array(const Field& f, std::size_t max_size) {
  if (!f.value->is_array() || f.value->size() > max_size)
    f.reject("an array of at most " + std::to_string(max_size) + " elements");
  std::vector<Field> elements;
  for (std::size_t i = 0; i < f.value->size(); ++i) elements.push_back(f.element(i));
  return elements;
}

// nlohmann's parser, plus what it lets through: duplicate keys (it keeps the last
// silently) and unbounded nesting.
json parse_document(std::string_view text) {
  std::vector<std::set<std::string>> open;  // per open object or array: the keys seen so far
  const json::parser_callback_t check = [&open](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (open.size() >= max_json_depth)
          throw RequestError("", "invalid JSON: nested deeper than " + std::to_string(max_json_depth) + " levels");
        open.emplace_back();
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end: open.pop_back(); break;
      case json::parse_event_t::key:
        if (!open.back().insert(parsed.get<std::string>()).second)
          throw RequestError("", "invalid JSON: duplicate key " + quote(parsed.get_ref<const std::string&>()));
        break;
      case json::parse_event_t::value: break;
    }
    return true;
  };
  try {
    return json::parse(text, check);
  } catch (const json::exception& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line 1, column 9: ...".
    std::string_view what = e.what();
    if (const auto end = what.find("] "); what.starts_with("[json.exception.") && end != std::string_view::npos)
      what.remove_prefix(end + 2);
    std::string message = "invalid JSON: " + std::string(what);
    // The parser quotes the bytes it last read, which may be anything.
    std::ranges::replace_if(message, [](char c) { return c < 0x20 || c > 0x7e; }, '?');
    throw RequestError("", message);
  }
}

}  // namespace api::reader
