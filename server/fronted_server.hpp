// httplib's request handling behind server/http_front: the routes, body reading and responses
// stay httplib's; accept and the request head are the front's. A request is served from the
// socket the front hands over, with the head the front read first, through a stream that
// bounds the body's arrival and the response's departure as wholes (--transfer-timeout-ms),
// where httplib bounds each read and write alone.
#pragma once

#include "server/connection_limits.hpp"
#include "server/http_front.hpp"

#include <httplib.h>

#include <optional>
#include <string>

namespace server {

// httplib 0.11 compresses an answer whose Content-Type is exactly "application/json" for a
// client that accepts brotli or gzip; an answer set to this type is left uncompressed (base64
// images: brotli costs 40 to 140 ms for a third of their bytes). It goes out as
// "application/json" all the same, as every JSON answer does (RFC 8259 defines no charset for
// it; issue 43: the contract saw both): the post-routing handler, which runs after httplib
// chose the encoding, writes the plain type.
inline constexpr const char* kUncompressedJson = "application/json; charset=utf-8";

class FrontedServer : public httplib::Server {
 public:
  explicit FrontedServer(const ConnectionLimits& limits);

  // Serves the one request whose head `connection` holds (HttpFront::Serve): the bytes after
  // the request when it was read to its end and the connection stays open, else nothing.
  // Owns httplib's post-routing handler (it marks the answers that close): set no other.
  std::optional<std::string> serve(const HeadReady& connection, bool closing);

 private:
  ConnectionLimits limits_;
};

}  // namespace server
