#include "server/web_routes.hpp"

#include "server/http_errors.hpp"
#include "web/web_assets.hpp"

#include <string_view>

namespace server {
namespace {

// Everything the page loads comes from this server: its scripts, styles and icon. It draws the
// API's images on a canvas, so it needs no image URLs of its own (no blob:, no data:).
// Nothing from other hosts, no inline code.
constexpr const char* kContentSecurityPolicy =
    "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self'; connect-src 'self'; "
    "base-uri 'none'; form-action 'none'; frame-ancestors 'none'";

const web::WebAsset* find_asset(std::string_view path) {
  if (path == kWebPageRoute) path = "/index.html";
  for (const web::WebAsset& asset : web::web_assets())
    if (asset.path == path) return &asset;
  return nullptr;
}

// If-None-Match: "*" or a comma-separated list of (possibly weak) ETags.
bool etag_matches(std::string_view if_none_match, std::string_view etag) {
  while (!if_none_match.empty()) {
    const auto comma = if_none_match.find(',');
    std::string_view candidate = if_none_match.substr(0, comma);
    while (!candidate.empty() && candidate.front() == ' ') candidate.remove_prefix(1);
    while (!candidate.empty() && candidate.back() == ' ') candidate.remove_suffix(1);
    if (candidate.starts_with("W/")) candidate.remove_prefix(2);
    if (candidate == "*" || candidate == etag) return true;
    if (comma == std::string_view::npos) break;
    if_none_match.remove_prefix(comma + 1);
  }
  return false;
}

}  // namespace

void serve_web_asset(const httplib::Request& request, httplib::Response& response) {
  const web::WebAsset* asset = find_asset(request.path);
  if (!asset) return send_error(response, {404, "not_found", "no such file of the web page: " + request.path, ""});
  // Names carry no version, so browsers must ask each time; an unchanged file costs a 304.
  response.set_header("Cache-Control", "no-cache");
  response.set_header("ETag", std::string(asset->etag));
  response.set_header("X-Content-Type-Options", "nosniff");
  if (asset->content_type.starts_with("text/html")) {
    response.set_header("Content-Security-Policy", kContentSecurityPolicy);
    response.set_header("Referrer-Policy", "no-referrer");
  }
  if (etag_matches(request.get_header_value("If-None-Match"), asset->etag)) {
    response.status = 304;
    return;
  }
  response.set_content(asset->body.data(), asset->body.size(), std::string(asset->content_type));
}

}  // namespace server
