// SHA-256 of a byte string, for content-addressed scene ids.
#pragma once

#include <string>
#include <string_view>

namespace core {

// 64 lowercase hex digits. Uses OpenSSL's EVP interface.
std::string sha256_hex(std::string_view bytes);

}  // namespace core
