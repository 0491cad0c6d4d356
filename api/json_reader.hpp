// Strict reading of JSON request documents, shared by every request type of api/.
//
// Every value is read through a Field (the value and its JSON path), so every error names
// the field it is about. Objects are read through Object, which rejects unknown keys up
// front. Each reader checks its range as it reads; errors are RequestError.
#pragma once

#include "api/request_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace api::reader {

inline constexpr float no_upper_limit = std::numeric_limits<float>::max();

// The shortest text that reads back as the same float ("0.1", "1e+12", "179.9").
std::string number_text(float x);
// A JSON string literal of (at most the start of) `s`, in ASCII, safe to embed in a message.
std::string quote(std::string_view s);
// What a value is, for the "got ..." part of a message; never dumps a container.
std::string describe(const nlohmann::json& v);
// "output" + "width" -> "output.width"; keys that are not identifiers are quoted.
std::string member_path(const std::string& parent, std::string_view key);
std::string element_path(const std::string& parent, std::size_t index);

// A value of the request with its path, so that every error can name it.
struct Field {
  const nlohmann::json* value;
  std::string path;

  [[noreturn]] void fail(const std::string& message) const { throw RequestError(path, message); }

  // "must be <expectation>, got <what it is>"
  [[noreturn]] void reject(const std::string& expectation) const {
    fail((path.empty() ? "the request must be " : "must be ") + expectation + ", got " + describe(*value));
  }

  Field element(std::size_t index) const { return {&(*value)[index], element_path(path, index)}; }

  // Members of an object, other members ignored: for documents this program wrote (results
  // files), which a later version may extend. Requests are read through Object instead.
  std::optional<Field> optional_member(std::string_view key) const {
    if (!value->is_object()) reject("an object");
    const auto it = value->find(std::string(key));
    if (it == value->end()) return std::nullopt;
    return Field{&*it, member_path(path, key)};
  }
  Field member(std::string_view key) const {
    if (auto field = optional_member(key)) return *field;
    throw RequestError(member_path(path, key), "required field missing");
  }
};

// A JSON object whose keys have all been checked against the allowed ones.
class Object {
 public:
  Object(Field field, std::span<const std::string_view> allowed) : field_(std::move(field)) {
    if (!field_.value->is_object()) field_.reject("an object");
    for (const auto& [key, value] : field_.value->items()) {
      if (std::ranges::find(allowed, key) == allowed.end()) {
        std::string names;
        for (const std::string_view name : allowed) names += (names.empty() ? "" : ", ") + std::string(name);
        throw RequestError(member_path(field_.path, key), "unknown field (allowed: " + names + ")");
      }
    }
  }

  const std::string& path() const { return field_.path; }
  std::string path_of(std::string_view key) const { return member_path(field_.path, key); }
  bool has(std::string_view key) const { return field_.value->contains(std::string(key)); }

  std::optional<Field> get(std::string_view key) const { return field_.optional_member(key); }

  // `what` says what the field should hold: "required field missing (<what>)".
  Field require(std::string_view key, const std::string& what) const {
    if (auto field = get(key)) return *field;
    throw RequestError(path_of(key), "required field missing (" + what + ")");
  }

 private:
  Field field_;
};


template <std::unsigned_integral T>
T as_uint(const Field& f, T lo, T hi) {
  const nlohmann::json& v = *f.value;
  std::optional<std::uint64_t> x;
  if (v.is_number_unsigned()) x = v.get<std::uint64_t>();
  // Only a json built in code holds a non-negative number_integer; parsed ones are unsigned.
  if (v.is_number_integer() && !v.is_number_unsigned() && v.get<std::int64_t>() >= 0)
    x = static_cast<std::uint64_t>(v.get<std::int64_t>());
  if (!x || *x < lo || *x > hi)
    f.reject("an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<T>(*x);
}

// "\"a\", \"b\", \"c\"": the JSON spellings of `values`.
template <class E, std::size_t N>
std::string enum_names(const std::array<E, N>& values) {
  std::string names;
  for (const E e : values) names += (names.empty() ? "\"" : ", \"") + to_string(e) + "\"";
  return names;
}

// An enum spelled as in to_string(); `values` lists every value of the enum.
template <class E, std::size_t N>
E as_enum(const Field& f, const std::array<E, N>& values) {
  if (f.value->is_string()) {
    const std::string& s = f.value->get_ref<const std::string&>();
    for (const E e : values)
      if (to_string(e) == s) return e;
  }
  f.reject("one of " + enum_names(values));
}

// Any JSON number, integer or not, that is finite and in [lo, hi] once stored as a float.
float as_float(const Field& f, float lo, float hi);
// Any finite JSON number in [lo, hi], kept as a double (measurements, not settings).
double as_double(const Field& f, double lo, double hi);
// A string of at most `max_bytes` bytes.
std::string as_string(const Field& f, std::size_t max_bytes);
// A name of 1 to `max_bytes` characters from [A-Za-z0-9._-], not starting with '.' (which
// would allow "." and ".."): scenes, suites; safe in paths and reports.
std::string as_name(const Field& f, std::size_t max_bytes);
bool as_bool(const Field& f);
// The elements of an array of at most `max_size` elements.
std::vector<Field> as_array(const Field& f, std::size_t max_size);

// nlohmann's parser, plus what it lets through: duplicate keys and unbounded nesting.
nlohmann::json parse_document(std::string_view text);

}  // namespace api::reader
