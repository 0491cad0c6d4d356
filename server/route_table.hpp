// The one table of lpv-server's routes: for each path, its pattern as docs and metrics name it,
// whether it is answered without the token or whatever the Host, and the handler of each method
// it answers. Registration, the 405s and their Allow lists, the token check, the Host check and
// the metrics labels all read it, so a route is written once.
#pragma once

#include <httplib.h>

#include <regex>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace server {

using RouteHandler = std::variant<httplib::Server::Handler, httplib::Server::HandlerWithContentReader>;

// One method of a route and what answers it: GET (HEAD too) and DELETE take a Handler, POST
// either kind (a HandlerWithContentReader reads the body itself, within its limits).
struct Endpoint {
  const char* method;
  RouteHandler handler;
};

struct Route {
  const char* regex;    // what httplib matches
  const char* pattern;  // how docs and metrics name it
  bool open = false;    // answered without the token: probes, and the web page, which holds no
                        // data (the API calls it makes carry the token; it asks for it on a 401)
  bool probe = false;   // answered whatever the Host: orchestrators probe by address
  std::vector<Endpoint> endpoints;
};

class RouteTable {
 public:
  explicit RouteTable(std::vector<Route> routes);

  // The route `path` matches, or null.
  const Route* find(const std::string& path) const;
  // "GET, POST": the methods a route answers, as Allow lists them.
  static std::string methods(const Route& route);
  // Every endpoint on `http`, then a 405 naming the allowed methods for every other method.
  void install(httplib::Server& http) const;

 private:
  std::vector<Route> routes_;
  std::vector<std::regex> compiled_;
};

}  // namespace server
