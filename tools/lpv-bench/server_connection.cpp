#include "server_connection.hpp"

#include "input_files.hpp"

#include <cstdlib>
#include <regex>

namespace bench {
namespace {

// A long render on lavapipe takes seconds and a sweep minutes; the server's accuracy
// deadline (600 s by default) ends anything longer first.
constexpr time_t kReadTimeoutSeconds = 610;
constexpr time_t kConnectTimeoutSeconds = 10;

}  // namespace

ServerConnection::ServerConnection(const std::string& url) {
  static const std::regex base_url(R"(http://[A-Za-z0-9.\-]+(:[0-9]{1,5})?/?|http://\[[0-9A-Fa-f:]+\](:[0-9]{1,5})?/?)");
  if (!std::regex_match(url, base_url))
    throw BadInput("--url must be http://HOST[:PORT] (the server's root, no path), got '" + url + "'");
  url_ = url.back() == '/' ? url.substr(0, url.size() - 1) : url;
  client_ = std::make_unique<httplib::Client>(url_);
  client_->set_read_timeout(kReadTimeoutSeconds, 0);
  client_->set_connection_timeout(kConnectTimeoutSeconds, 0);
  client_->set_keep_alive(true);  // one connection for the whole run: no connection set-up in the round trips
  // A request's headers and body go out in separate writes: without this, Nagle's algorithm
  // holds the body until the server acknowledges the headers, which it may delay by 40 ms,
  // and round_trip_ms measured that stall (75.8 against 32.7 ms of frame at 256^2 in one run).
  client_->set_tcp_nodelay(true);
  if (const char* token = std::getenv("LPV_SERVER_TOKEN"); token && *token) client_->set_bearer_token_auth(token);
}

std::runtime_error ServerConnection::failure(const std::string& what, const httplib::Result& result) const {
  if (!result) return std::runtime_error(what + ": " + httplib::to_string(result.error()) + " error with " + url_);
  std::string message = std::to_string(result->status);
  const nlohmann::json body = nlohmann::json::parse(result->body, nullptr, false);
  if (body.is_object() && body.contains("error") && body["error"].is_object()) {
    const nlohmann::json& e = body["error"];
    for (const std::string& part : {e.value("code", ""), e.value("field", ""), e.value("message", "")}) {
      if (part.empty()) continue;
      message += ": ";  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on ": " + string
      message += part;
    }
  }
  return std::runtime_error(what + ": " + message);
}

nlohmann::json parse_answer(const std::string& text, const std::string& what) {
  nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded()) throw std::runtime_error(what + " is not JSON");
  return json;
}

}  // namespace bench
