#include "server/request_framing.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <vector>

namespace server {
namespace {

HttpError bad_request(std::string message) { return {400, "bad_http_request", std::move(message), ""}; }

// RFC 9110, section 5.6.2: the characters of a field's name.
bool is_token_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
}

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// Field names and codings are case-insensitive; compared in place, since every header line
// of every request passes here.
bool iequals(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](unsigned char x, unsigned char y) {
    return std::tolower(x) == std::tolower(y);
  });
}

// A comma-separated list's elements, trimmed, the empty ones dropped (RFC 9110, section 5.6.1).
std::vector<std::string_view> list_elements(std::string_view value) {
  std::vector<std::string_view> elements;
  while (true) {
    const auto comma = value.find(',');
    if (const std::string_view element = trim(value.substr(0, comma)); !element.empty()) elements.push_back(element);
    if (comma == std::string_view::npos) return elements;
    value.remove_prefix(comma + 1);
  }
}

std::string joined(const std::vector<std::string_view>& elements) {
  std::string text;
  for (const std::string_view e : elements) text += (text.empty() ? "" : ", ") + std::string(e);
  return text;
}

// 1*DIGIT that fits 64 bits.
std::optional<std::uint64_t> parse_length(std::string_view text) {
  if (text.empty()) return std::nullopt;
  std::uint64_t value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    const std::uint64_t digit = std::uint64_t(c - '0');
    if (value > (UINT64_MAX - digit) / 10) return std::nullopt;
    value = value * 10 + digit;
  }
  return value;
}

}  // namespace

std::size_t find_bare_line_break(std::string_view bytes, std::size_t from) {
  for (std::size_t i = from; i < bytes.size(); ++i) {
    if (bytes[i] == '\n' && (i == 0 || bytes[i - 1] != '\r')) return i;
    if (bytes[i] == '\r' && i + 1 < bytes.size() && bytes[i + 1] != '\n') return i;
  }
  return std::string_view::npos;
}

HttpError bare_line_break_refusal() {
  return bad_request("a bare CR or LF in the request's head: its lines end with CRLF (RFC 9112, section 2.2)");
}

std::variant<FramedHead, HttpError> frame_request(std::string_view head, std::uint64_t max_body_bytes) {
  if (find_bare_line_break(head, 0) != std::string_view::npos) return bare_line_break_refusal();
  if (head.find('\0') != std::string_view::npos) return bad_request("a NUL byte in the request's head");

  const std::size_t request_line_end = head.find("\r\n");
  const std::string_view request_line = head.substr(0, request_line_end);
  const bool http_1_0 = request_line.ends_with(" HTTP/1.0");

  FramedHead framed;
  std::vector<std::string_view> codings;
  bool transfer_encoding = false;
  std::optional<std::uint64_t> content_length;
  for (std::size_t at = request_line_end + 2; at < head.size();) {
    const std::size_t end = head.find("\r\n", at);
    const std::string_view line = head.substr(at, end - at);
    at = end + 2;
    if (line.empty()) break;  // the blank line: the head's end
    if (line.front() == ' ' || line.front() == '\t')
      return bad_request("a header line starts with whitespace: obsolete line folding is refused (RFC 9112, section 5.2)");
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) return bad_request("a header line without a colon");
    const std::string_view name = line.substr(0, colon);
    if (name.empty() || !std::all_of(name.begin(), name.end(), is_token_char))
      return bad_request("the header name '" + std::string(name) +
                         "' is not a token (no whitespace may stand before the colon: RFC 9112, section 5.1)");
    const std::string_view value = trim(line.substr(colon + 1));
    if (value.empty()) framed.empty_fields.emplace_back(name);
    if (iequals(name, "Transfer-Encoding")) {
      transfer_encoding = true;
      for (const std::string_view coding : list_elements(value)) codings.push_back(coding);
    } else if (iequals(name, "Content-Length")) {
      for (const std::string_view element : list_elements(value.empty() ? std::string_view(" ") : value)) {
        const std::optional<std::uint64_t> length = parse_length(element);
        if (!length)
          return bad_request("Content-Length '" + std::string(value) + "' is not a number of bytes this server can read");
        if (content_length && *content_length != *length)
          return bad_request("Content-Length fields that differ (" + std::to_string(*content_length) + " and " +
                             std::to_string(*length) + ")");
        content_length = length;
      }
      if (!content_length) return bad_request("an empty Content-Length");
    }
  }

  if (transfer_encoding) {
    if (http_1_0) return bad_request("Transfer-Encoding in an HTTP/1.0 request (RFC 9112, section 6.1)");
    if (content_length) return bad_request("both Transfer-Encoding and Content-Length: the body's length is ambiguous");
    if (codings.empty() || !iequals(codings.back(), "chunked"))
      return bad_request("Transfer-Encoding whose last coding is not chunked: the body's length cannot be known");
    if (codings.size() > 1)
      return HttpError{501, "unsupported_transfer_encoding",
                       "only the chunked transfer coding is read here, alone; got '" + joined(codings) + "'", ""};
    framed.body = {BodyFraming::Kind::chunked, 0};
  } else if (content_length && *content_length > max_body_bytes) {
    return payload_too_large(std::size_t(max_body_bytes), "--max-body-bytes, --max-scene-bytes");
  } else if (content_length && *content_length > 0) {
    framed.body = {BodyFraming::Kind::length, *content_length};
  }
  return framed;
}

}  // namespace server
