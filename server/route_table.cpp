#include "server/route_table.hpp"

#include "server/http_errors.hpp"

#include <algorithm>
#include <stdexcept>

namespace server {
namespace {

bool answers(const Route& route, std::string_view method) {
  return std::ranges::any_of(route.endpoints, [&](const Endpoint& e) { return e.method == method; });
}

void install_endpoint(httplib::Server& http, const char* regex, const Endpoint& endpoint) {
  const std::string_view method = endpoint.method;
  if (const auto* reader = std::get_if<httplib::Server::HandlerWithContentReader>(&endpoint.handler)) {
    if (method != "POST") throw std::logic_error("a body-reading handler must be POST, not " + std::string(method));
    http.Post(regex, *reader);
    return;
  }
  const auto& handler = std::get<httplib::Server::Handler>(endpoint.handler);
  if (method == "GET") {
    http.Get(regex, handler);  // also HEAD
  } else if (method == "POST") {
    http.Post(regex, handler);
  } else if (method == "DELETE") {
    http.Delete(regex, handler);
  } else {
    throw std::logic_error("no route method " + std::string(method));
  }
}

void install_method_not_allowed(httplib::Server& http, const Route& route) {
  const std::string allowed = RouteTable::methods(route);
  const httplib::Server::Handler refuse = [pattern = std::string(route.pattern), allowed](
                                              const httplib::Request& request, httplib::Response& response) {
    send_error(response, {405, "method_not_allowed",
                          request.method + " is not allowed on " + pattern + "; use " + allowed, ""});
    response.set_header("Allow", allowed);
  };
  if (!answers(route, "GET")) http.Get(route.regex, refuse);  // also HEAD
  if (!answers(route, "POST")) http.Post(route.regex, refuse);
  if (!answers(route, "PUT")) http.Put(route.regex, refuse);
  if (!answers(route, "PATCH")) http.Patch(route.regex, refuse);
  if (!answers(route, "DELETE")) http.Delete(route.regex, refuse);
  http.Options(route.regex, refuse);
}

}  // namespace

RouteTable::RouteTable(std::vector<Route> routes) : routes_(std::move(routes)) {
  for (const Route& route : routes_) compiled_.emplace_back(route.regex);
}

const Route* RouteTable::find(const std::string& path) const {
  for (std::size_t i = 0; i < routes_.size(); ++i)
    if (std::regex_match(path, compiled_[i])) return &routes_[i];
  return nullptr;
}

std::string RouteTable::methods(const Route& route) {
  std::string list;
  for (const Endpoint& e : route.endpoints) list += (list.empty() ? "" : ", ") + std::string(e.method);
  return list;
}

void RouteTable::install(httplib::Server& http) const {
  for (const Route& route : routes_)
    for (const Endpoint& endpoint : route.endpoints) install_endpoint(http, route.regex, endpoint);
  for (const Route& route : routes_) install_method_not_allowed(http, route);
}

}  // namespace server
