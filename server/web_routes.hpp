// GET / and the page's assets: the web parameter explorer (docs/web.md), served from the
// files embedded in the binary, with ETags so browsers revalidate cheaply.
#pragma once

#include <httplib.h>

#include <string>

namespace server {

// What the routes table lists: "/" (the page) and its flat asset names.
inline constexpr const char* kWebPageRoute = "/";
inline constexpr const char* kWebAssetRoute = R"(/[A-Za-z0-9_-]+\.(?:html|css|js|svg))";

// The page itself holds no data, so it is served without a token; the API calls it makes
// carry one (the page asks for it when the server answers 401).
bool is_web_page_path(const std::string& path);

void install_web_routes(httplib::Server& http);

}  // namespace server
