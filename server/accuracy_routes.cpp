#include "server/accuracy_routes.hpp"

#include "api/accuracy_report.hpp"
#include "api/request_error.hpp"
#include "api/request_json.hpp"
#include "api/sweep_table.hpp"
#include "core/base64.hpp"
#include "image/flip.hpp"
#include "image/pfm.hpp"
#include "image/png.hpp"
#include "server/accuracy_jobs.hpp"
#include "server/http_errors.hpp"
#include "server/request_log.hpp"

#include <nlohmann/json.hpp>

#include <memory>

namespace server {
namespace {

// How often a streamed sweep checks on its client while nothing happens.
constexpr auto kStreamPoll = std::chrono::milliseconds(250);

std::string png_base64(const image::Rgba8Image& picture) { return core::base64_encode(image::encode_png(picture)); }
std::string pfm_base64(const image::RgbaF32Image& linear) { return core::base64_encode(image::encode_pfm(linear)); }

// "png": the display image as the PNG shows it; "pfm": the linear final and indirect images,
// exact values per pixel.
nlohmann::json side_json(const accuracy::CompareSide& side, api::CompareImages images) {
  nlohmann::json j = {{"label", side.label}};
  if (images == api::CompareImages::pfm) {
    j["image"] = pfm_base64(side.final_image);
    j["indirect"] = pfm_base64(side.indirect);
  } else {
    j["image"] = png_base64(side.display);
  }
  if (side.stats) j["stats"] = api::to_json(*side.stats);
  if (side.reference) j["reference"] = api::to_json(*side.reference);
  return j;
}

nlohmann::json flip_json(const accuracy::Comparison& c, api::CompareImages images) {
  nlohmann::json j = {{"image", png_base64(c.flip_heatmap)},
                      {"mean", c.final_error.flip},
                      {"viewing",
                       {{"monitor_width_m", c.viewing.monitor_width_m},
                        {"monitor_width_px", c.viewing.monitor_width_px},
                        {"distance_m", c.viewing.distance_m},
                        {"pixels_per_degree", c.viewing.pixels_per_degree()}}}};
  if (images == api::CompareImages::pfm) j["values"] = pfm_base64(image::flip_image(c.flip));
  return j;
}

nlohmann::json comparison_json(const accuracy::Comparison& c, const api::CompareRequest& request, double queue_ms) {
  nlohmann::json j = {
      {"mask", api::to_string(c.mask)},
      {"images", api::to_string(request.images)},
      {"metrics", {{"final", api::to_json(c.final_error)}, {"indirect", api::to_json(c.indirect_error)}}},
      {"base", side_json(c.base, request.images)},
      {"other", side_json(c.other, request.images)},
      {"difference",
       {{"image", png_base64(c.difference.image)},
        {"scale", c.difference.scale},
        {"quantity", "|luminance(base) - luminance(other)| of the final images, linear; the top of the colour "
                     "scale is `scale`"}}},
      {"flip", flip_json(c, request.images)},
      {"indirect_ratio", c.indirect_ratio ? nlohmann::json(*c.indirect_ratio) : nlohmann::json(nullptr)},
      {"queue_ms", queue_ms}};
  if (c.region) j["region"] = api::to_json(*c.region);
  return j;
}

nlohmann::json sweep_json(const accuracy::SweepResult& result) {
  return {{"complete", result.complete}, {"reference", api::to_json(result.reference)}, {"table", api::to_json(result.table)}};
}

std::string sweep_plot(const SweepJob& job) {
  return api::to_svg_plot(job.result->table, api::sweep_plot_title(job.request.base.scene));
}

enum class SweepFormat { json, csv, svg, ndjson };

SweepFormat sweep_format(const httplib::Request& request) {
  const std::string format = request.get_param_value("format");
  if (format.empty())
    return request.get_header_value("Accept").find("application/x-ndjson") != std::string::npos ? SweepFormat::ndjson
                                                                                                 : SweepFormat::json;
  if (format == "json") return SweepFormat::json;
  if (format == "csv") return SweepFormat::csv;
  if (format == "svg") return SweepFormat::svg;
  if (format == "ndjson") return SweepFormat::ndjson;
  throw api::RequestError("format", "must be one of \"json\", \"csv\", \"svg\", \"ndjson\", got '" + format + "'");
}

void send_sweep(httplib::Response& response, const SweepJob& job, SweepFormat format) {
  const accuracy::SweepResult& result = *job.result;
  switch (format) {
    case SweepFormat::csv: return response.set_content(api::to_csv(result.table), "text/csv");
    case SweepFormat::svg:
      return response.set_content(sweep_plot(job), "image/svg+xml");
    default: return send_json(response, sweep_json(result));
  }
}

// The error a failed job would have answered, as the last event of a stream (its status is
// already sent: 200).
nlohmann::json error_event(const Job& job, Service& service) {
  httplib::Response scratch;
  answer_job_error(job, scratch, service);
  nlohmann::json body = nlohmann::json::parse(scratch.body, nullptr, false);
  return {{"event", "error"}, {"status", scratch.status}, {"error", body.is_object() ? body["error"] : body}};
}

// Streams the sweep's events while it runs: the HTTP thread stays in the content provider
// until the sweep ends (its last event says how) or the client leaves (the sweep stops at
// its next row).
void stream_sweep(const std::shared_ptr<SweepJob>& job, httplib::Response& response, Service& service) {
  response.set_chunked_content_provider(
      "application/x-ndjson", [job, &service](std::size_t, httplib::DataSink& sink) {
        const auto write = [&sink](const nlohmann::json& event) {
          const std::string line = event.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace) + "\n";
          return sink.write(line.data(), line.size());
        };
        const auto write_pending = [&] {
          while (std::optional<nlohmann::json> event = job->events.next(std::chrono::milliseconds(0)))
            if (!write(*event)) return false;
          return true;
        };
        const auto client_gone = [&sink] { return !sink.is_writable(); };
        std::optional<RenderQueue::Outcome> outcome;
        while (!outcome) {
          if (!write_pending()) break;
          outcome = service.queue.wait_until(*job, client_gone, Clock::now() + kStreamPoll);
        }
        if (!outcome || *outcome == RenderQueue::Outcome::client_gone || !write_pending()) {
          job->abandoned = true;
          service.metrics.count_render("client_gone");
          return false;
        }
        if (*outcome == RenderQueue::Outcome::deadline_exceeded) {
          service.metrics.count_render("deadline_exceeded");
          write({{"event", "error"},
                 {"status", 504},
                 {"error", {{"code", "deadline_exceeded"}, {"message", "the sweep did not start within its deadline"}}}});
        } else if (job->error) {
          write(error_event(*job, service));
        } else {
          service.metrics.count_render("ok");
          // The plot too, so that the web page shows the same plot as ?format=svg.
          nlohmann::json done = sweep_json(*job->result);
          done["event"] = "done";
          done["plot"] = sweep_plot(*job);
          write(done);
        }
        sink.done();
        return true;
      });
}

}  // namespace

