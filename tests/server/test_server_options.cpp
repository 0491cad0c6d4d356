#include "server/server_options.hpp"

#include <gtest/gtest.h>

#include <map>
#include <vector>

namespace server {
namespace {

ServerOptions parse(std::vector<const char*> args, std::map<std::string, std::string> env = {}) {
  args.insert(args.begin(), "lpv-server");
  return parse_server_options(int(args.size()), args.data(), [&env](const char* name) -> const char* {
    const auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  });
}

TEST(ServerOptions, DefaultsAreLoopbackPort8080AndSafeLimits) {
  const ServerOptions o = parse({});
  EXPECT_EQ(o.host, "127.0.0.1");
  EXPECT_EQ(o.port, 8080);
  EXPECT_TRUE(o.token.empty());
  EXPECT_EQ(o.limits.max_pixels, 4096u * 4096u);
  EXPECT_EQ(o.limits.max_grid_cells, 128u * 128u * 128u);
  EXPECT_EQ(o.limits.max_iterations, 64u);
  EXPECT_TRUE(o.data_dir.empty());
  EXPECT_EQ(o.max_scene_bytes, 64u << 20);
  EXPECT_EQ(o.scene_cache_bytes, 1ull << 30);
}

TEST(ServerOptions, SceneSettingsAndTheLargestBodyHttplibMustAccept) {
  const ServerOptions o = parse({"--max-scene-bytes", "1000000", "--max-scene-triangles=500", "--scene-cache-mb", "64"},
                                {{"LPV_SERVER_MAX_BODY_BYTES", "2000000"}});
  EXPECT_EQ(o.max_scene_bytes, 1000000u);
  EXPECT_EQ(o.scene_limits.max_triangles, 500u);
  EXPECT_EQ(o.scene_cache_bytes, 64ull << 20);
  // Renders may take more than uploads; httplib's one limit must allow both.
  EXPECT_EQ(largest_body_bytes(o), 2000000u);
  EXPECT_EQ(largest_body_bytes(parse({"--max-scene-bytes", "5000000"})), 5000000u);
}

TEST(ServerOptions, FlagsAndEnvironmentWithFlagsWinning) {
  const ServerOptions o = parse({"--port", "9000", "--queue=3", "--max-iterations", "12"},
                                {{"LPV_SERVER_PORT", "7000"}, {"LPV_SERVER_WORKERS", "2"},
                                 {"LPV_SERVER_TOKEN", "abc"}, {"LPV_SERVER_DEADLINE_MS", "1500"}});
  EXPECT_EQ(o.port, 9000);
  EXPECT_EQ(o.queue_capacity, 3u);
  EXPECT_EQ(o.render_workers, 2u);
  EXPECT_EQ(o.token, "abc");
  EXPECT_EQ(o.deadline.count(), 1500);
  EXPECT_EQ(o.limits.max_iterations, 12u);
}

TEST(ServerOptions, BadValuesNameTheFlagOrVariable) {
  auto message = [](std::vector<const char*> args, std::map<std::string, std::string> env = {}) -> std::string {
    try {
      parse(std::move(args), std::move(env));
    } catch (const OptionsError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message({"--port", "65536"}).find("--port"), std::string::npos);
  EXPECT_NE(message({"--port", "80x"}).find("--port"), std::string::npos);
  EXPECT_NE(message({"--queue", "0"}).find("--queue"), std::string::npos);
  EXPECT_NE(message({"--max-pixels", "-1"}).find("--max-pixels"), std::string::npos);
  EXPECT_NE(message({"--max-iterations", "1025"}).find("--max-iterations"), std::string::npos);
  EXPECT_NE(message({"--workers"}).find("needs a value"), std::string::npos);
  EXPECT_NE(message({"--verbose"}).find("unknown option"), std::string::npos);
  EXPECT_NE(message({}, {{"LPV_SERVER_THREADS", "many"}}).find("LPV_SERVER_THREADS"), std::string::npos);
  EXPECT_NE(message({"--token", ""}).find("--token"), std::string::npos);
  EXPECT_NE(message({"--max-scene-bytes", "2000000000"}).find("--max-scene-bytes"), std::string::npos);
  EXPECT_NE(message({"--max-scene-triangles", "0"}).find("--max-scene-triangles"), std::string::npos);
  EXPECT_NE(message({}, {{"LPV_SERVER_SCENE_CACHE_MB", "lots"}}).find("LPV_SERVER_SCENE_CACHE_MB"), std::string::npos);
}

TEST(ServerOptions, AllowedHostsRepeatSplitAtCommasAndRefusePorts) {
  EXPECT_TRUE(parse({}).allowed_hosts.empty());
  EXPECT_EQ(parse({"--allowed-host", "a.example,b.example", "--allowed-host=[::2]"}).allowed_hosts,
            (std::vector<std::string>{"a.example", "b.example", "::2"}));
  EXPECT_EQ(parse({}, {{"LPV_SERVER_ALLOWED_HOST", "*"}}).allowed_hosts, (std::vector<std::string>{"*"}));
  for (const char* bad : {"a.example:8080", "", "a.example,", "http://a.example", "::1", "[::1]:80", "*.example"})
    EXPECT_THROW(parse({"--allowed-host", bad}), OptionsError) << bad;
}

TEST(ServerOptions, APublicAddressNeedsATokenOrInsecure) {
  EXPECT_THROW(parse({"--host", "0.0.0.0"}), OptionsError);
  EXPECT_THROW(parse({}, {{"LPV_SERVER_HOST", "192.168.1.5"}}), OptionsError);
  EXPECT_EQ(parse({"--host", "0.0.0.0", "--token", "t"}).host, "0.0.0.0");
  EXPECT_TRUE(parse({"--host", "0.0.0.0", "--insecure"}).insecure);
  EXPECT_TRUE(parse({"--host", "::1"}).token.empty());
}

}  // namespace
}  // namespace server
