// Base64 (RFC 4648, with padding) for images inside JSON documents.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace core {

std::string base64_encode(std::span<const std::uint8_t> bytes);
// Strict: padded to a multiple of 4 characters of the alphabet; nullopt for anything else.
std::optional<std::vector<std::uint8_t>> base64_decode(std::string_view text);

}  // namespace core
