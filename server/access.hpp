// Who may use the server: an optional bearer token, and which addresses are loopback.
#pragma once

#include <string>
#include <string_view>

namespace server {

// Equal strings, in time that depends only on the lengths, so a client cannot find the
// token byte by byte by timing the answers.
bool equal_in_constant_time(std::string_view a, std::string_view b);

// True when `authorization` (the header's value) is "Bearer <token>" with this token.
bool bearer_token_matches(std::string_view authorization, std::string_view token);

// 127.0.0.0/8, ::1 and "localhost": addresses only this machine can reach.
bool is_loopback_host(std::string_view host);

}  // namespace server
