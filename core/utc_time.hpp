// Wall-clock time as people and logs read it.
#pragma once

#include <string>

namespace core {

// Now, as ISO 8601 UTC with milliseconds: "2024-05-01T12:34:56.789Z".
std::string utc_timestamp();

}  // namespace core
