// Renders benchmark cases through an lpv-server (lpv-bench run --url, and the round-trip
// cases): POST /v1/render as a client sends it, timed from the request to the last byte of
// the answer, with the server's own stats beside.
#pragma once

#include "lab/bench/suite_runner.hpp"
#include "server_connection.hpp"

#include <httplib.h>

#include <map>
#include <string>

namespace bench {

class HttpCaseRunner : public CaseRunner {
 public:
  // `url`: http://HOST:PORT. $LPV_SERVER_TOKEN, when set, is sent as the bearer token.
  // Throws BadInput for a URL it cannot use.
  explicit HttpCaseRunner(const std::string& url);

  api::BenchDevice device() override;  // GET /v1/device
  // render cases: Accept: application/json, the stats from the answer; server_round_trip
  // cases: the image in the body, as a client that wants the image asks, the stats from
  // X-Render-Stats. Both add round_trip_ms.
  Measurement render_timed(const api::BenchCase& c) override;
  // The request with output.format "pfm": the linear radiance.
  api::BenchImage render_image(const api::BenchCase& c) override;

 private:
  nlohmann::json request_body(const api::BenchCase& c);  // a scene file is uploaded once, then named by its id
  httplib::Result post_render(const nlohmann::json& body, bool want_json);

  ServerConnection server_;
  std::map<std::string, std::string> uploaded_;  // scene file -> scene id
};

}  // namespace bench
