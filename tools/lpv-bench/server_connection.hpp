// A connection to a running lpv-server, as lpv-bench's clients of one make it: the URL
// checked, $LPV_SERVER_TOKEN as the bearer token, and the server's errors in words.
#pragma once

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <memory>
#include <stdexcept>
#include <string>

namespace bench {

class ServerConnection {
 public:
  // `url`: http://HOST:PORT. Throws BadInput for a URL it cannot use.
  explicit ServerConnection(const std::string& url);

  httplib::Client& http() { return *client_; }
  const std::string& url() const { return url_; }

  // "POST /v1/render: 422: limit_exceeded: lpv.grid: grid x * y * z ...": what the server said.
  std::runtime_error failure(const std::string& what, const httplib::Result& result) const;

 private:
  std::string url_;
  std::unique_ptr<httplib::Client> client_;
};

// The answer's body as JSON; throws naming `what` when it is not.
nlohmann::json parse_answer(const std::string& text, const std::string& what);

}  // namespace bench
