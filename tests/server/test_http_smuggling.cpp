// Request smuggling (issue 43, docs/server.md "Where a request ends"): no answer sent before
// a request's body was read leaves that body on the connection to run as the next request,
// and a head whose framing two readers could read apart is refused and its connection closed.
// Each case on a raw socket: one answer, the connection closed, the hidden request not run.
#include "http_checks.hpp"
#include "raw_connection.hpp"
#include "server_process.hpp"
#include "smuggling_cases.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <cstdio>
#include <unistd.h>

#include <string>
#include <thread>

namespace server_test {
namespace {

// A server's stored scene, the hidden requests' target.
std::string stored_scene(const ServerProcess& server) {
  const auto created = server.client()->Post("/v1/scenes", small_scene_glb(), "model/gltf-binary");
  if (!created || created->status != 201) throw std::runtime_error("the scene did not upload");
  return nlohmann::json::parse(created->body)["id"];
}

bool scene_exists(const ServerProcess& server, const std::string& id) {
  const auto r = server.client()->Get("/v1/scenes/" + id);
  return r && r->status == 200;
}

// Sends `bytes` on a new connection; what came back within `seconds`, and whether the server closed.
std::string exchange(int port, const std::string& bytes, bool& closed, double seconds = 5.0) {
  const int fd = connect_to(port);
  if (fd < 0 || !send_all(fd, bytes)) throw std::runtime_error("cannot send");
  std::string text = answer(fd, seconds, &closed);
  close(fd);
  return text;
}

// For a connection the server keeps: what came back until the first answer (at most 10 s,
// however slow a loaded machine is) and for a second after it.
std::string exchange_kept(int port, const std::string& bytes, bool& closed) {
  const int fd = connect_to(port);
  if (fd < 0 || !send_all(fd, bytes)) throw std::runtime_error("cannot send");
  std::string text = answers_until_quiet(fd, 10.0, 1.0, &closed);
  close(fd);
  return text;
}

TEST(Smuggling, NoRefusalLeavesItsBodyToRunAsTheNextRequest) {
  ServerProcess server;
  const std::string id = stored_scene(server);
  for (const SmugglingCase& c : smuggling_cases(id)) {
    SCOPED_TRACE(c.name);
    bool closed = false;
    // A connection kept alive is closed by the server when idle for 2 s: a second answer,
    // which would follow the first at once, has had a second to come.
    const std::string text =
        c.body_read ? exchange_kept(server.port(), c.bytes, closed) : exchange(server.port(), c.bytes, closed);
    EXPECT_EQ(answers_in(text), 1) << text.substr(0, 600);
    EXPECT_EQ(status_and_code(text).first, c.status) << text.substr(0, 600);
    if (!c.body_read) {
      EXPECT_NE(text.find("\r\nConnection: close\r\n"), std::string::npos) << text.substr(0, 600);
      // Within 5 s: at once, not at a deadline (the head's is 10 s, the body's 60 s).
      EXPECT_TRUE(closed) << "the server kept the connection";
    }
    ASSERT_TRUE(scene_exists(server, id)) << "the hidden DELETE ran";
  }
  EXPECT_EQ(server.log().find("\"method\":\"DELETE\""), std::string::npos) << "a DELETE reached the routes";
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

TEST(Smuggling, ATokenRefusalClosesToo) {
  ServerProcess server({"--token", "secret"});
  const auto created = server.client()->Post("/v1/scenes", {{"Authorization", "Bearer secret"}}, small_scene_glb(),
                                             "model/gltf-binary");
  ASSERT_TRUE(created && created->status == 201);
  const std::string id = nlohmann::json::parse(created->body)["id"];
  const std::string hidden = hidden_delete(id);
  bool closed = false;
  const std::string text = exchange(server.port(),
                                    "POST /v1/render HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                                    "Content-Length: " + std::to_string(hidden.size()) + "\r\n\r\n" + hidden,
                                    closed);
  EXPECT_EQ(answers_in(text), 1) << text;
  EXPECT_EQ(status_and_code(text).first, 401) << text;
  EXPECT_TRUE(closed);
  const auto still = server.client()->Get("/v1/scenes/" + id, {{"Authorization", "Bearer secret"}});
  EXPECT_TRUE(still && still->status == 200) << "the hidden DELETE ran";
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

TEST(Smuggling, ABodyThatMissesItsDeadlineIsAnswered408AndClosed) {
  ServerProcess server({"--transfer-timeout-ms", "500"});
  const std::string id = stored_scene(server);
  const std::string hidden = hidden_delete(id);
  const int fd = connect_to(server.port());
  ASSERT_GE(fd, 0);
  // Ten bytes declared, five sent; the rest and a pipelined DELETE after the 408.
  ASSERT_TRUE(send_all(fd, "POST /v1/render HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                           "Content-Length: 10\r\n\r\n{\"a\":"));
  bool closed = false;
  std::string text = answer(fd, 3.0, &closed);
  EXPECT_EQ(status_and_code(text).first, 408) << text;
  if (!closed) {
    send_all(fd, "1}   " + hidden);
    text += answer(fd, 3.0, &closed);
  }
  close(fd);
  EXPECT_EQ(answers_in(text), 1) << text;
  EXPECT_TRUE(closed);
  EXPECT_TRUE(scene_exists(server, id)) << "the DELETE after the 408 ran";
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

TEST(Smuggling, PipelinedRequestsReadToTheirEndAreEachAnsweredOnce) {
  ServerProcess server;
  const std::string render = R"({"output": {"width": 16, "height": 16}})";
  const std::string invalid = R"({"lpv": {"grid": 0}})";
  // Two GETs, a render, a render refused after its body was read (the connection stays), and
  // a last GET that asks to close: five answers in order.
  bool closed = false;
  const std::string text = exchange(
      server.port(),
      "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"
      "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"
      "POST /v1/render HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\nContent-Length: " +
          std::to_string(render.size()) + "\r\n\r\n" + render +
          "POST /v1/render HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\nContent-Length: " +
          std::to_string(invalid.size()) + "\r\n\r\n" + invalid +
          "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n",
      closed, 60.0);
  EXPECT_EQ(statuses_in(text), (std::vector<int>{200, 200, 200, 400, 200})) << text.substr(0, 300);
  EXPECT_TRUE(closed);

  // A chunked body read to its end by the route: answered, then closed (the front counts no
  // chunks, so it cannot vouch for where the next request starts), the GET after it unanswered.
  char size[16];
  std::snprintf(size, sizeof size, "%zx", render.size());  // a chunk's size is hexadecimal
  const std::string chunked = size + ("\r\n" + render) + "\r\n0\r\n\r\n";
  const std::string chunked_text = exchange(
      server.port(),
      "POST /v1/render HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n" +
          chunked + "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n",
      closed, 60.0);
  EXPECT_EQ(answers_in(chunked_text), 1) << chunked_text.substr(0, 300);
  EXPECT_EQ(status_and_code(chunked_text).first, 200);
  EXPECT_TRUE(closed);
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

}  // namespace
}  // namespace server_test
