// What one client connection may spend before the server answers it (docs/server.md, "Slow
// clients"): how many connections there may be, how long a request's head and its body may
// take to arrive, and how large a head and a body may be. server/http_front enforces them.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>

namespace server {

struct ConnectionLimits {
  std::size_t max_connections = 512;            // open at once, all clients; more get 503
  std::size_t max_connections_per_client = 64;  // open at once from one address; more get 503
  // From a connection's accept, or a kept-alive request's first byte, to the end of its head:
  // past it, 408 (or a silent close when no byte came).
  std::chrono::milliseconds head_timeout{10000};
  // Reading a request's body, and writing its response, each at most this long: past it, 408
  // (a body) or a close (a response).
  std::chrono::milliseconds transfer_timeout{60000};
  std::chrono::milliseconds keep_alive_timeout{2000};  // idle between requests, then closed
  std::size_t max_header_lines = 100;                  // beside the request line; more get 431
  std::size_t max_head_bytes = 64 * 1024;              // request line and headers; more get 431
  // The largest body any route reads (largest_body_bytes: --max-body-bytes, --max-scene-bytes):
  // a longer Content-Length is answered 413 before the body is read, and the connection closed.
  std::uint64_t max_body_bytes = 64u << 20;
};

}  // namespace server