void handle_compare(const httplib::Request& request, httplib::Response& response,
                    const httplib::ContentReader& content, Service& service) {
  auto accepted = accept_request<api::CompareRequest>(
      request, response, content, service, api::parse_compare_request, service.options.accuracy_deadline,
      [&](const api::CompareRequest& c) { return missing_scene(c.base.scene, "base.scene", service); });
  if (!accepted) return;
  auto job = std::make_shared<CompareJob>(std::move(accepted->request), request_arrival() + accepted->deadline);
  if (!run_job(job, accepted->deadline, request, response, service)) return;
  send_json(response, comparison_json(*job->result, job->request, job->queue_wait_ms), 200, kImageJson);
}

void handle_sweep(const httplib::Request& request, httplib::Response& response, const httplib::ContentReader& content,
                  Service& service) {
  auto accepted = accept_request<api::SweepRequest>(
      request, response, content, service, api::parse_sweep_request, service.options.accuracy_deadline,
      [&](const api::SweepRequest& s) { return missing_scene(s.base.scene, "base.scene", service); });
  if (!accepted) return;
  SweepFormat format{};
  try {  // after the body is read, so that the connection stays usable after a 400
    format = sweep_format(request);
  } catch (const api::RequestError& e) {
    return send_error(response, parse_error(e));
  }
  auto job = std::make_shared<SweepJob>(std::move(accepted->request), request_arrival() + accepted->deadline);
  if (format == SweepFormat::ndjson) {
    if (admit_job(job, response, service)) stream_sweep(job, response, service);
    return;
  }
  if (!run_job(job, accepted->deadline, request, response, service)) return;
  send_sweep(response, *job, format);
}

}  // namespace server
