// GET / and the page's assets: the web parameter explorer (docs/web.md), served from the
// files embedded in the binary, with ETags so browsers revalidate cheaply.
#pragma once

#include <httplib.h>

namespace server {

// What the routes table lists: "/" (the page) and its flat asset names.
inline constexpr const char* kWebPageRoute = "/";
inline constexpr const char* kWebAssetRoute = R"(/[A-Za-z0-9_-]+\.(?:html|css|js|svg))";

// GET of kWebPageRoute or kWebAssetRoute: the embedded file, or 404.
void serve_web_asset(const httplib::Request& request, httplib::Response& response);

}  // namespace server
