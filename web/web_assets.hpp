// The web parameter explorer's files (web/, docs/web.md), embedded in the binary at build
// time by web/embed_assets.cmake: the server never reads them from disk.
#pragma once

#include <span>
#include <string_view>

namespace web {

struct WebAsset {
  std::string_view path;          // as requested: "/app.js"
  std::string_view content_type;  // by extension: "text/javascript; charset=utf-8"
  std::string_view etag;          // quoted, from the file's SHA-256: changes with its bytes
  std::string_view body;
};

// Every embedded file, in web/CMakeLists.txt's order (defined in the generated source).
std::span<const WebAsset> web_assets();

}  // namespace web
