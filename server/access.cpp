#include "server/access.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cstddef>

namespace server {

bool equal_in_constant_time(std::string_view a, std::string_view b) {
  // Walk the longer length in full whatever the contents; a length mismatch still fails.
  const std::size_t n = a.size() > b.size() ? a.size() : b.size();
  unsigned char diff = a.size() == b.size() ? 0 : 1;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char x = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
    const unsigned char y = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
    diff |= static_cast<unsigned char>(x ^ y);
  }
  return diff == 0;
}

std::string ascii_lowercase(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
  return lower;
}

bool bearer_token_matches(std::string_view authorization, std::string_view token) {
  constexpr std::string_view scheme = "bearer ";
  // The scheme is case-insensitive (RFC 7235); the token is compared exactly.
  if (authorization.size() < scheme.size() || ascii_lowercase(authorization.substr(0, scheme.size())) != scheme)
    return false;
  return equal_in_constant_time(authorization.substr(scheme.size()), token);
}

bool is_loopback_host(std::string_view host) {
  if (host == "localhost") return true;
  const std::string text(host);
  in_addr v4{};
  if (inet_pton(AF_INET, text.c_str(), &v4) == 1) return (ntohl(v4.s_addr) >> 24) == 127;
  in6_addr v6{};
  if (inet_pton(AF_INET6, text.c_str(), &v6) == 1) return IN6_IS_ADDR_LOOPBACK(&v6);
  return false;
}

std::string authority_host(std::string_view authority) {
  std::string_view host = authority;
  if (host.starts_with('[')) {  // an IPv6 literal: [::1]:8080
    const auto close = host.find(']');
    if (close == std::string_view::npos) return {};
    const std::string_view rest = host.substr(close + 1);
    if (!rest.empty() && !rest.starts_with(':')) return {};
    host = host.substr(1, close - 1);
  } else if (const auto colon = host.rfind(':'); colon != std::string_view::npos) {
    if (host.find(':') != colon) return {};  // a bare IPv6 address is no authority
    host = host.substr(0, colon);
  }
  return ascii_lowercase(host);
}

std::string origin_authority(std::string_view origin) {
  const auto scheme_end = origin.find("://");
  if (scheme_end == std::string_view::npos || scheme_end == 0) return {};
  const std::string_view authority = origin.substr(scheme_end + 3);
  if (authority.empty() || authority.find_first_of("/?#@ ") != std::string_view::npos) return {};
  return ascii_lowercase(authority);
}

HostPolicy::HostPolicy(std::vector<std::string> allowed) {
  for (std::string& name : allowed) {
    if (name == "*") {
      any_ = true;
      continue;
    }
    allowed_.push_back(ascii_lowercase(name));
  }
}

bool HostPolicy::allows(std::string_view host) const {
  if (any_) return true;
  const std::string name = authority_host(host);
  if (name.empty()) return false;
  return is_loopback_host(name) || std::find(allowed_.begin(), allowed_.end(), name) != allowed_.end();
}

}  // namespace server
