// Milliseconds since a moment on the steady clock: how every layer times its work.
#pragma once

#include <chrono>

namespace core {

inline double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace core
