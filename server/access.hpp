// Who may use the server: an optional bearer token, and which addresses are loopback.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace server {

// Equal strings, in time that depends only on the lengths, so a client cannot find the
// token byte by byte by timing the answers.
bool equal_in_constant_time(std::string_view a, std::string_view b);

// True when `authorization` (the header's value) is "Bearer <token>" with this token.
bool bearer_token_matches(std::string_view authorization, std::string_view token);

// ASCII letters in lower case (HTTP's names and media types are case-insensitive ASCII).
std::string ascii_lowercase(std::string_view text);

// 127.0.0.0/8, ::1 and "localhost": addresses only this machine can reach.
bool is_loopback_host(std::string_view host);

// The host name of an HTTP authority ("name:port", "[v6]:port", "name"), lowercased, without
// the port or the brackets; empty for something that is not one.
std::string authority_host(std::string_view authority);

// The authority ("host[:port]") of an Origin header ("scheme://host[:port]"), lowercased;
// empty for "null" and anything else that is not an origin.
std::string origin_authority(std::string_view origin);

// Which names a browser may reach this server by (docs/server.md, "Cross-site requests"):
// loopback names and addresses always, and what the operator allows (--allowed-host: names,
// or "*" for any).
class HostPolicy {
 public:
  explicit HostPolicy(std::vector<std::string> allowed);
  // `host`: a Host header's value.
  bool allows(std::string_view host) const;

 private:
  std::vector<std::string> allowed_;  // lowercased host names
  bool any_ = false;
};

}  // namespace server
