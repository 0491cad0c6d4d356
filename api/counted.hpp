// Counted nouns in messages, so that none says "1 lights": "1 light", "2 lights",
// "0 vertices".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace api {

// `n` and the noun: `singular` when n is 1, else `plural` (default: singular + "s").
std::string counted(std::size_t n, std::string_view singular, std::string_view plural = {});

}  // namespace api
