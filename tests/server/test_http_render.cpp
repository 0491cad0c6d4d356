// Renders and reports over real HTTP: PNG, stats headers, JSON, EXR, scenes, device,
// metrics, the request log and bearer tokens.
#include "http_checks.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <sstream>
#include <thread>

namespace server_test {
namespace {

httplib::Result post_render(httplib::Client& http, const nlohmann::json& request, httplib::Headers headers = {}) {
  return http.Post("/v1/render", headers, request.dump(), "application/json");
}

TEST(HttpRender, ReturnsPngOfTheRequestedSize) {
  auto http = shared_server().client();
  const auto r = post_render(*http, {{"output", {{"width", 160}, {"height", 96}}}});
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
  const auto size = png_size(r->body);
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 160);
  EXPECT_EQ(size->height, 96);
}

TEST(HttpRender, APostWithNoBodyAtAllIsTheEmptyRequest) {
  // What `curl -X POST URL` sends: no Content-Length, no Transfer-Encoding, so no body
  // (RFC 9112 6.3); answered at once, not after the read timeout.
  EXPECT_EQ(send_raw(shared_server().port(), "POST /v1/render HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", 3),
            "HTTP/1.1 200 OK");
}

TEST(HttpRender, AnEmptyBodyIsTheEmptyRequest) {
  auto http = shared_server().client();
  const auto r = http->Post("/v1/render", httplib::Headers{}, "", "");  // Content-Length 0, no media type
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(nlohmann::json::parse(r->get_header_value("X-Render-Stats"))["scene"], "cornell-box");
  const auto size = png_size(r->body);
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 512);  // the defaults
  EXPECT_EQ(size->height, 512);
}

