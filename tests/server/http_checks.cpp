#include "http_checks.hpp"

#include "raw_connection.hpp"

#include "core/base64.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <regex>
#include <stdexcept>
#include <thread>

namespace server_test {
namespace {

const char* type_name(const nlohmann::json& j) {
  if (j.is_number()) return "number";  // integer and float examples match either
  return j.type_name();
}

::testing::AssertionResult shape(const nlohmann::json& example, const nlohmann::json& actual, const std::string& path) {
  if (std::string(type_name(example)) != type_name(actual))
    return ::testing::AssertionFailure() << path << ": expected a " << type_name(example) << ", got "
                                         << actual.dump();
  if (example.is_object()) {
    for (const auto& [key, value] : example.items()) {
      if (!actual.contains(key)) return ::testing::AssertionFailure() << path << "." << key << " is missing";
      if (auto r = shape(value, actual.at(key), path + "." + key); !r) return r;
    }
  } else if (example.is_array() && !example.empty()) {
    for (std::size_t i = 0; i < actual.size(); ++i)
      if (auto r = shape(example.front(), actual.at(i), path + "[" + std::to_string(i) + "]"); !r) return r;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace

long status_kb(pid_t pid, const std::string& field) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field + ":", 0) == 0) return std::stol(line.substr(field.size() + 1));
  return -1;
}

std::string long_render_body(const ServerProcess& server) {
  nlohmann::json request = {{"output", {{"width", 1024}, {"height", 1024}}},
                            {"lpv", {{"grid", 96}, {"iterations", 64}}},
                            {"plan", "exact"},
                            {"repeat", 2}};
  const auto timed = server.client()->Post("/v1/render", {{"X-Deadline-Ms", "1000"}}, request.dump(), "application/json");
  if (!timed) throw std::runtime_error("long_render_body: the timing render got no answer");
  int repeat = kLongRenderMaxRepeat;
  if (timed->status == 200) {
    const double frame_ms = nlohmann::json::parse(timed->get_header_value("X-Render-Stats"))["wall_ms"]["min"];
    if (frame_ms * kLongRenderMaxRepeat < 10000.0) return {};
    repeat = std::min(kLongRenderMaxRepeat, int(std::ceil(60000.0 / std::max(frame_ms, 1e-3))));
  } else if (timed->status != 504) {
    throw std::runtime_error("long_render_body: the timing render answered " + std::to_string(timed->status));
  }
  request["repeat"] = repeat;
  return request.dump();
}

std::future<httplib::Result> start_slow_render(const ServerProcess& server) {
  // Two frames, the faster one counted: the first also compiles the pipelines (2.5 times a
  // warm frame on lavapipe).
  nlohmann::json request = {{"output", {{"width", kSlowRenderSize}, {"height", kSlowRenderSize}}},
                            {"lpv", {{"enabled", false}}},
                            {"repeat", 2}};
  const auto timed = server.client()->Post("/v1/render", request.dump(), "application/json");
  if (!timed || timed->status != 200) throw std::runtime_error("start_slow_render: the timing render failed");
  const double frame_ms = nlohmann::json::parse(timed->get_header_value("X-Render-Stats"))["wall_ms"]["min"];
  request["repeat"] = std::clamp(int(std::ceil(1000.0 / std::max(frame_ms, 1e-3))), 1, 100);
  return std::async(std::launch::async, [&server, body = request.dump()] {
    return server.client()->Post("/v1/render", body, "application/json");
  });
}

std::optional<ImageSize> png_size(const std::string& bytes) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &width,
                                          &height, &channels, 4);
  if (!pixels) return std::nullopt;
  stbi_image_free(pixels);
  return ImageSize{width, height};
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string() + " (is assimp-testmodels installed?)");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::string base64_decode(const std::string& text) {
  const auto bytes = core::base64_decode(text);
  return bytes ? std::string(bytes->begin(), bytes->end()) : std::string();
}

std::string send_raw(int port, const std::string& bytes, int answer_timeout_s) {
  const int fd = connect_to(port);
  if (fd < 0 || !send_all(fd, bytes)) {
    if (fd >= 0) close(fd);
    throw std::runtime_error("send_raw: could not send the request to port " + std::to_string(port));
  }
  const timeval wait{answer_timeout_s, 0};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof(wait));
  std::string answer;
  if (answer_timeout_s > 0) {
    char buffer[256];
    for (ssize_t n; answer.find("\r\n") == std::string::npos && (n = recv(fd, buffer, sizeof(buffer), 0)) > 0;)
      answer.append(buffer, std::size_t(n));
  }
  close(fd);
  return answer.substr(0, answer.find("\r\n"));
}

std::map<std::string, double> parse_server_timing(const std::string& header) {
  std::map<std::string, double> entries;
  std::size_t start = 0;
  while (start < header.size()) {
    std::size_t end = header.find(',', start);
    if (end == std::string::npos) end = header.size();
    std::string entry = header.substr(start, end - start);
    start = end + 1;
    entry.erase(0, entry.find_first_not_of(' '));
    const auto semicolon = entry.find(';');
    const auto dur = entry.find("dur=");
    if (semicolon == std::string::npos || dur == std::string::npos) continue;
    entries[entry.substr(0, semicolon)] = std::strtod(entry.c_str() + dur + 4, nullptr);
  }
  return entries;
}

::testing::AssertionResult is_json_error(const httplib::Result& result, int status, const std::string& code,
                                         const std::string& field) {
  if (!result) return ::testing::AssertionFailure() << "no response: " << httplib::to_string(result.error());
  if (result->status != status)
    return ::testing::AssertionFailure() << "status " << result->status << ", expected " << status << "; body "
                                         << result->body;
  if (result->get_header_value("Content-Type") != "application/json")
    return ::testing::AssertionFailure() << "Content-Type " << result->get_header_value("Content-Type");
  const auto body = nlohmann::json::parse(result->body, nullptr, false);
  if (body.is_discarded() || !body.contains("error"))
    return ::testing::AssertionFailure() << "not an error body: " << result->body;
  const auto& error = body["error"];
  if (!error.value("code", nlohmann::json()).is_string() || !error.value("message", nlohmann::json()).is_string() ||
      !error.value("field", nlohmann::json()).is_string())
    return ::testing::AssertionFailure() << "error needs string code, message and field: " << result->body;
  if (error["code"] != code || error["field"] != field || error["message"].get<std::string>().empty())
    return ::testing::AssertionFailure() << "expected code '" << code << "' and field '" << field << "', got "
                                         << result->body;
  return ::testing::AssertionSuccess();
}

double metric(const ServerProcess& server, const std::string& series) {
  const auto r = server.client()->Get("/metrics");
  if (!r || r->status != 200) return -1;
  const std::regex line("(^|\n)" + std::regex_replace(series, std::regex(R"([{}\[\]().+*?^$|\\])"), R"(\$&)") +
                        " ([0-9.e+-]+)");
  std::smatch m;
  return std::regex_search(r->body, m, line) ? std::stod(m[2]) : 0.0;
}

bool wait_for_metric(const ServerProcess& server, const std::string& series, double value) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < give_up) {
    if (metric(server, series) == value) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

::testing::AssertionResult has_shape_of(const nlohmann::json& example, const nlohmann::json& actual) {
  return shape(example, actual, "$");
}

}  // namespace server_test
