// Base64 (RFC 4648, with padding) for images inside JSON responses.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace server {

std::string base64_encode(std::span<const std::uint8_t> bytes);

}  // namespace server
