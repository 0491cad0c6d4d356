// Uploaded scenes over real HTTP: upload, list, render by id, restart on the same data dir,
// delete; the same bytes twice; uploads that break off or that a crash interrupted leave
// nothing behind; and every way an upload or a scene id can be wrong. The scenes are the
// glTF corpus of the assimp-testmodels package (scripts/install-deps.sh).
#include "data_dir.hpp"
#include "http_checks.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <signal.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <future>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

namespace server_test {
namespace {

const std::filesystem::path kCorpus = "/usr/share/assimp/models/glTF2";
const std::filesystem::path kBoxGlb = kCorpus / "BoxTextured-glTF-Binary/BoxTextured.glb";            // 12 triangles
const std::filesystem::path kBoxGltf = kCorpus / "BoxTextured-glTF-Embedded/BoxTextured.gltf";       // data: URIs
const std::filesystem::path kExternalBin = kCorpus / "MissingBin/BoxTextured.gltf";                  // refers to a .bin
const std::filesystem::path kIndexOutOfRange = kCorpus / "IndexOutOfRange/IndexOutOfRange.gltf";     // and a .bin

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The SHA-256 as coreutils computes it: the server's id must be exactly that.
std::string sha256_of_file(const std::filesystem::path& path) {
  FILE* pipe = popen(("sha256sum '" + path.string() + "'").c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run sha256sum");
  char hex[65] = {};
  const std::size_t read = std::fread(hex, 1, 64, pipe);
  pclose(pipe);
  return std::string(hex, read);
}

// One triangle with its buffer in a data: URI, as in api/openapi.yaml.
nlohmann::json triangle_gltf() {
  return nlohmann::json::parse(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})");
}

httplib::Result upload(httplib::Client& http, const std::string& bytes, const std::string& query = "") {
  return http.Post("/v1/scenes" + query, bytes, "model/gltf-binary");
}

httplib::Result render(httplib::Client& http, const std::string& scene, int width = 48, int height = 32) {
  const nlohmann::json request = {{"scene", scene}, {"output", {{"width", width}, {"height", height}}}};
  return http.Post("/v1/render", request.dump(), "application/json");
}

::testing::AssertionResult renders_png(const httplib::Result& r, int width = 48, int height = 32) {
  if (!r) return ::testing::AssertionFailure() << "no response: " << httplib::to_string(r.error());
  if (r->status != 200) return ::testing::AssertionFailure() << "status " << r->status << ": " << r->body;
  const auto size = png_size(r->body);
  if (!size || size->width != width || size->height != height)
    return ::testing::AssertionFailure() << "not a " << width << "x" << height << " PNG";
  return ::testing::AssertionSuccess();
}

// The uploaded scenes GET /v1/scenes lists, by id.
std::map<std::string, nlohmann::json> uploaded_scenes(httplib::Client& http) {
  std::map<std::string, nlohmann::json> uploaded;
  const auto r = http.Get("/v1/scenes");
  if (!r || r->status != 200) return uploaded;
  const auto list = nlohmann::json::parse(r->body);
  for (const auto& scene : list["scenes"])
    if (scene["source"] == "uploaded") uploaded[scene["id"]] = scene;
  return uploaded;
}

// Waits up to 10 s for the server's log to have a line for `method path` with `status`.
bool logged(const ServerProcess& server, const std::string& method, const std::string& path, int status) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < give_up) {
    std::istringstream lines(server.log());
    for (std::string line; std::getline(lines, line);) {
      const auto entry = nlohmann::json::parse(line, nullptr, false);
      if (!entry.is_discarded() && entry.value("method", "") == method && entry.value("path", "") == path &&
          entry.value("status", 0) == status)
        return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

TEST(HttpScenes, UploadListRenderRestartDeleteAndRenderNoMore) {
  DataDir data;
  std::optional<ServerProcess> server;
  server.emplace(std::vector<std::string>{"--data-dir", data.path()});
  auto http = server->client();

  const std::string glb = read_file(kBoxGlb);
  const auto created = upload(*http, glb, "?name=textured%20box");
  ASSERT_TRUE(created);
  ASSERT_EQ(created->status, 201) << created->body;
  const auto report = nlohmann::json::parse(created->body);
  const std::string id = report["id"];
  EXPECT_EQ(id, sha256_of_file(kBoxGlb));
  EXPECT_EQ(report["sha256"], id);
  EXPECT_EQ(created->get_header_value("Location"), "/v1/scenes/" + id);
  EXPECT_EQ(report["name"], "textured box");
  EXPECT_EQ(report["source"], "uploaded");
  EXPECT_EQ(report["triangles"], 12);
  EXPECT_EQ(report["bytes"], glb.size());
  EXPECT_TRUE(report["uploaded_at"].is_string());
  EXPECT_EQ(report["bounds"]["min"], nlohmann::json({-0.5, -0.5, -0.5}));
  EXPECT_EQ(data.scene_files(), (std::set<std::string>{id + ".glb", id + ".json"}));

  // Listed next to the built-in scenes, which say they are built in; and on its own.
  const auto list = nlohmann::json::parse(http->Get("/v1/scenes")->body)["scenes"];
  std::map<std::string, std::string> sources;
  for (const auto& scene : list) sources[scene["id"]] = scene["source"];
  EXPECT_EQ(sources["cornell-box"], "builtin");
  EXPECT_EQ(sources[id], "uploaded");
  const auto one = http->Get("/v1/scenes/" + id);
  ASSERT_TRUE(one);
  ASSERT_EQ(one->status, 200);
  EXPECT_EQ(nlohmann::json::parse(one->body), report);

  // The upload warmed the scene up on the worker: its first render loads nothing and
  // compiles nothing (no scene_load, no warm_up among its CPU times).
  EXPECT_EQ(created->get_header_value("Server-Timing").rfind("warm_up;dur=", 0), 0u) << "the warm-up's time";
  const auto first = render(*http, id);
  EXPECT_TRUE(renders_png(first));
  const auto first_stats = nlohmann::json::parse(first->get_header_value("X-Render-Stats"));
  EXPECT_EQ(first_stats["scene"], id);
  EXPECT_EQ(first_stats["cpu_ms"]["scene_load"]["median"], 0.0);
  EXPECT_FALSE(first_stats["cpu_ms"].contains("warm_up")) << first_stats["cpu_ms"].dump();
  const std::string metrics = http->Get("/metrics")->body;
  EXPECT_NE(metrics.find("lpv_uploaded_scenes 1\n"), std::string::npos);
  EXPECT_NE(metrics.find("lpv_scene_cache_scenes{worker=\"0\"} "), std::string::npos);

  // A restart on the same data dir finds it as it was.
  ASSERT_EQ(server->stop(SIGTERM), 0);
  server.emplace(std::vector<std::string>{"--data-dir", data.path()});
  http = server->client();
  EXPECT_EQ(uploaded_scenes(*http), (std::map<std::string, nlohmann::json>{{id, report}}));
  // Not resident after the restart: the first render loads it and warms it up, and says so
  // apart from its frames.
  const auto after_restart = render(*http, id);
  EXPECT_TRUE(renders_png(after_restart));
  const auto restart_stats = nlohmann::json::parse(after_restart->get_header_value("X-Render-Stats"));
  EXPECT_GT(restart_stats["cpu_ms"]["warm_up"]["median"].get<double>(), 0.0) << restart_stats["cpu_ms"].dump();

  const auto deleted = http->Delete("/v1/scenes/" + id);
  ASSERT_TRUE(deleted);
  EXPECT_EQ(deleted->status, 204);
  EXPECT_TRUE(data.scene_files().empty());
  EXPECT_TRUE(is_json_error(render(*http, id), 404, "scene_not_found", "scene"));
  EXPECT_TRUE(is_json_error(http->Get("/v1/scenes/" + id), 404, "scene_not_found", ""));
  EXPECT_TRUE(is_json_error(http->Delete("/v1/scenes/" + id), 404, "scene_not_found", ""));
  EXPECT_TRUE(uploaded_scenes(*http).empty());
}

TEST(HttpScenes, AFullStoreRefusesNewScenesWith507AndKeepsWhatItHas) {
  DataDir data;
  const std::string glb = read_file(kBoxGlb), gltf = read_file(kBoxGltf), triangle = triangle_gltf().dump();
  {
    // A quota of scenes: one.
    ServerProcess server({"--data-dir", data.path(), "--max-store-scenes", "1"});
    auto http = server.client();
    const auto first = upload(*http, glb);
    ASSERT_EQ(first->status, 201) << first->body;
    const std::string id = nlohmann::json::parse(first->body)["id"];
    const auto refused = upload(*http, triangle);
    EXPECT_TRUE(is_json_error(refused, 507, "insufficient_storage", ""));
    EXPECT_NE(refused->body.find("holds 1 scene, its most"), std::string::npos) << refused->body;
    EXPECT_EQ(upload(*http, glb)->status, 200) << "the same bytes again are no new scene";
    EXPECT_EQ(uploaded_scenes(*http).size(), 1u);
    EXPECT_TRUE(renders_png(render(*http, id))) << "what was stored is untouched";
    ASSERT_EQ(http->Delete("/v1/scenes/" + id)->status, 204);
    EXPECT_EQ(upload(*http, triangle)->status, 201) << "room again after a delete";
  }
  {
    // A quota of bytes: the stored triangle and the box's .glb fit, the box's bigger .gltf then not.
    const std::string quota = std::to_string(triangle.size() + glb.size() + gltf.size() - 1);
    ServerProcess server({"--data-dir", data.path(), "--max-store-bytes", quota});
    auto http = server.client();
    EXPECT_EQ(upload(*http, glb)->status, 201);
    const auto refused = upload(*http, gltf);
    EXPECT_TRUE(is_json_error(refused, 507, "insufficient_storage", ""));
    EXPECT_NE(refused->body.find("--max-store-bytes"), std::string::npos) << refused->body;
    EXPECT_EQ(uploaded_scenes(*http).size(), 2u);
    EXPECT_EQ(data.scene_files().size(), 4u) << "two scenes, each its report and its bytes; nothing half-written";
  }
}

TEST(HttpScenes, TheSameBytesTwiceAreOneScene) {
  DataDir data;
  ServerProcess server({"--data-dir", data.path()});
  auto http = server.client();
  const std::string gltf = read_file(kBoxGltf);
  const auto first = upload(*http, gltf, "?name=first");
  ASSERT_TRUE(first);
  ASSERT_EQ(first->status, 201) << first->body;
  const auto second = upload(*http, gltf, "?name=second");
  ASSERT_TRUE(second);
  EXPECT_EQ(second->status, 200);
  EXPECT_EQ(second->body, first->body);  // the first upload's report, its name included
  const std::string id = nlohmann::json::parse(first->body)["id"];
  EXPECT_EQ(id, sha256_of_file(kBoxGltf));
  EXPECT_EQ(uploaded_scenes(*http).size(), 1u);
  EXPECT_EQ(data.scene_files(), (std::set<std::string>{id + ".gltf", id + ".json"}));
  EXPECT_TRUE(renders_png(render(*http, id)));
}

TEST(HttpScenes, ADeletedSceneIsNotRenderedFromAWorkersCache) {
  ServerProcess server;
  auto http = server.client();
  const auto uploaded = upload(*http, read_file(kBoxGlb));
  ASSERT_TRUE(uploaded);
  ASSERT_EQ(uploaded->status, 201);
  const std::string id = nlohmann::json::parse(uploaded->body)["id"];
  ASSERT_TRUE(renders_png(render(*http, id)));  // now resident on the worker

  // A render of it waits behind a slow one while the scene is deleted: it got past the
  // check before queueing, so the worker must see the deletion itself.
  auto slow = start_slow_render(server);
  ASSERT_TRUE(wait_for_metric(server, "lpv_renders_in_flight", 1));
  auto queued = std::async(std::launch::async, [&] { return render(*server.client(), id); });
  ASSERT_TRUE(wait_for_metric(server, "lpv_render_queue_depth", 1));
  ASSERT_EQ(http->Delete("/v1/scenes/" + id)->status, 204);
  EXPECT_TRUE(is_json_error(queued.get(), 404, "scene_not_found", "scene"));
  EXPECT_EQ(slow.get()->status, 200);
}

// Sends the headers of an upload of 100000 bytes and only the first `sent` of them, then
// closes the connection, as a client that crashed would.
void send_partial_upload(int port, const std::string& bytes, std::size_t sent) {
  send_raw(port,
           "POST /v1/scenes HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: model/gltf-binary\r\n"
           "Content-Length: 100000\r\n\r\n" +
               bytes.substr(0, sent));
}

TEST(HttpScenes, AnUploadThatBreaksOffLeavesNothingBehind) {
  DataDir data;
  ServerProcess server({"--data-dir", data.path()});
  auto http = server.client();
  ASSERT_EQ(upload(*http, read_file(kBoxGltf))->status, 201);
  const auto files_before = data.scene_files();
  const auto scenes_before = uploaded_scenes(*http);

  send_partial_upload(server.port(), read_file(kBoxGlb), 3000);
  ASSERT_TRUE(logged(server, "POST", "/v1/scenes", 400)) << server.log();
  EXPECT_EQ(data.scene_files(), files_before);
  EXPECT_EQ(uploaded_scenes(*http), scenes_before);
  EXPECT_EQ(http->Get("/healthz")->status, 200);
}

TEST(HttpScenes, WhatACrashLeftIsRemovedAtStartAndNeverListed) {
  DataDir data;
  std::filesystem::create_directories(data.scenes());
  // A write interrupted before its rename, and an upload interrupted between writing its
  // report and its scene file, both an hour and more ago (younger ones may be another
  // replica's upload in progress: SceneStore::kStaleAge).
  write_file(data.scenes() / ".partial-Xy12Zq", read_file(kBoxGlb).substr(0, 1000));
  const std::string unfinished(64, 'a');
  write_file(data.scenes() / (unfinished + ".json"),
             nlohmann::json({{"id", unfinished}, {"uploaded_at", "2025-01-01T00:00:00.000Z"}, {"bytes", 4696}}).dump());
  for (const std::string& file : {std::string(".partial-Xy12Zq"), unfinished + ".json"})
    std::filesystem::last_write_time(data.scenes() / file,
                                     std::filesystem::file_time_type::clock::now() - std::chrono::minutes(61));

  ServerProcess server({"--data-dir", data.path()});
  auto http = server.client();
  EXPECT_TRUE(data.scene_files().empty());
  EXPECT_TRUE(uploaded_scenes(*http).empty());
  EXPECT_TRUE(is_json_error(http->Get("/v1/scenes/" + unfinished), 404, "scene_not_found", ""));
  EXPECT_NE(server.log().find("\"removed_temporary\":1"), std::string::npos) << server.log();
  EXPECT_NE(server.log().find("\"removed_unfinished\":1"), std::string::npos) << server.log();
}

TEST(HttpScenes, BadUploadsAndBadIdsAreRefusedWithTheirStatus) {
  // No --data-dir: uploads live in memory.
  ServerProcess server({"--max-scene-bytes", "6000", "--max-scene-triangles", "5"});
  auto http = server.client();

  EXPECT_TRUE(is_json_error(upload(*http, std::string(10000, 'x')), 413, "payload_too_large", ""));
  EXPECT_TRUE(is_json_error(upload(*http, read_file(kBoxGlb)), 422, "scene_too_complex", ""));
  EXPECT_TRUE(is_json_error(upload(*http, read_file(kExternalBin)), 422, "invalid_scene", ""));
  EXPECT_TRUE(is_json_error(upload(*http, read_file(kIndexOutOfRange)), 422, "invalid_scene", ""));
  EXPECT_TRUE(is_json_error(upload(*http, "not a scene"), 422, "invalid_scene", ""));
  nlohmann::json out_of_range = triangle_gltf();
  out_of_range["accessors"][0]["bufferView"] = 7;
  EXPECT_TRUE(is_json_error(upload(*http, out_of_range.dump()), 422, "invalid_scene", ""));
  nlohmann::json draco = triangle_gltf();
  draco["extensionsUsed"] = draco["extensionsRequired"] = nlohmann::json::array({"KHR_draco_mesh_compression"});
  EXPECT_TRUE(is_json_error(upload(*http, draco.dump()), 422, "unsupported_scene", ""));
  EXPECT_TRUE(is_json_error(upload(*http, triangle_gltf().dump(), "?name=%01"), 400, "invalid_value", "name"));
  EXPECT_TRUE(uploaded_scenes(*http).empty());

  // Within the limits it is kept (in memory) and renders.
  const auto triangle = upload(*http, triangle_gltf().dump());
  ASSERT_TRUE(triangle);
  ASSERT_EQ(triangle->status, 201) << triangle->body;
  const std::string id = nlohmann::json::parse(triangle->body)["id"];
  EXPECT_EQ(nlohmann::json::parse(triangle->body)["name"], id);  // no ?name=
  EXPECT_TRUE(renders_png(render(*http, id)));

  const std::string unknown(64, '0');
  EXPECT_TRUE(is_json_error(http->Get("/v1/scenes/" + unknown), 404, "scene_not_found", ""));
  EXPECT_TRUE(is_json_error(http->Delete("/v1/scenes/" + unknown), 404, "scene_not_found", ""));
  EXPECT_TRUE(is_json_error(render(*http, unknown), 404, "scene_not_found", "scene"));
  EXPECT_TRUE(is_json_error(render(*http, std::string(64, 'A')), 404, "scene_not_found", "scene"));
  EXPECT_TRUE(is_json_error(render(*http, "../../etc/passwd"), 400, "invalid_value", "scene"));  // the schema's
  // Ids with path characters never name a scene (httplib decodes %2F into '/').
  for (const std::string path : {"/v1/scenes/..%2F..%2Fetc", "/v1/scenes/%2E%2E", "/v1/scenes/%FF"}) {
    const auto got = http->Get(path);
    ASSERT_TRUE(got) << path;
    EXPECT_EQ(got->status, 404) << path << ": " << got->body;
    const auto removed = http->Delete(path);
    ASSERT_TRUE(removed) << path;
    EXPECT_EQ(removed->status, 404) << path << ": " << removed->body;
  }
  EXPECT_TRUE(is_json_error(http->Delete("/v1/scenes/cornell-box"), 409, "builtin_scene", ""));
  const auto put = http->Put("/v1/scenes", "{}", "application/json");
  EXPECT_TRUE(is_json_error(put, 405, "method_not_allowed", ""));
  EXPECT_EQ(put->get_header_value("Allow"), "GET, POST");

  EXPECT_EQ(uploaded_scenes(*http).size(), 1u);
  EXPECT_EQ(http->Get("/healthz")->status, 200);
}

// Replicas: two servers on one --data-dir behave as one service (docs/server.md, "Replicas").
// A scene uploaded through one renders on the other, bit for bit as on the first; a delete
// through either is final on both, also for the one that holds it resident.
TEST(HttpScenes, ReplicasSharingADataDirAreOneStore) {
  DataDir data;
  ServerProcess a({"--data-dir", data.path()}), b({"--data-dir", data.path()});
  auto on_a = a.client();
  auto on_b = b.client();
  const auto created = upload(*on_a, read_file(kBoxGlb));
  ASSERT_TRUE(created);
  ASSERT_EQ(created->status, 201);
  const std::string id = nlohmann::json::parse(created->body)["id"];
  const auto from_a = render(*on_a, id), from_b = render(*on_b, id);
  EXPECT_TRUE(renders_png(from_a));
  EXPECT_TRUE(renders_png(from_b));
  if (from_a && from_b) {
    EXPECT_EQ(from_a->body, from_b->body) << "the same bits from every replica";
  }
  EXPECT_EQ(on_b->Get("/v1/scenes/" + id)->status, 200);
  EXPECT_NE(on_b->Get("/v1/scenes")->body.find(id), std::string::npos);
  EXPECT_EQ(upload(*on_b, read_file(kBoxGlb))->status, 200) << "the other replica's scene: no second copy";

  ASSERT_EQ(on_b->Delete("/v1/scenes/" + id)->status, 204);
  EXPECT_TRUE(is_json_error(render(*on_a, id), 404, "scene_not_found", "scene")) << "A still held it resident";
  EXPECT_EQ(on_a->Get("/v1/scenes/" + id)->status, 404);
  EXPECT_EQ(on_a->Get("/v1/scenes")->body.find(id), std::string::npos);
  EXPECT_EQ(a.stop(SIGTERM), 0);
  EXPECT_EQ(b.stop(SIGTERM), 0);
}

}  // namespace
}  // namespace server_test
