#include "scene/decode_budget.hpp"

#include <algorithm>

namespace scene {

DecodeBudget::Lease::~Lease() {
  if (budget_) budget_->release(bytes_);
}

std::optional<DecodeBudget::Lease> DecodeBudget::acquire(std::uint64_t bytes, std::chrono::milliseconds wait) {
  bytes = std::min(bytes, capacity_);
  std::unique_lock lock(mutex_);
  if (!returned_.wait_for(lock, wait, [&] { return capacity_ - in_use_ >= bytes; })) return std::nullopt;
  in_use_ += bytes;
  return Lease(this, bytes);
}

std::uint64_t DecodeBudget::in_use() const {
  std::lock_guard lock(mutex_);
  return in_use_;
}

void DecodeBudget::release(std::uint64_t bytes) {
  {
    std::lock_guard lock(mutex_);
    in_use_ -= bytes;
  }
  returned_.notify_all();
}

}  // namespace scene
