#include "smuggling_cases.hpp"

#include "gltf_builder.hpp"

namespace server_test {
namespace {

constexpr const char* kHost = "Host: 127.0.0.1\r\n";

std::string length(const std::string& body) { return "Content-Length: " + std::to_string(body.size()) + "\r\n"; }

// `head` (request line and fields, each ending CRLF) with `body` after the blank line.
std::string request(const std::string& head, const std::string& body) { return head + "\r\n" + body; }

std::string with_bare_line_feeds(std::string text) {
  for (std::size_t at = 0; (at = text.find("\r\n", at)) != std::string::npos;) text.erase(at, 1);
  return text;
}

}  // namespace

std::string hidden_delete(const std::string& scene_id) {
  return "DELETE /v1/scenes/" + scene_id + " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\n\r\n";
}

std::vector<SmugglingCase> smuggling_cases(const std::string& scene_id) {
  const std::string hidden = hidden_delete(scene_id);
  const std::string json = "Content-Type: application/json\r\n";
  const std::string render = "POST /v1/render HTTP/1.1\r\n";
  std::string many_fields;
  for (int i = 0; i < 120; ++i) many_fields += "X-Field-" + std::to_string(i) + ": 1\r\n";
  const std::string chunked_hidden = "0\r\n\r\n" + hidden;
  return {
      // Refused before the body is read: each must close, or read the body to its end.
      {"403 foreign Origin", request(render + kHost + "Origin: http://evil.example\r\n" + json + length(hidden), hidden), 403},
      {"421 foreign Host", request(render + "Host: evil.example:8080\r\n" + json + length(hidden), hidden), 421},
      {"415 text/plain", request(render + kHost + "Content-Type: text/plain\r\n" + length(hidden), hidden), 415},
      {"400 over-long upload name",
       request("POST /v1/scenes?name=" + std::string(400, 'n') + " HTTP/1.1\r\n" + kHost +
                   "Content-Type: model/gltf-binary\r\n" + length(hidden),
               hidden),
       400},
      // httplib reads these bodies before it finds no route or no method: kept alive, the
      // hidden request read as the body it is.
      {"404 unknown route", request(std::string("POST /v1/nowhere HTTP/1.1\r\n") + kHost + json + length(hidden), hidden), 404, true},
      {"405 wrong method", request(std::string("PUT /v1/render HTTP/1.1\r\n") + kHost + json + length(hidden), hidden), 405, true},
      {"404 body on a GET", request(std::string("GET /v1/nowhere HTTP/1.1\r\n") + kHost + length(hidden), hidden), 404},
      {"413 Content-Length over the cap", request(render + kHost + json + "Content-Length: 99999999999\r\n", hidden), 413},
      {"431 too many header lines", request(render + kHost + json + many_fields + length(hidden), hidden), 431},
      // Framing two readers could read apart: refused, and closed.
      {"400 Content-Length with Transfer-Encoding",
       request(render + kHost + json + length(chunked_hidden) + "Transfer-Encoding: chunked\r\n", chunked_hidden), 400},
      {"400 two Content-Lengths that differ",
       request(render + kHost + json + "Content-Length: 5\r\n" + length(hidden), hidden), 400},
      {"400 chunked then identity",
       request(render + kHost + json + "Transfer-Encoding: chunked, identity\r\n", chunked_hidden), 400},
      {"501 a coding before chunked", request(render + kHost + json + "Transfer-Encoding: gzip, chunked\r\n", chunked_hidden), 501},
      {"400 obs-fold", request(render + kHost + json + "Transfer-Encoding:\r\n chunked\r\n" + length(hidden), hidden), 400},
      {"400 space before the colon",
       request(render + kHost + json + "Transfer-Encoding : chunked\r\n" + length(hidden), hidden), 400},
      {"400 bare LF line ends",
       with_bare_line_feeds(render + kHost + "Origin: http://evil.example\r\n" + json + length(hidden) + "\r\n") + hidden,
       400},
      {"400 Content-Length too large to parse",
       request(render + kHost + json + "Content-Length: 99999999999999999999999\r\n", hidden), 400},
      {"400 Content-Length with a sign", request(render + kHost + json + "Content-Length: +70\r\n", hidden), 400},
  };
}

std::string small_scene_glb() {
  test_gltf::GltfBuilder b;
  b.add_node({{"mesh", b.add_quad({0, 0, 0}, {0, 1, 0}, 2)}});
  const std::vector<std::uint8_t> glb = b.glb();
  return std::string(glb.begin(), glb.end());
}

}  // namespace server_test
