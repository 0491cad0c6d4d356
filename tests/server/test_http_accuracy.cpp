// POST /v1/compare and POST /v1/sweep over real HTTP: images that decode (PNG, or PFM of the
// linear images equal to /v1/render's), a region that restricts the metrics, the sweep's four
// answers (JSON, CSV, SVG, a stream of events), a client that leaves mid-sweep, and the
// reference's cost limit. The contract test sends the OpenAPI examples besides these.
#include "http_checks.hpp"
#include "server_process.hpp"

#include "image/pfm.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string_view>
#include <string>
#include <vector>

namespace server_test {
namespace {

const nlohmann::json kSmallSweep = {{"base", {{"output", {{"width", 48}, {"height", 40}}}}},
                                    {"parameters", {{"grid", {8, 16}}, {"iterations", {2, 4}}}},
                                    {"reference", {{"samples", 8}}}};

std::vector<nlohmann::json> lines_of(const std::string& body) {
  std::vector<nlohmann::json> events;
  std::istringstream in(body);
  for (std::string line; std::getline(in, line);) events.push_back(nlohmann::json::parse(line));
  return events;
}

TEST(HttpAccuracy, CompareAnswersBothImagesTheHeatMapAndTheMetrics) {
  auto http = shared_server().client();
  const nlohmann::json request = {{"base", {{"output", {{"width", 40}, {"height", 32}}}}},
                                  {"reference", {{"samples", 4}, {"seed", 7}}}};
  const auto r = http->Post("/v1/compare", {{"Accept-Encoding", "br, gzip"}}, request.dump(), "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json") << "one media type for every JSON answer";
  EXPECT_EQ(r->get_header_value("Content-Encoding"), "") << "base64 images are sent uncompressed";
  const auto body = nlohmann::json::parse(r->body);
  for (const auto& image : {body["base"]["image"], body["other"]["image"], body["difference"]["image"]}) {
    const auto size = png_size(base64_decode(image.get<std::string>()));
    ASSERT_TRUE(size);
    EXPECT_EQ(size->width, 40);
    EXPECT_EQ(size->height, 32);
  }
  EXPECT_EQ(body["other"]["label"], "reference");
  EXPECT_EQ(body["other"]["reference"]["samples"], 4);
  EXPECT_EQ(body["other"]["reference"]["seed"], 7);
  EXPECT_GT(body["metrics"]["final"]["rmse"].get<double>(), 0.0);
  EXPECT_GT(body["metrics"]["final"]["pixels"].get<int>(), 0);
  EXPECT_GT(body["difference"]["scale"].get<double>(), 0.0);
  EXPECT_TRUE(body["base"]["stats"]["passes"].is_array());
}

TEST(HttpAccuracy, CompareOfIdenticalSettingsHasZeroErrorAndNullPsnr) {
  auto http = shared_server().client();
  const nlohmann::json request = {{"base", {{"output", {{"width", 32}, {"height", 32}}}}},
                                  {"against", nlohmann::json::object()}};
  const auto r = http->Post("/v1/compare", request.dump(), "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto metrics = nlohmann::json::parse(r->body)["metrics"]["final"];
  EXPECT_EQ(metrics["rmse"], 0.0);
  EXPECT_TRUE(metrics["psnr_db"].is_null());  // +inf: JSON has no infinity
  EXPECT_EQ(metrics["ssim"], 1.0);
}

image::RgbaF32Image decoded_pfm(const nlohmann::json& base64) {
  const std::string bytes = base64_decode(base64.get<std::string>());
  return image::decode_pfm({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
}

TEST(HttpAccuracy, CompareWithPfmImagesAnswersTheLinearRendersValues) {
  auto http = shared_server().client();
  const nlohmann::json base = {{"output", {{"width", 32}, {"height", 24}}}};
  const nlohmann::json request = {{"base", base}, {"against", nlohmann::json::object()}, {"images", "pfm"}};
  const auto r = http->Post("/v1/compare", request.dump(), "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body.substr(0, 500);
  const auto body = nlohmann::json::parse(r->body);
  EXPECT_EQ(body["images"], "pfm");
  for (const auto& encoded : {body["base"]["image"], body["base"]["indirect"], body["other"]["image"],
                              body["other"]["indirect"], body["flip"]["values"]}) {
    const image::RgbaF32Image img = decoded_pfm(encoded);
    EXPECT_EQ(img.width, 32u);
    EXPECT_EQ(img.height, 24u);
  }

  // The same request rendered alone, as a PFM: the compare's base image holds its values.
  nlohmann::json render = base;
  render["output"]["format"] = "pfm";
  const auto rendered = http->Post("/v1/render", render.dump(), "application/json");
  ASSERT_TRUE(rendered);
  ASSERT_EQ(rendered->status, 200);
  const image::RgbaF32Image alone = image::decode_pfm(
      {reinterpret_cast<const std::uint8_t*>(rendered->body.data()), rendered->body.size()});
  const image::RgbaF32Image compared = decoded_pfm(body["base"]["image"]);
  EXPECT_EQ(compared.pixels, alone.pixels);
  EXPECT_GT(*std::max_element(compared.pixels.begin(), compared.pixels.end()), 0.0f) << "not a black image";

  // Against itself: FLIP 0 everywhere, as much indirect light on both sides.
  EXPECT_EQ(body["flip"]["mean"], 0.0);
  EXPECT_EQ(body["metrics"]["final"]["flip"], 0.0);
  EXPECT_EQ(body["metrics"]["indirect"]["flip"], 0.0);
  const image::RgbaF32Image flip = decoded_pfm(body["flip"]["values"]);
  EXPECT_EQ(*std::max_element(flip.pixels.begin(), flip.pixels.end()), 1.0f) << "alpha 1, values 0";
  for (std::size_t i = 0; i < flip.pixels.size(); i += 4) ASSERT_EQ(flip.pixels[i], 0.0f);
  EXPECT_EQ(body["indirect_ratio"], 1.0);
  const auto heat = png_size(base64_decode(body["flip"]["image"].get<std::string>()));
  ASSERT_TRUE(heat);
  EXPECT_EQ(heat->width, 32);
  EXPECT_NEAR(body["flip"]["viewing"]["pixels_per_degree"].get<double>(), 67.02, 0.01);
}

TEST(HttpAccuracy, ARegionRestrictsThePixelsCounted) {
  auto http = shared_server().client();
  const nlohmann::json region = {{"x", 4}, {"y", 2}, {"width", 10}, {"height", 6}};
  const nlohmann::json request = {{"base", {{"output", {{"width", 32}, {"height", 24}}}, {"lpv", {{"grid", 8}}}}},
                                  {"against", {{"lpv", {{"grid", 16}}}}},
                                  {"mask", "all"},
                                  {"region", region}};
  const auto r = http->Post("/v1/compare", request.dump(), "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body.substr(0, 500);
  const auto body = nlohmann::json::parse(r->body);
  EXPECT_EQ(body["metrics"]["final"]["pixels"], 60);  // 10 x 6, every pixel with mask "all"
  EXPECT_EQ(body["metrics"]["indirect"]["pixels"], 60);
  EXPECT_EQ(body["region"], region);
  EXPECT_EQ(body["images"], "png");
  EXPECT_TRUE(body["indirect_ratio"].is_number());
  EXPECT_GE(body["flip"]["mean"].get<double>(), 0.0);
  EXPECT_EQ(body["flip"]["mean"], body["metrics"]["final"]["flip"]);

  nlohmann::json outside = request;
  outside["region"]["height"] = 23;  // rows 2..24 of 24
  EXPECT_TRUE(is_json_error(http->Post("/v1/compare", outside.dump(), "application/json"), 400, "invalid_value",
                            "region.height"));
}

TEST(HttpAccuracy, SweepAnswersJsonCsvAndSvg) {
  auto http = shared_server().client();
  const auto json = http->Post("/v1/sweep", kSmallSweep.dump(), "application/json");
  ASSERT_TRUE(json);
  ASSERT_EQ(json->status, 200) << json->body;
  const auto body = nlohmann::json::parse(json->body);
  EXPECT_TRUE(body["complete"].get<bool>());
  ASSERT_EQ(body["table"]["rows"].size(), 5u);  // LPV off, then 2 grids x 2 iteration counts
  int on_front = 0;
  for (const auto& row : body["table"]["rows"]) on_front += row["pareto"].get<bool>() ? 1 : 0;
  EXPECT_GE(on_front, 1);

  const auto csv = http->Post("/v1/sweep?format=csv", kSmallSweep.dump(), "application/json");
  ASSERT_TRUE(csv);
  ASSERT_EQ(csv->status, 200) << csv->body;
  EXPECT_EQ(csv->get_header_value("Content-Type"), "text/csv");
  EXPECT_EQ(std::count(csv->body.begin(), csv->body.end(), '\n'), 6);  // header + 5 rows
  EXPECT_EQ(csv->body.rfind("lpv,path_traced_samples,grid_x,", 0), 0u) << csv->body.substr(0, 80);

  const auto svg = http->Post("/v1/sweep?format=svg", kSmallSweep.dump(), "application/json");
  ASSERT_TRUE(svg);
  ASSERT_EQ(svg->status, 200) << svg->body;
  EXPECT_EQ(svg->get_header_value("Content-Type"), "image/svg+xml");
  EXPECT_EQ(svg->body.rfind("<svg", 0), 0u);
  EXPECT_NE(svg->body.find("</svg>"), std::string::npos);

  const auto bad = http->Post("/v1/sweep?format=xml", kSmallSweep.dump(), "application/json");
  EXPECT_TRUE(is_json_error(bad, 400, "invalid_value", "format"));
}

TEST(HttpAccuracy, SweepStreamsItsEventsInOrder) {
  auto http = shared_server().client();
  const auto r = http->Post("/v1/sweep", {{"Accept", "application/x-ndjson"}}, kSmallSweep.dump(), "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/x-ndjson");
  const std::vector<nlohmann::json> events = lines_of(r->body);
  ASSERT_GE(events.size(), 8u);  // reference, 5 rows, timing, done (progress lines besides)
  std::size_t rows = 0;
  bool reference_seen = false;
  nlohmann::json last_timing;
  for (std::size_t i = 0; i + 1 < events.size(); ++i) {
    const std::string kind = events[i]["event"];
    if (kind == "reference_progress") {
      EXPECT_FALSE(reference_seen);
      continue;
    }
    if (kind == "reference") {
      reference_seen = true;
      continue;
    }
    if (kind == "timing_progress") {  // the timed frames, once every row's errors are in
      EXPECT_EQ(rows, 5u);
      last_timing = events[i];
      continue;
    }
    ASSERT_EQ(kind, "row") << events[i].dump();
    EXPECT_TRUE(reference_seen);
    EXPECT_TRUE(last_timing.is_null()) << "a row after the timing began";
    EXPECT_EQ(events[i]["index"], rows++);
    EXPECT_EQ(events[i]["total"], 5);
  }
  EXPECT_EQ(rows, 5u);
  EXPECT_EQ(last_timing, nlohmann::json({{"event", "timing_progress"}, {"done", 15}, {"total", 15}}))
      << "5 rows x 3 frames, the last always sent";
  EXPECT_EQ(events.back()["event"], "done");
  EXPECT_EQ(events.back()["table"]["rows"].size(), 5u);
  for (const nlohmann::json& row : events.back()["table"]["rows"]) EXPECT_EQ(row["frames"], 3);
  // The plot ?format=svg answers (the web page shows it): each plotted row a circle that
  // names its row.
  const std::string plot = events.back().value("plot", "");
  EXPECT_TRUE(plot.starts_with("<svg ")) << plot.substr(0, 40);
  EXPECT_NE(plot.find("Error against time per frame: cornell-box"), std::string::npos);
  for (int row = 0; row < 5; ++row)
    EXPECT_NE(plot.find("data-row=\"" + std::to_string(row) + "\""), std::string::npos) << "row " << row;
}

// 65 rows (LPV off, then 4 grids x 16 iteration counts): about 7.5 s on the project's 2-core
// lavapipe machine.
nlohmann::json long_sweep() {
  nlohmann::json sweep = kSmallSweep;
  sweep["parameters"]["grid"] = {8, 16, 24, 32};
  sweep["parameters"]["iterations"] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  return sweep;
}

// A client that leaves the long sweep at its first row must free the worker at the next
// one, so the render sent right after waits far less than the rest of the sweep would take.
TEST(HttpAccuracy, AClientLeavingASweepStopsItAtTheNextRow) {
  {
    httplib::Request request;
    request.method = "POST";
    request.path = "/v1/sweep?format=ndjson";
    request.body = long_sweep().dump();
    request.set_header("Content-Type", "application/json");
    // Reads the stream until the sweep has rendered its first rows, then hangs up.
    request.content_receiver = [](const char* data, std::size_t length, std::uint64_t, std::uint64_t) {
      return std::string_view(data, length).find("\"event\":\"row\"") == std::string_view::npos;
    };
    httplib::Response response;
    httplib::Error error = httplib::Error::Success;
    auto http = shared_server().client();
    (void)http->send(request, response, error);  // ends with error Canceled: we left
    ASSERT_EQ(error, httplib::Error::Canceled) << "the sweep ended before the client left";
  }
  auto http = shared_server().client();
  const auto r = http->Post("/v1/render", R"({"output": {"width": 32, "height": 32}})", "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto timing = parse_server_timing(r->get_header_value("Server-Timing"));
  ASSERT_TRUE(timing.count("queue"));
  EXPECT_LT(timing.at("queue"), 2500.0) << "the render waited for the abandoned sweep";
}

// The long sweep (65 rows) with a deadline of three times what a sweep of its first row
// takes on this machine (timed with the reference already traced, as the long sweep finds
// it): answered 200 with the rows done and complete false, not 504.
TEST(HttpAccuracy, ASweepPastItsDeadlineAnswersTheRowsDone) {
  nlohmann::json first_row = long_sweep();
  first_row["parameters"] = {{"grid", {8}}, {"iterations", {1}}};
  first_row["lpv_off_row"] = false;
  auto sweep_once = [&] {
    const auto r = shared_server().client()->Post("/v1/sweep", first_row.dump(), "application/json");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
  };
  sweep_once();  // traces the reference, if no test before did
  const std::string deadline_ms = std::to_string(static_cast<long>(3.0 * elapsed_ms(sweep_once)) + 100);
  const auto r = shared_server().client()->Post("/v1/sweep", {{"X-Deadline-Ms", deadline_ms}}, long_sweep().dump(),
                                                "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto body = nlohmann::json::parse(r->body);
  EXPECT_FALSE(body["complete"].get<bool>()) << "deadline " << deadline_ms << " ms";
  EXPECT_GE(body["table"]["rows"].size(), 1u) << "deadline " << deadline_ms << " ms";
  EXPECT_LT(body["table"]["rows"].size(), 65u);
}

TEST(HttpAccuracy, PathTracedRowsShareTheFrontTimedOnTheCpu) {
  auto http = shared_server().client();
  nlohmann::json request = kSmallSweep;
  request["parameters"] = {{"grid", {8}}};
  request["path_traced"] = {{"samples", {1, 16}}};
  request["reference"] = {{"samples", 64}};
  const auto answer = http->Post("/v1/sweep", request.dump(), "application/json");
  ASSERT_TRUE(answer);
  ASSERT_EQ(answer->status, 200) << answer->body;
  const auto rows = nlohmann::json::parse(answer->body)["table"]["rows"];
  ASSERT_EQ(rows.size(), 4u);  // LPV off, 8^3, then 1 and 16 samples per pixel
  for (std::size_t i : {0u, 1u}) {
    EXPECT_EQ(rows[i]["settings"]["path_traced_samples"], 0);
    EXPECT_EQ(rows[i]["device"].get<std::string>().rfind("CPU", 0), std::string::npos) << "a raster row ran on the GPU device";
  }
  for (std::size_t i : {2u, 3u}) {
    EXPECT_EQ(rows[i]["device"].get<std::string>().rfind("CPU: ", 0), 0u) << rows[i]["device"];
    EXPECT_EQ(rows[i]["frames"], 3);
    EXPECT_GT(rows[i]["gpu_ms"].get<double>(), 0.0);
    EXPECT_TRUE(rows[i]["passes"].empty()) << "a trace has no raster passes";
  }
  EXPECT_EQ(rows[2]["label"], "path traced, 1 sample per pixel");
  // Noise falls as samples rise: 16 samples against 64 leave far less error than 1 does (and
  // a seed of its own: at the reference's seed and samples, the error would be 0).
  const double one = rows[2]["indirect_error"]["rmse"].get<double>(), sixteen = rows[3]["indirect_error"]["rmse"].get<double>();
  EXPECT_GT(sixteen, 0.0);
  EXPECT_LT(sixteen, 0.5 * one) << one << " vs " << sixteen;
  EXPECT_GT(rows[3]["gpu_ms"].get<double>(), rows[2]["gpu_ms"].get<double>()) << "16 paths a pixel take longer than 1";

  const auto svg = http->Post("/v1/sweep?format=svg", request.dump(), "application/json");
  ASSERT_TRUE(svg);
  EXPECT_NE(svg->body.find("path-traced\" d=\"M"), std::string::npos) << "a diamond of their own";
}

TEST(HttpAccuracy, ErrorsNameTheFieldUnderTheEmbeddedRequest) {
  auto http = shared_server().client();
  EXPECT_TRUE(is_json_error(http->Post("/v1/compare", R"({"base": {"scene": "atlantis"}, "reference": {}})",
                                       "application/json"),
                            404, "scene_not_found", "base.scene"));
  EXPECT_TRUE(is_json_error(http->Post("/v1/sweep", R"({"base": {"output": {"width": 2048, "height": 2048}}})",
                                       "application/json"),
                            422, "limit_exceeded", "base.output"));  // the shared server allows 1048576 pixels
  EXPECT_TRUE(is_json_error(http->Post("/v1/compare", R"({"base": {}, "against": {"output": {"height": 64}}})",
                                       "application/json"),
                            400, "invalid_value", "against.output"));
  EXPECT_TRUE(is_json_error(http->Get("/v1/sweep"), 405, "method_not_allowed", ""));
  // A path-traced row costs what a reference of its samples costs, and is refused the same way.
  EXPECT_TRUE(is_json_error(http->Post("/v1/sweep", R"({"base": {"output": {"width": 1024, "height": 1024}},
                                                        "reference": {"samples": 1}, "path_traced": {"samples": [1, 65536]}})",
                                       "application/json"),
                            422, "limit_exceeded", "path_traced.samples[1]"));
}

}  // namespace
}  // namespace server_test
