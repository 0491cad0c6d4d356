// GET / and the page's assets: the web parameter explorer (docs/web.md), served from the
// files embedded in the binary, with ETags so browsers revalidate cheaply.
#pragma once

#include <httplib.h>

namespace server {

// What the routes table lists: "/" (the page) and its flat asset names.
inline constexpr const char* kWebPageRoute = "/";
inline constexpr const char* kWebAssetRoute = R"(/[A-Za-z0-9_-]+\.(?:html|css|js|svg))";

void install_web_routes(httplib::Server& http);

}  // namespace server
