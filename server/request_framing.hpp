// Where a request ends (RFC 9112, section 6), decided once by the front from the request's
// head, before any handler runs: no body, a body of Content-Length bytes, or a chunked one.
// A head whose framing is ambiguous, and so could be read one way here and another way by a
// proxy in front (request smuggling), is refused instead: bare CR or LF line ends, obsolete
// line folding, whitespace before a field's colon, Transfer-Encoding with Content-Length or
// with a coding other than chunked, Content-Lengths that differ or do not parse. A refusal
// closes the connection, since nothing says where the next request would start.
#pragma once

#include "server/http_errors.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace server {

struct BodyFraming {
  enum class Kind { none, length, chunked };
  Kind kind = Kind::none;
  std::uint64_t length = 0;  // Kind::length: the body's bytes
};

struct FramedHead {
  BodyFraming body;
  // The names of the fields with an empty value, which httplib 0.11 drops as it parses the
  // head: the server puts them back, so that "X-Deadline-Ms:" is refused as "0" is, not
  // taken for an absent field.
  std::vector<std::string> empty_fields;
};

// `head`: the request line and the header fields up to and including the blank line's CRLF.
// `max_body_bytes`: the largest body any route takes; a longer Content-Length is 413.
std::variant<FramedHead, HttpError> frame_request(std::string_view head, std::uint64_t max_body_bytes);

// The refusal of a head with a bare CR or LF: frame_request's, and the front's for a head
// that has not ended yet (with bare LF line ends it never shows a CRLF CRLF).
HttpError bare_line_break_refusal();

// The position of a bare CR or LF (one not part of a CRLF) in `bytes[from, bytes.size())`, or
// npos. A CR at the very end is not bare yet: its LF may be the next byte to arrive.
std::size_t find_bare_line_break(std::string_view bytes, std::size_t from);

}  // namespace server