TEST(HttpRender, StatsHeadersParseAndPassTimesAddUpToNoMoreThanTheTotal) {
  auto http = shared_server().client();
  const auto r = post_render(*http, {{"output", {{"width", 128}, {"height", 128}}}, {"repeat", 2}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;

  const auto stats = nlohmann::json::parse(r->get_header_value("X-Render-Stats"));
  EXPECT_EQ(stats["scene"], "cornell-box");
  EXPECT_EQ(stats["width"], 128);
  EXPECT_EQ(stats["frames"], 2);
  double pass_sum = 0.0;
  int passes_ran = 0;
  for (const auto& pass : stats["passes"]) {
    if (!pass["ran"].get<bool>()) continue;
    ++passes_ran;
    EXPECT_GE(pass["gpu_ms"]["median"].get<double>(), 0.0) << pass.dump();
    pass_sum += pass["gpu_ms"]["median"].get<double>();
  }
  EXPECT_GE(passes_ran, 2);
  const double eps = 1e-3;
  EXPECT_LE(pass_sum, stats["wall_ms"]["median"].get<double>() * 1.05 + eps) << stats.dump();
  EXPECT_GT(stats["cpu_ms"]["encode"]["median"].get<double>(), 0.0);

  const auto timing = parse_server_timing(r->get_header_value("Server-Timing"));
  double timing_pass_sum = 0.0;
  for (const auto& pass : stats["passes"]) {
    if (!pass["ran"].get<bool>()) continue;
    const std::string name = pass["name"];
    ASSERT_TRUE(timing.count(name)) << "Server-Timing lacks " << name << ": " << r->get_header_value("Server-Timing");
    timing_pass_sum += timing.at(name);
  }
  for (const char* entry : {"gpu", "wall", "queue", "encode", "total"}) ASSERT_TRUE(timing.count(entry)) << entry;
  // Two frames plus encoding happened inside the total; the passes of one frame cannot exceed it.
  EXPECT_LE(timing_pass_sum, timing.at("total") + eps);
  EXPECT_LE(timing.at("wall") + timing.at("encode") + timing.at("queue"), timing.at("total") + eps);
}

TEST(HttpRender, AcceptJsonReturnsStatsAndTheImageAsBase64) {
  auto http = shared_server().client();
  const auto r = post_render(*http, {{"output", {{"width", 64}, {"height", 48}}}},
                             {{"Accept", "application/json"}, {"Accept-Encoding", "br, gzip"}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  // Uncompressed even for a client that accepts brotli: base64 images cost more time to
  // compress than the bytes they would save.
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json") << "one media type for every JSON answer";
  EXPECT_EQ(r->get_header_value("Content-Encoding"), "");
  // The control: the same client sees the encoding of a JSON answer without images.
  const auto scenes = http->Get("/v1/scenes", {{"Accept-Encoding", "br, gzip"}});
  ASSERT_TRUE(scenes);
  EXPECT_NE(scenes->get_header_value("Content-Encoding"), "");
  const auto body = nlohmann::json::parse(r->body);
  EXPECT_EQ(body["stats"]["width"], 64);
  EXPECT_EQ(body["image"]["media_type"], "image/png");
  const auto size = png_size(base64_decode(body["image"]["base64"]));
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 64);
  EXPECT_EQ(size->height, 48);
}

TEST(HttpRender, DryRunReturnsThePlanWithoutAnImage) {
  auto http = shared_server().client();
  const nlohmann::json away = {{"type", "spot"}, {"position", {0, 6, 0}}, {"direction", {0, 1, 0}}, {"intensity", 5}};
  const auto r = post_render(*http, {{"dry_run", true}, {"lights", {away}}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
  const auto body = nlohmann::json::parse(r->body);
  EXPECT_FALSE(body.contains("image"));
  EXPECT_EQ(body["stats"]["plan"]["mode"], "auto");
  ASSERT_EQ(body["stats"]["plan"]["decisions"].size(), 1u);
  for (const auto& pass : body["stats"]["passes"]) {
    EXPECT_FALSE(pass["ran"]) << "nothing runs in a dry run: " << pass.dump();
    if (pass["name"] == "shadow") {
      EXPECT_FALSE(pass["planned"]);
      EXPECT_EQ(pass["reason"], "no light reaches the scene");
    }
    if (pass["name"] == "forward") {
      EXPECT_TRUE(pass["planned"]) << "what would run is planned: " << pass.dump();
    }
  }
}

TEST(HttpRender, LinearFormatsComeBackAsExrAndPfm) {
  auto http = shared_server().client();
  const auto exr = post_render(*http, {{"output", {{"width", 32}, {"height", 32}, {"format", "exr"}}}});
  ASSERT_TRUE(exr);
  ASSERT_EQ(exr->status, 200) << exr->body;
  EXPECT_EQ(exr->get_header_value("Content-Type"), "image/x-exr");
  EXPECT_EQ(exr->body.substr(0, 4), std::string("\x76\x2f\x31\x01", 4));
  const auto pfm = post_render(*http, {{"output", {{"width", 32}, {"height", 16}, {"format", "pfm"}}}});
  ASSERT_TRUE(pfm);
  ASSERT_EQ(pfm->status, 200);
  EXPECT_EQ(pfm->body.substr(0, 3), "PF\n");
  EXPECT_EQ(pfm->body.size() > 32u * 16u * 3u * 4u, true);
}

TEST(HttpRender, ChangingTheLightChangesTheImage) {
  auto http = shared_server().client();
  const nlohmann::json base = {{"output", {{"width", 64}, {"height", 64}}}};
  nlohmann::json brighter = base;
  brighter["light_edits"] = {{{"index", 0}, {"intensity", 40}}};
  const auto a = post_render(*http, base);
  const auto b = post_render(*http, brighter);
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->status, 200);
  ASSERT_EQ(b->status, 200) << b->body;
  EXPECT_NE(a->body, b->body);
}

TEST(HttpScenes, ListAndOneSceneCarryBoundsLightsAndCamera) {
  auto http = shared_server().client();
  const auto list = http->Get("/v1/scenes");
  ASSERT_TRUE(list);
  ASSERT_EQ(list->status, 200);
  const auto scenes = nlohmann::json::parse(list->body)["scenes"];
  ASSERT_GE(scenes.size(), 3u);
  bool found = false;
  for (const auto& s : scenes) found = found || s["name"] == "cornell-box";
  EXPECT_TRUE(found);

  const auto one = http->Get("/v1/scenes/cornell-box");
  ASSERT_TRUE(one);
  ASSERT_EQ(one->status, 200);
  const auto scene = nlohmann::json::parse(one->body);
  EXPECT_EQ(scene["bounds"]["min"], nlohmann::json({-1.0, 0.0, -1.0}));
  EXPECT_EQ(scene["bounds"]["max"], nlohmann::json({1.0, 2.0, 1.0}));
  ASSERT_EQ(scene["lights"].size(), 1u);
  EXPECT_EQ(scene["lights"][0]["type"], "spot");
  EXPECT_EQ(scene["camera"]["position"], nlohmann::json({0.0, 1.0, 3.4}));

  // The lights as reported are a valid request: sending them back renders.
  const auto r = http->Post("/v1/render",
                            nlohmann::json({{"lights", scene["lights"]}, {"camera", scene["camera"]},
                                            {"output", {{"width", 32}, {"height", 32}}}})
                                .dump(),
                            "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
}

TEST(HttpDevice, ReportsTheDeviceDriverAndLimits) {
  auto http = shared_server().client();
  const auto r = http->Get("/v1/device");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  const auto device = nlohmann::json::parse(r->body);
  EXPECT_FALSE(device["name"].get<std::string>().empty());
  EXPECT_FALSE(device["driver"].get<std::string>().empty());
  EXPECT_GE(device["limits"]["max_image_dimension_2d"].get<int>(), 4096);
}

TEST(HttpMetrics, CountRequestsAndRecordPassTimesAndQueueGauges) {
  auto http = shared_server().client();
  ASSERT_EQ(http->Post("/v1/render", R"({"output": {"width": 32, "height": 32}})", "application/json")->status, 200);
  ASSERT_EQ(http->Get("/v2/nothing")->status, 404);
  // A request is counted after its answer is sent, and the next request may come on another
  // connection, served by another thread: wait until both are counted.
  const std::vector<std::string> counted = {
      "lpv_http_requests_total{route=\"/v1/render\",method=\"POST\",status=\"200\"}",
      "lpv_http_requests_total{route=\"unmatched\",method=\"GET\",status=\"404\"}"};
  const auto all_counted = [&](const httplib::Result& r) {
    return std::all_of(counted.begin(), counted.end(),
                       [&](const std::string& series) { return r->body.find(series) != std::string::npos; });
  };
  httplib::Result r = http->Get("/metrics");
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (r && !all_counted(r) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    r = http->Get("/metrics");
  }
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type").rfind("text/plain", 0), 0u);
  EXPECT_TRUE(all_counted(r)) << r->body;
  const std::string& text = r->body;
  EXPECT_NE(text.find("lpv_http_request_duration_seconds_bucket{route=\"/v1/render\",le=\"+Inf\"}"), std::string::npos);
  EXPECT_NE(text.find("lpv_render_pass_gpu_seconds_bucket{pass=\"shade\""), std::string::npos);
  EXPECT_NE(text.find("lpv_render_queue_depth 0"), std::string::npos);
  EXPECT_NE(text.find("lpv_renders_in_flight 0"), std::string::npos);
  EXPECT_NE(text.find("lpv_ready 1"), std::string::npos);
}

TEST(HttpLog, OneJsonLinePerRequestWithStatusTimeAndQueueWait) {
  auto& server = shared_server();
  auto http = server.client();
  ASSERT_EQ(http->Get("/healthz?marker=log-test")->status, 200);
  ASSERT_EQ(http->Post("/v1/render", R"({"output": {"width": 16, "height": 16}})", "application/json")->status, 200);
  bool health_seen = false, render_seen = false;
  std::istringstream lines(server.log());
  for (std::string line; std::getline(lines, line);) {
    const auto entry = nlohmann::json::parse(line, nullptr, false);
    if (entry.is_discarded() || !entry.contains("path")) continue;
    EXPECT_TRUE(entry["ms"].is_number()) << line;
    if (entry["path"] == "/healthz" && entry["status"] == 200) health_seen = true;
    if (entry["path"] == "/v1/render" && entry["method"] == "POST" && entry["status"] == 200) {
      render_seen = true;
      EXPECT_TRUE(entry["queue_ms"].is_number()) << line;
    }
  }
  EXPECT_TRUE(health_seen);
  EXPECT_TRUE(render_seen);
}

TEST(HttpAccess, TokenGuardsEveryRouteButHealthAndReadiness) {
  ServerProcess server({"--token", "s3cret"});
  auto http = server.client();
  EXPECT_EQ(http->Get("/healthz")->status, 200);
  EXPECT_EQ(http->Get("/readyz")->status, 200);
  const auto anonymous = http->Get("/v1/scenes");
  EXPECT_TRUE(is_json_error(anonymous, 401, "unauthorized", ""));
  EXPECT_EQ(anonymous->get_header_value("WWW-Authenticate"), "Bearer");
  EXPECT_TRUE(is_json_error(http->Get("/metrics", {{"Authorization", "Bearer s3cre"}}), 401, "unauthorized", ""));
  EXPECT_TRUE(is_json_error(http->Get("/v1/device", {{"Authorization", "Bearer s3cret2"}}), 401, "unauthorized", ""));
  EXPECT_EQ(http->Get("/v1/scenes", {{"Authorization", "Bearer s3cret"}})->status, 200);
  const auto render = http->Post("/v1/render", {{"Authorization", "Bearer s3cret"}},
                                 R"({"output": {"width": 16, "height": 16}})", "application/json");
  ASSERT_TRUE(render);
  EXPECT_EQ(render->status, 200);
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

int exit_status_of(const std::string& arguments) {
  const int status = std::system((server_binary() + " " + arguments + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(HttpAccess, RefusesAPublicAddressWithoutATokenAndBadFlags) {
  EXPECT_EQ(exit_status_of("--host 0.0.0.0 --port 0"), 2);
  EXPECT_EQ(exit_status_of("--port 70000"), 2);
  EXPECT_EQ(exit_status_of("--queue 0"), 2);
  EXPECT_EQ(exit_status_of("--frobnicate"), 2);
  EXPECT_EQ(exit_status_of("--help"), 0);
}

}  // namespace
}  // namespace server_test
